// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Editing.h"
#include "ElementKind.h"
#include "Network.h"
#include "SymbolTable.h"

#include "blocks/BlockLibrary.h"
#include "lang/Address.h"

#include <QLineF>
#include <QRectF>
#include <QString>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

// Where everything of a network is drawn, computed from the model alone (no
// stored coordinates), in layout units: one unit is one pixel at 100 % zoom.
namespace rs::ladder {

struct LayoutMetrics {
    qreal cellWidth = 128;  // one grid column
    qreal cellHeight = 72;  // one grid row: name, symbol, address
    qreal labelHeight = 14; // the name above and the address below a symbol
    qreal titleHeight = 22; // a line of the network's title and comment
    qreal noteHeight = 18;  // a comment line among the rungs
    qreal charWidth = 7;    // a character of running text, to size the comment column
    qreal margin = 8;
    int minimumConditionColumns = 2;
    friend bool operator==(const LayoutMetrics&, const LayoutMetrics&) = default;
};

struct ElementLayout {
    ElementKind kind = ElementKind::NormallyOpen; // Pluto's kind, which its editor acts on
    Shape shape = Shape::Contact;                 // how it is drawn, for every target
    QString mark;         // inside a contact or coil: "P", "S"; "/" a normally closed slash
    bool negated = false; // a timer or comparison box that passes power when it is false
    // The compiler's numbering: the statement's number in the unit and the
    // element in it (0 the output, 1.. the condition's nodes in pre-order).
    std::uint32_t statement = 0;
    std::uint16_t element = 0;
    // Its place in the model: a condition node, or output `output` of the rung
    // at path.item (then path.node is empty).
    ElementPath path;
    int output = -1;
    // Grid cell within its rung: column from the left rail, row from the
    // rung's top, and the columns it spans.
    int column = 0;
    int row = 0;
    int columnSpan = 1;
    QRectF cell;       // the grid cell(s), in network coordinates
    QRectF symbolRect; // the contact, coil or box drawn inside
    QString name;      // symbolic name, empty when the operand has none
    QString address;   // the operand's address, or the timer's preset, or a jump's step
    QString text;      // inside a box: "TON", ">= 4", "+= 77"
    QRectF nameRect;
    QRectF addressRect;
    friend bool operator==(const ElementLayout&, const ElementLayout&) = default;
};

// Where the power on a wire comes from.
struct PowerFeed {
    enum class Kind : std::uint8_t {
        None,     // never powered: the right rail and what leads to it
        Rail,     // the left rail: powered whenever the statement runs
        Elements, // powered when any of `elements` conducts (several at a branch join)
    };
    Kind kind = Kind::None;
    std::uint32_t statement = 0;
    std::vector<std::uint16_t> elements;
    friend bool operator==(const PowerFeed&, const PowerFeed&) = default;
};

struct WireLayout {
    QLineF line;
    PowerFeed feed;
    bool rail = false; // a part of a rail, drawn heavier than a wire
    friend bool operator==(const WireLayout&, const WireLayout&) = default;
};

struct TextLayout {
    enum class Role : std::uint8_t {
        Title,         // "Network 3"
        Comment,       // a line of the network's comment
        Note,          // a comment line among the rungs
        OutputComment, // a statement's trailing comment, beside its output
    };
    Role role = Role::Title;
    QRectF rect;
    QString text;
    friend bool operator==(const TextLayout&, const TextLayout&) = default;
};

// One pin of a block's box: its name inside the box, a short wire out of
// the box, and beyond it the operand bound to it.
struct PinLayout {
    QString pin;
    blocks::PinDirection direction = blocks::PinDirection::In;
    blocks::PinKind kind = blocks::PinKind::Bit;
    bool open = false;    // unbound: its default, nothing, or "???"
    bool missing = false; // open and to be bound: drawn "???" (manual 3.10)
    bool power = false;   // the first bit input: the rung's power through a contact of its operand
    QString name;         // the operand's symbolic name; empty when it has none
    QString operand;      // the operand's address, or the time or constant bound
    std::optional<lang::Address> address; // the bound variable, whose live value is shown
    QRectF pinRect;                       // the pin's name, inside the box
    QLineF stub;                          // from the box's side outwards
    QRectF contactRect;                   // the power pin's contact, on the rung
    QRectF nameRect;    // the operand's name (above the stub), or for the power pin its contact's
    QRectF operandRect; // the operand (below the stub)
    friend bool operator==(const PinLayout&, const PinLayout&) = default;
};

// A block network's box (blocks.md): the block's name at its top, inputs on
// the left, outputs on the right.
struct BlockLayout {
    QRectF box;
    QString type;
    QRectF typeRect;
    std::vector<PinLayout> pins;
    friend bool operator==(const BlockLayout&, const BlockLayout&) = default;
};

struct NetworkLayout {
    LayoutMetrics metrics;
    QSizeF size;
    int conditionColumns = 0; // grid columns between the left rail and the outputs
    int outputColumns = 0;
    std::vector<ElementLayout> elements;
    std::vector<WireLayout> wires;
    std::vector<TextLayout> texts;
    std::optional<BlockLayout> block; // a block network's box; it has no elements
    friend bool operator==(const NetworkLayout&, const NetworkLayout&) = default;
};

struct LayoutContext {
    int number = 1;                   // the network's number in its step, shown in its title
    QString title;                    // the title in the reader's language; empty: "Network N"
    std::uint32_t firstStatement = 0; // number in the unit of the network's first statement
    const SymbolTable* symbols = nullptr;
    LayoutMetrics metrics;
    // A block network's block: its pins and description. Without it the box
    // shows the pins the record binds, as inputs.
    const blocks::BlockDefinition* block = nullptr;
    std::string language = "en"; // of the block's description ("en", "sv", "de")
    QString blockNote;           // under the box: that another version of the block exists
};

// A comment line is drawn with at most this many characters and an ellipsis:
// measuring and shaping a line of megabytes on every repaint would stall the
// page, and the text page shows the line whole.
inline constexpr qsizetype kLongestDrawnText = 400;

// Series parts stand side by side, parallel branches one below the other,
// each as wide as the widest; outputs line up at the right of the widest
// condition of the network, stacked when a rung has several.
NetworkLayout layoutNetwork(const Network& network, const LayoutContext& context);

// The layout of the same network at another place in its unit: its title
// and its statements' numbers as `to` gives them, `from` the context it was
// laid out with. Nothing else depends on them, so nothing is laid out again:
// an edit above a network moves it without a new layout.
void moveLayout(NetworkLayout& layout, const LayoutContext& from, const LayoutContext& to);

} // namespace rs::ladder
