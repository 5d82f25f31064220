// SPDX-License-Identifier: GPL-3.0-or-later
#include "RungLayout.h"

#include "ProgramText.h"

#include "ladder/RungGeometry.h"

#include <QStringList>

#include <algorithm>

namespace rs::pl110 {

namespace {

using ladder::ElementLabels;
using ladder::Shape;

constexpr qreal kTitleWidth = 96;

QString utf8(std::string_view text) {
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

QString operandName(const Operand& operand) {
    return utf8(operand.name);
}

QString shownValue(const Value& value) {
    return utf8(valueText(value));
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
        l.shape = Shape::Box;
        l.text = utf8(compareWord(element.compare)) + u' ' + shownValue(element.right);
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
        l.shape = Shape::Box;
        l.text = utf8(timerWord(output.timer)) + u' ' + utf8(timeBaseWord(output.base));
        l.address += QStringLiteral(" PT ") + shownValue(output.preset);
        break;
    }
    case OutputKind::Counter: {
        l.shape = Shape::Box;
        l.text = utf8(counterWord(output.counter)) + u' ' + utf8(inputWord(output.input));
        l.address += QStringLiteral(" PV ") + shownValue(output.preset);
        break;
    }
    case OutputKind::Move:
        l.shape = Shape::Box;
        l.text = QStringLiteral("= ") + shownValue(output.left);
        break;
    case OutputKind::Formula: {
        l.shape = Shape::Box;
        l.text = QStringLiteral("= ") + shownValue(output.left) + u' ' +
                 utf8(formulaWord(output.formula)) + u' ' + shownValue(output.right);
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
        ladder::ElementPath path{0, {}};
        lang::PreOrderNumbering<Circuit> numbering(
            *rung.condition, [](const Circuit& c) -> const auto& { return c.parts; });
        ladder::RungGeometry::Placed placed = geometry.placeCircuit(
            *rung.condition, numbering, labels, path, context.statement, top, 0, 0, power);
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
