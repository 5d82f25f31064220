// SPDX-License-Identifier: GPL-3.0-or-later
#include "BlockLayout.h"

#include <algorithm>

namespace rs::ladder {

namespace {

using blocks::PinDirection;
using blocks::PinKind;

constexpr qreal kHeader = 26; // the block's name at the top of the box
// One pin: its operand's name above the stub, the operand below; room too for
// the power pin's contact with its name above and address below.
constexpr qreal kPinRow = 42;
constexpr qreal kStub = 36;    // the wire out of the box to a pin's operand
constexpr qreal kPinInset = 6; // between the box's side and a pin's name
constexpr qreal kMinimumBox = 150;
constexpr qreal kContactWidth = 24;
constexpr qreal kContactHeight = 26;

QString text(const std::string& utf8) {
    return QString::fromUtf8(utf8.data(), static_cast<qsizetype>(utf8.size()));
}

// A pin as the block defines it, with the operand the record binds to it.
struct BoundPin {
    std::string name;
    PinDirection direction = PinDirection::In;
    PinKind kind = PinKind::Bit;
    const blocks::Binding* binding = nullptr;
    const blocks::Pin* pin = nullptr; // as the block defines it; null without the block
};

// The block's pins in its order; without the block, the pins the record binds.
std::vector<BoundPin> boundPins(const blocks::BlockInstance& instance,
                                const blocks::BlockDefinition* block) {
    std::vector<BoundPin> pins;
    if (!block) {
        for (const auto& binding : instance.pins)
            pins.push_back({binding.name, PinDirection::In, PinKind::Bit, &binding, nullptr});
        return pins;
    }
    for (const auto& pin : block->pins)
        pins.push_back({pin.name, pin.direction, pin.kind, instance.findPin(pin.name), &pin});
    return pins;
}

// Where the operand written for a pin stands: an address word, a name the
// unit declares, or a time or constant as written.
void describeOperand(PinLayout& pin, const std::string& operand, const SymbolTable* symbols) {
    const lang::AddressWord word = lang::readAddressWord(operand);
    if (word.shape == lang::AddressWord::Shape::Variable) {
        pin.address = word.address;
        pin.operand = text(lang::toString(word.address));
        if (symbols)
            pin.name = text(symbols->nameOf(word.address));
        return;
    }
    if (symbols)
        if (auto address = symbols->addressOf(operand)) {
            pin.address = *address;
            pin.name = text(operand);
            pin.operand = text(lang::toString(*address));
            return;
        }
    pin.operand = text(operand);
}

const QString kMissing = QStringLiteral("???");

// What an open pin shows: its default in parentheses, nothing for a
// secondary output (it may stay open, manual 3.13), else "???" as the
// manual draws a pin still to be bound (3.10).
QString openPinText(const blocks::Pin* pin) {
    if (pin && pin->defaultValue)
        return QStringLiteral("(%1)").arg(text(*pin->defaultValue));
    if (pin && pin->direction == PinDirection::Out && pin->role == blocks::PinRole::Secondary)
        return {};
    return kMissing;
}

} // namespace

qreal placeBlock(NetworkLayout& layout, const BlockCall& call, const LayoutContext& context,
                 qreal railX, qreal top, qreal& width) {
    const LayoutMetrics& m = context.metrics;
    const std::vector<BoundPin> pins = boundPins(call.instance, context.block);
    std::size_t inputs = 0;
    std::size_t outputs = 0;
    qreal widestIn = 0;
    qreal widestOut = 0;
    for (const auto& pin : pins) {
        const qreal w = static_cast<qreal>(pin.name.size()) * m.charWidth;
        if (pin.direction == PinDirection::In) {
            ++inputs;
            widestIn = std::max(widestIn, w);
        } else {
            ++outputs;
            widestOut = std::max(widestOut, w);
        }
    }
    const QString type = text(call.instance.type);
    const qreal boxWidth =
        std::max({kMinimumBox, widestIn + widestOut + 4 * kPinInset + 4 * m.charWidth,
                  static_cast<qreal>(type.size()) * m.charWidth + 4 * kPinInset});
    const qreal boxLeft = railX + m.cellWidth + kStub;
    const qreal boxTop = top + m.margin;
    const auto rows = static_cast<qreal>(std::max<std::size_t>({inputs, outputs, 1}));
    BlockLayout block;
    block.box = QRectF(boxLeft, boxTop, boxWidth, kHeader + rows * kPinRow);
    block.type = type;
    block.typeRect = QRectF(boxLeft, boxTop, boxWidth, kHeader);

    const qreal operandWidth = m.cellWidth - 2 * kPinInset;
    bool powerTaken = false;
    std::size_t inRow = 0;
    std::size_t outRow = 0;
    for (const auto& bound : pins) {
        PinLayout pin;
        pin.pin = text(bound.name);
        pin.direction = bound.direction;
        pin.kind = bound.kind;
        pin.open = bound.binding == nullptr;
        if (bound.binding)
            describeOperand(pin, bound.binding->operand, context.symbols);
        else
            pin.operand = openPinText(bound.pin);
        pin.missing = pin.open && pin.operand == kMissing;
        // An analogue input bound to a pin is read for its value (a system
        // block's Input): shown as a number, never as the rung's power.
        if (pin.address &&
            (pin.address->kind == lang::AddressKind::AnalogInput || !pin.address->isBit()))
            pin.kind = PinKind::Register;
        const bool in = bound.direction == PinDirection::In;
        const std::size_t row = in ? inRow++ : outRow++;
        const qreal y = boxTop + kHeader + static_cast<qreal>(row) * kPinRow + kPinRow / 2;
        const qreal half = m.labelHeight / 2;
        if (in) {
            pin.pinRect = QRectF(boxLeft + kPinInset, y - half,
                                 boxWidth - widestOut - 3 * kPinInset, 2 * half);
            pin.power = !powerTaken && pin.kind == PinKind::Bit;
            powerTaken = powerTaken || pin.power;
            if (pin.power) {
                // The rung: rail, a contact of the operand, the pin.
                const qreal centre = railX + m.cellWidth / 2;
                pin.contactRect = QRectF(centre - kContactWidth / 2, y - kContactHeight / 2,
                                         kContactWidth, kContactHeight);
                pin.stub = QLineF(pin.contactRect.right(), y, boxLeft, y);
                pin.nameRect = QRectF(railX + kPinInset, pin.contactRect.top() - m.labelHeight,
                                      operandWidth, m.labelHeight);
                pin.operandRect = QRectF(railX + kPinInset, pin.contactRect.bottom(), operandWidth,
                                         m.labelHeight);
                layout.wires.push_back({QLineF(railX, y, pin.contactRect.left(), y),
                                        {PowerFeed::Kind::Rail, context.firstStatement, {}},
                                        false});
                if (pin.open) {
                    // Nothing bound, so nothing switches: the rung runs
                    // straight to the pin, its default written below it.
                    layout.wires.back().line.setP2(QPointF(boxLeft, y));
                    pin.contactRect = {};
                    pin.stub = {};
                }
            } else {
                pin.stub = QLineF(boxLeft - kStub, y, boxLeft, y);
                const qreal right = boxLeft - kStub;
                pin.nameRect = QRectF(right - operandWidth, y - m.labelHeight - 1, operandWidth,
                                      m.labelHeight);
                pin.operandRect = QRectF(right - operandWidth, y + 1, operandWidth, m.labelHeight);
            }
        } else {
            const qreal boxRight = boxLeft + boxWidth;
            pin.pinRect = QRectF(boxRight - widestOut - 2 * kPinInset, y - half,
                                 widestOut + kPinInset, 2 * half);
            pin.stub = QLineF(boxRight, y, boxRight + kStub, y);
            pin.nameRect = QRectF(boxRight + kStub + kPinInset, y - m.labelHeight - 1, operandWidth,
                                  m.labelHeight);
            pin.operandRect =
                QRectF(boxRight + kStub + kPinInset, y + 1, operandWidth, m.labelHeight);
        }
        block.pins.push_back(std::move(pin));
    }
    const qreal bottom = block.box.bottom() + m.margin;
    layout.wires.push_back({QLineF(railX, top, railX, bottom),
                            {PowerFeed::Kind::Rail, context.firstStatement, {}},
                            true});
    width = std::max(width, boxLeft + boxWidth + kStub + kPinInset + m.cellWidth);
    qreal y = bottom;
    if (!context.blockNote.isEmpty()) {
        layout.texts.push_back(
            {TextLayout::Role::Note,
             QRectF(boxLeft, y, context.blockNote.size() * m.charWidth, m.noteHeight),
             context.blockNote});
        width = std::max(width, boxLeft + context.blockNote.size() * m.charWidth);
        y += m.noteHeight;
    }
    layout.block = std::move(block);
    return y;
}

} // namespace rs::ladder
