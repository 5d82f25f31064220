// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Editing.h"
#include "ElementKind.h"
#include "Network.h"
#include "SymbolTable.h"

#include <QLineF>
#include <QRectF>
#include <QString>

#include <cstdint>
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
};

struct ElementLayout {
    ElementKind kind = ElementKind::NormallyOpen;
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
};

struct WireLayout {
    QLineF line;
    PowerFeed feed;
    bool rail = false; // a part of a rail, drawn heavier than a wire
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
};

struct NetworkLayout {
    LayoutMetrics metrics;
    QSizeF size;
    int conditionColumns = 0; // grid columns between the left rail and the outputs
    int outputColumns = 0;
    std::vector<ElementLayout> elements;
    std::vector<WireLayout> wires;
    std::vector<TextLayout> texts;
};

struct LayoutContext {
    int number = 1;                   // the network's number in its step, shown in its title
    QString title;                    // the title in the reader's language; empty: "Network N"
    std::uint32_t firstStatement = 0; // number in the unit of the network's first statement
    const SymbolTable* symbols = nullptr;
    LayoutMetrics metrics;
};

// A comment line is drawn with at most this many characters and an ellipsis:
// measuring and shaping a line of megabytes on every repaint would stall the
// page, and the text page shows the line whole.
inline constexpr qsizetype kLongestDrawnText = 400;

// Series parts stand side by side, parallel branches one below the other,
// each as wide as the widest; outputs line up at the right of the widest
// condition of the network, stacked when a rung has several.
NetworkLayout layoutNetwork(const Network& network, const LayoutContext& context);

} // namespace rs::ladder
