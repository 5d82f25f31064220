// SPDX-License-Identifier: GPL-3.0-or-later
#include "Layout.h"

#include "BlockLayout.h"
#include "ElementVocabulary.h"
#include "RungGeometry.h"

#include "lang/ElementNumbering.h"
#include "lang/Keywords.h"
#include "lang/Printer.h"

#include <QCoreApplication>
#include <QStringList>

#include <algorithm>

namespace rs::ladder {

namespace {

constexpr qreal kTitleWidth = 96; // "Network 999" before the comment
constexpr qreal kCommentGap = 12; // between the right rail and output comments

QString text(const std::string& utf8) {
    return QString::fromUtf8(utf8.data(), static_cast<qsizetype>(utf8.size()));
}

// A comment line as drawn: its first kLongestDrawnText characters, never
// half of a surrogate pair.
QString shortened(QString line) {
    if (line.size() <= kLongestDrawnText)
        return line;
    qsizetype keep = kLongestDrawnText;
    if (line.at(keep - 1).isHighSurrogate())
        --keep;
    line.truncate(keep);
    return line + QChar(0x2026);
}

QString word(std::string_view keyword) {
    return QString::fromLatin1(keyword.data(), static_cast<qsizetype>(keyword.size()));
}

QString valueText(const lang::Value& value) {
    return text(lang::printValue(value));
}

// How Pluto draws a kind: its vocabulary's shape and mark.
ElementLabels drawn(ElementKind kind) {
    ElementLabels l;
    l.kind = kind;
    const ElementKindInfo& info = infoOf(kind);
    l.shape = info.shape;
    l.mark = QString::fromUtf8(info.mark.data(), static_cast<qsizetype>(info.mark.size()));
    return l;
}

class Layouter {
public:
    Layouter(const Network& network, const LayoutContext& context)
        : m_network(network), m_context(context), m_metrics(context.metrics) {
        m_layout.metrics = m_metrics;
    }

    NetworkLayout run() {
        measureColumns();
        m_railX = m_metrics.margin;
        m_outputX = m_railX + m_layout.conditionColumns * m_metrics.cellWidth;
        m_rightRailX = m_outputX + m_layout.outputColumns * m_metrics.cellWidth;
        m_commentX = m_rightRailX + kCommentGap;

        qreal y = title();
        const qreal bodyTop = y;
        if (m_network.block)
            y = placeBlock(m_layout, *m_network.block, m_context, m_railX, y, m_width);
        std::uint32_t statement = m_context.firstStatement;
        for (std::size_t item = 0; item < m_network.items.size(); ++item) {
            if (const auto* rung = std::get_if<Rung>(&m_network.items[item])) {
                y = placeRung(*rung, item, statement, y);
                statement += static_cast<std::uint32_t>(rung->outputs.size());
            } else {
                y = placeNote(std::get<lang::Line>(m_network.items[item]), y);
            }
        }
        if (y > bodyTop && !m_network.block)
            m_layout.wires.push_back({QLineF(m_rightRailX, bodyTop, m_rightRailX, y), {}, true});
        if (m_commentWidth > 0)
            m_width = std::max(m_width, m_commentX + m_commentWidth);
        m_layout.size = QSizeF(m_width + m_metrics.margin, y + m_metrics.margin);
        return std::move(m_layout);
    }

private:
    // ----- labels and widths

    QString nameOf(const lang::Operand& operand) const {
        if (operand.isName())
            return text(operand.name);
        return m_context.symbols ? text(m_context.symbols->nameOf(operand.address)) : QString();
    }

    static QString addressOf(const lang::Operand& operand) {
        return operand.address.valid() ? text(lang::toString(operand.address)) : QString();
    }

    auto labelsOf() const {
        return [this](const Element& element) {
            return labels(element);
        };
    }

    ElementLabels labels(const Element& element) const {
        ElementLabels l = drawn(kindOf(element));
        if (const auto* contact = std::get_if<Contact>(&element)) {
            l.name = nameOf(contact->operand);
            l.address = addressOf(contact->operand);
            if (contact->operandNegated) {
                // P(/x): the edge of the inverted bit, written as the text writes it.
                if (!l.name.isEmpty())
                    l.name.prepend(u'/');
                l.address.prepend(u'/');
            }
        } else if (const auto* timer = std::get_if<TimerBox>(&element)) {
            l.negated = timer->negated;
            l.text = word(lang::timerWord(timer->spelling));
            if (timer->preset.registerOperand) {
                l.name = nameOf(*timer->preset.registerOperand);
                l.address = addressOf(*timer->preset.registerOperand);
            } else {
                l.address = text(lang::formatTime(timer->preset.hundredths));
            }
        } else {
            const auto& box = std::get<ComparisonBox>(element);
            l.negated = box.negated;
            l.name = nameOf(box.left);
            l.address = addressOf(box.left);
            l.text = word(lang::compareWord(box.op)) + u' ' + valueText(box.right);
        }
        return l;
    }

    ElementLabels labels(const Output& output) const {
        ElementLabels l = drawn(kindOf(output));
        switch (output.kind) {
        case lang::StatementKind::Jump:
            // The window's translations hold it (ui/CMakeLists.txt scans this file).
            l.address = QCoreApplication::translate("rs::ladder::Layout", "step %1")
                            .arg((output.relativeJump && output.jumpStep >= 0 ? QStringLiteral("+")
                                                                              : QString()) +
                                 QString::number(output.jumpStep));
            break;
        case lang::StatementKind::Assign:
            l.name = nameOf(output.assignment.target);
            l.address = addressOf(output.assignment.target);
            l.text = text(lang::printAssignmentOperation(output.assignment));
            break;
        default:
            l.name = nameOf(output.target);
            l.address = addressOf(output.target);
            break;
        }
        return l;
    }

    void measureColumns() {
        int condition = m_metrics.minimumConditionColumns;
        int outputs = 1;
        for (const auto& item : m_network.items) {
            const auto* rung = std::get_if<Rung>(&item);
            if (!rung)
                continue;
            if (rung->condition)
                condition =
                    std::max(condition, m_geometry.extent(*rung->condition, labelsOf()).columns);
            for (const auto& output : rung->outputs)
                outputs = std::max(outputs, m_geometry.span(labels(output)));
        }
        m_layout.conditionColumns = condition;
        m_layout.outputColumns = outputs;
    }

    qreal placeRung(const Rung& rung, std::size_t item, std::uint32_t firstStatement, qreal top) {
        const qreal y = m_geometry.wireY(top, 0);
        PowerFeed power{PowerFeed::Kind::Rail, firstStatement, {}};
        RungGeometry::Extent condition;
        if (rung.condition) {
            lang::PreOrderNumbering<Circuit> numbering(
                *rung.condition, [](const Circuit& c) -> const auto& { return c.parts; });
            ElementPath path{item, {}};
            RungGeometry::Placed placed = m_geometry.placeCircuit(
                *rung.condition, numbering, labelsOf(), path, firstStatement, top, 0, 0, power);
            condition = placed.extent;
            power = std::move(placed.output);
        }
        m_geometry.wire(m_railX + condition.columns * m_metrics.cellWidth, y, m_outputX, y, power);

        const int outputs = static_cast<int>(rung.outputs.size());
        const qreal lastY = m_geometry.wireY(top, outputs - 1);
        m_geometry.wire(m_outputX, y, m_outputX, lastY, power);
        for (int i = 0; i < outputs; ++i) {
            const Output& output = rung.outputs[static_cast<std::size_t>(i)];
            const ElementLabels l = labels(output);
            const int columns = m_geometry.span(l);
            const int column = m_layout.conditionColumns + m_layout.outputColumns - columns;
            const qreal left = m_railX + column * m_metrics.cellWidth;
            ElementLayout& e =
                m_geometry.place(l, left, top + i * m_metrics.cellHeight, column, i, columns);
            e.statement = firstStatement + static_cast<std::uint32_t>(i);
            e.element = lang::kOutputElement;
            e.path = {item, {}};
            e.output = i;
            const qreal outY = m_geometry.wireY(top, i);
            const qreal symbolLeft = e.symbolRect.left();
            const qreal symbolRight = e.symbolRect.right();
            m_geometry.wire(m_outputX, outY, symbolLeft, outY, power);
            m_geometry.wire(symbolRight, outY, m_rightRailX, outY, {});
            if (output.comment)
                outputComment(*output.comment, outY);
        }
        const qreal bottom = top + std::max(condition.rows, outputs) * m_metrics.cellHeight;
        m_layout.wires.push_back({QLineF(m_railX, top, m_railX, bottom),
                                  {PowerFeed::Kind::Rail, firstStatement, {}},
                                  true});
        m_width = std::max(m_width, m_rightRailX);
        return bottom;
    }

    void outputComment(const std::string& comment, qreal y) {
        const QString shown = shortened(text(comment).trimmed());
        if (shown.isEmpty())
            return;
        const qreal width = shown.size() * m_metrics.charWidth;
        m_commentWidth = std::max(m_commentWidth, width);
        m_layout.texts.push_back(
            {TextLayout::Role::OutputComment,
             QRectF(m_commentX, y - m_metrics.labelHeight / 2, width, m_metrics.labelHeight),
             shown});
    }

    qreal placeNote(const lang::Line& line, qreal top) {
        const auto* comment = std::get_if<lang::CommentLine>(&line.body);
        if (!comment)
            return top; // a blank line leaves no mark in the drawing
        const QString shown = shortened(text(comment->text).trimmed());
        const qreal left = m_railX + kCommentGap;
        const qreal width = std::max<qreal>(shown.size() * m_metrics.charWidth, 1);
        m_width = std::max(m_width, left + width);
        m_layout.texts.push_back(
            {TextLayout::Role::Note, QRectF(left, top, width, m_metrics.noteHeight), shown});
        const qreal bottom = top + m_metrics.noteHeight;
        m_layout.wires.push_back({QLineF(m_railX, top, m_railX, bottom), {}, true});
        return bottom;
    }

    // A block network shows the first line of its block's description as
    // its comment: the dialogs show the whole of it.
    std::string commentShown() const {
        if (!m_network.block || !m_context.block)
            return m_network.comment;
        const std::string& description = m_context.block->description.in(m_context.language);
        return description.substr(0, description.find('\n'));
    }

    // The title and the comment's lines beside it; returns where the rungs start.
    qreal title() {
        const qreal top = m_metrics.margin;
        m_width = std::max(m_width, m_metrics.margin + kTitleWidth);
        m_layout.texts.push_back({TextLayout::Role::Title,
                                  QRectF(m_metrics.margin, top, kTitleWidth, m_metrics.titleHeight),
                                  m_context.title.isEmpty()
                                      ? QStringLiteral("Network %1").arg(m_context.number)
                                      : m_context.title});
        const QStringList lines = text(commentShown()).split(u'\n');
        qreal y = top;
        for (const QString& whole : lines) {
            const QString line = shortened(whole);
            if (!line.isEmpty()) {
                const qreal left = m_metrics.margin + kTitleWidth;
                const qreal width = line.size() * m_metrics.charWidth;
                m_width = std::max(m_width, left + width);
                m_layout.texts.push_back({TextLayout::Role::Comment,
                                          QRectF(left, y, width, m_metrics.titleHeight), line});
            }
            y += m_metrics.titleHeight;
        }
        return y + m_metrics.margin / 2;
    }

    const Network& m_network;
    const LayoutContext& m_context;
    const LayoutMetrics& m_metrics;
    NetworkLayout m_layout;
    qreal m_railX = 0;
    qreal m_outputX = 0;
    qreal m_rightRailX = 0;
    qreal m_commentX = 0;
    qreal m_commentWidth = 0;
    qreal m_width = 0;
    RungGeometry m_geometry{m_layout, m_metrics, m_metrics.margin};
};

} // namespace

NetworkLayout layoutNetwork(const Network& network, const LayoutContext& context) {
    return Layouter(network, context).run();
}

void moveLayout(NetworkLayout& layout, const LayoutContext& from, const LayoutContext& to) {
    const std::uint32_t shift = to.firstStatement - from.firstStatement; // modulo 2^32
    for (auto& element : layout.elements)
        element.statement += shift;
    for (auto& wire : layout.wires)
        if (wire.feed.kind != PowerFeed::Kind::None)
            wire.feed.statement += shift;
    for (auto& text : layout.texts)
        if (text.role == TextLayout::Role::Title)
            text.text = to.title.isEmpty() ? QStringLiteral("Network %1").arg(to.number) : to.title;
}

} // namespace rs::ladder
