// SPDX-License-Identifier: GPL-3.0-or-later
#include "RungLayout.h"

#include "ladder/RungGeometry.h"

#include <QStringList>

#include <algorithm>

namespace rs::pl110 {

namespace {

using ladder::ElementLabels;
using ladder::Shape;

constexpr qreal kTitleWidth = 96;

QString utf8(const std::string& text) {
    return QString::fromStdString(text);
}

QString operandName(const Operand& operand) {
    return utf8(operand.name);
}

QString valueText(const Value& value) {
    if (value.isConstant())
        return QString::number(value.constant);
    return value.operand->isName() ? utf8(value.operand->name)
                                   : utf8(toString(value.operand->address));
}

ElementLabels labelsOf(const Element& element) {
    ElementLabels l;
    switch (element.kind) {
    case ElementKind::NormallyOpen:
    case ElementKind::NormallyClosed:
        l.mark = element.kind == ElementKind::NormallyClosed ? QStringLiteral("/") : QString();
        l.name = operandName(element.operand);
        l.address = utf8(toString(element.operand.address));
        break;
    case ElementKind::Compare: {
        static const char* const kOps[] = {"=", "<>", ">", "<", ">=", "<="};
        l.shape = Shape::Box;
        l.text = QString::fromLatin1(kOps[static_cast<int>(element.compare)]) + u' ' +
                 valueText(element.right);
        if (element.left.isConstant()) {
            l.address = QString::number(element.left.constant);
        } else {
            l.name = operandName(*element.left.operand);
            l.address = utf8(toString(element.left.operand->address));
        }
        break;
    }
    case ElementKind::Not:
        l.shape = Shape::Box;
        l.text = QStringLiteral("NOT");
        break;
    case ElementKind::RisingEdge:
        l.mark = QStringLiteral("P");
        break;
    case ElementKind::FallingEdge:
        l.mark = QStringLiteral("N");
        break;
    }
    return l;
}

QString timeBaseText(TimeBase base) {
    return base == TimeBase::Ms10    ? QStringLiteral("10ms")
           : base == TimeBase::Ms100 ? QStringLiteral("100ms")
                                     : QStringLiteral("1s");
}

ElementLabels labelsOf(const Output& output) {
    ElementLabels l;
    l.shape = Shape::Coil;
    l.name = operandName(output.target);
    l.address = utf8(toString(output.target.address));
    switch (output.kind) {
    case OutputKind::Coil:
        if (output.target.address.area == Area::Bistable)
            l.mark = QStringLiteral("B");
        break;
    case OutputKind::SetBit:
        l.mark = QStringLiteral("S");
        break;
    case OutputKind::ResetBit:
        l.mark = QStringLiteral("R");
        break;
    case OutputKind::Timer: {
        static const char* const kTypes[] = {"TON", "TOFF", "TONR"};
        l.shape = Shape::Box;
        l.text = QString::fromLatin1(kTypes[static_cast<int>(output.timer)]) + u' ' +
                 timeBaseText(output.base);
        l.address += QStringLiteral(" PT ") + valueText(output.preset);
        break;
    }
    case OutputKind::Counter: {
        static const char* const kInputs[] = {"UP", "DOWN", "RESET"};
        l.shape = Shape::Box;
        l.text = QString::fromLatin1(output.counter == CounterType::Up ? "MUP " : "MDOWN ") +
                 QString::fromLatin1(kInputs[static_cast<int>(output.input)]);
        l.address += QStringLiteral(" PV ") + valueText(output.preset);
        break;
    }
    case OutputKind::Move:
        l.shape = Shape::Box;
        l.text = QStringLiteral("= ") + valueText(output.left);
        break;
    case OutputKind::Formula: {
        static const char* const kOps[] = {"+", "-", "*", "/", "|", "&", "^", "<<", ">>"};
        l.shape = Shape::Box;
        l.text = QStringLiteral("= ") + valueText(output.left) + u' ' +
                 QString::fromLatin1(kOps[static_cast<int>(output.formula)]) + u' ' +
                 valueText(output.right);
        break;
    }
    }
    return l;
}

} // namespace

ladder::NetworkLayout layoutRung(const Rung& rung, const RungLayoutContext& context) {
    const ladder::LayoutMetrics& metrics = context.metrics;
    ladder::NetworkLayout layout;
    layout.metrics = metrics;
    const qreal railX = metrics.margin;
    ladder::RungGeometry geometry(layout, metrics, railX);
    const auto labels = [](const Element& element) {
        return labelsOf(element);
    };

    // Title and comment, then the rung.
    qreal width = metrics.margin + kTitleWidth;
    layout.texts.push_back(
        {ladder::TextLayout::Role::Title,
         QRectF(metrics.margin, metrics.margin, kTitleWidth, metrics.titleHeight), context.title});
    qreal top = metrics.margin;
    for (const QString& line : context.comment.split(u'\n')) {
        if (!line.isEmpty()) {
            const qreal lineWidth = line.size() * metrics.charWidth;
            layout.texts.push_back(
                {ladder::TextLayout::Role::Comment,
                 QRectF(metrics.margin + kTitleWidth, top, lineWidth, metrics.titleHeight), line});
            width = std::max(width, metrics.margin + kTitleWidth + lineWidth);
        }
        top += metrics.titleHeight;
    }
    top += metrics.margin / 2;

    const ElementLabels output = labelsOf(rung.output);
    layout.conditionColumns = metrics.minimumConditionColumns;
    if (rung.condition)
        layout.conditionColumns =
            std::max(layout.conditionColumns, geometry.extent(*rung.condition, labels).columns);
    layout.outputColumns = geometry.span(output);
    const qreal outputX = railX + layout.conditionColumns * metrics.cellWidth;
    const qreal rightRailX = outputX + layout.outputColumns * metrics.cellWidth;

    const qreal y = geometry.wireY(top, 0);
    ladder::PowerFeed power{ladder::PowerFeed::Kind::Rail, context.statement, {}};
    int rows = 1;
    int columns = 0;
    if (rung.condition) {
        lang::PreOrderNumbering<Circuit> numbering(
            *rung.condition, [](const Circuit& c) -> const auto& { return c.parts; });
        ladder::RungGeometry::Placed placed = geometry.placeCircuit(
            *rung.condition, numbering, labels, {0, {}}, context.statement, top, 0, 0, power);
        rows = placed.extent.rows;
        columns = placed.extent.columns;
        power = std::move(placed.output);
    }
    geometry.wire(railX + columns * metrics.cellWidth, y, outputX, y, power);
    ladder::ElementLayout& e =
        geometry.place(output, outputX, top, layout.conditionColumns, 0, layout.outputColumns);
    e.statement = context.statement;
    e.element = lang::kOutputElement;
    e.path = {0, {}};
    e.output = 0;
    geometry.wire(outputX, y, e.symbolRect.left(), y, power);
    geometry.wire(e.symbolRect.right(), y, rightRailX, y, {});
    const qreal bottom = top + rows * metrics.cellHeight;
    layout.wires.push_back({QLineF(railX, top, railX, bottom),
                            {ladder::PowerFeed::Kind::Rail, context.statement, {}},
                            true});
    layout.wires.push_back({QLineF(rightRailX, top, rightRailX, bottom), {}, true});
    width = std::max(width, rightRailX);
    layout.size = QSizeF(width + metrics.margin, bottom + metrics.margin);
    return layout;
}

} // namespace rs::pl110
