// SPDX-License-Identifier: GPL-3.0-or-later
#include "Layout.h"

#include "BlockLayout.h"
#include "ElementVocabulary.h"

#include "lang/ElementNumbering.h"
#include "lang/Keywords.h"
#include "lang/Printer.h"

#include <QCoreApplication>
#include <QStringList>

#include <algorithm>

namespace rs::ladder {

namespace {

constexpr qreal kSymbolWidth = 24; // a contact or coil
constexpr qreal kSymbolHeight = 26;
constexpr qreal kBoxInset = 12; // between a box and its cell's sides
constexpr qreal kBoxHeight = 28;
constexpr qreal kLabelInset = 3;
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

// The labels of an element before it has a place.
struct Labels {
    ElementKind kind = ElementKind::NormallyOpen;
    bool negated = false;
    QString name;
    QString address;
    QString text;
};

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

    Labels labels(const Element& element) const {
        Labels l;
        l.kind = kindOf(element);
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

    Labels labels(const Output& output) const {
        Labels l;
        l.kind = kindOf(output);
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

    // A box whose text does not fit one column takes two.
    int span(const Labels& l) const {
        if (!isBox(l.kind))
            return 1;
        return l.text.size() * m_metrics.charWidth > m_metrics.cellWidth - 2 * kBoxInset ? 2 : 1;
    }

    struct Extent {
        int columns = 0;
        int rows = 0;
    };

    Extent extent(const Circuit& circuit) const {
        if (circuit.isElement())
            return {span(labels(circuit.element)), 1};
        Extent total;
        for (const auto& part : circuit.parts) {
            Extent e = extent(part);
            if (circuit.kind == Circuit::Kind::Series) {
                total.columns += e.columns;
                total.rows = std::max(total.rows, e.rows);
            } else {
                total.columns = std::max(total.columns, e.columns);
                total.rows += e.rows;
            }
        }
        return total;
    }

    void measureColumns() {
        int condition = m_metrics.minimumConditionColumns;
        int outputs = 1;
        for (const auto& item : m_network.items) {
            const auto* rung = std::get_if<Rung>(&item);
            if (!rung)
                continue;
            if (rung->condition)
                condition = std::max(condition, extent(*rung->condition).columns);
            for (const auto& output : rung->outputs)
                outputs = std::max(outputs, span(labels(output)));
        }
        m_layout.conditionColumns = condition;
        m_layout.outputColumns = outputs;
    }

    // ----- geometry

    qreal wireY(qreal rungTop, int row) const {
        return rungTop + row * m_metrics.cellHeight + m_metrics.cellHeight / 2;
    }

    void wire(qreal x1, qreal y1, qreal x2, qreal y2, PowerFeed feed) {
        if (x1 != x2 || y1 != y2)
            m_layout.wires.push_back({QLineF(x1, y1, x2, y2), std::move(feed), false});
    }

    PowerFeed fedBy(std::vector<std::uint16_t> elements) const {
        return {PowerFeed::Kind::Elements, m_statement, std::move(elements)};
    }

    ElementLayout& place(const Labels& l, qreal left, qreal top, int column, int row, int columns) {
        ElementLayout e;
        e.kind = l.kind;
        e.negated = l.negated;
        e.column = column;
        e.row = row;
        e.columnSpan = columns;
        e.cell = QRectF(left, top, columns * m_metrics.cellWidth, m_metrics.cellHeight);
        const qreal middle = e.cell.center().y();
        if (isBox(l.kind))
            e.symbolRect = QRectF(e.cell.left() + kBoxInset, middle - kBoxHeight / 2,
                                  e.cell.width() - 2 * kBoxInset, kBoxHeight);
        else
            e.symbolRect = QRectF(e.cell.center().x() - kSymbolWidth / 2,
                                  middle - kSymbolHeight / 2, kSymbolWidth, kSymbolHeight);
        e.name = l.name;
        e.address = l.address;
        e.text = l.text;
        e.nameRect = QRectF(e.cell.left() + kLabelInset, e.cell.top() + kLabelInset,
                            e.cell.width() - 2 * kLabelInset, m_metrics.labelHeight);
        e.addressRect = QRectF(e.cell.left() + kLabelInset,
                               e.cell.bottom() - kLabelInset - m_metrics.labelHeight,
                               e.cell.width() - 2 * kLabelInset, m_metrics.labelHeight);
        m_layout.elements.push_back(std::move(e));
        return m_layout.elements.back();
    }

    struct Placed {
        Extent extent;
        PowerFeed output;
    };

    // Places a condition node with its top-left grid cell at (column, row),
    // numbered by the one rule (lang/ElementNumbering.h).
    Placed placeCircuit(const Circuit& circuit, std::vector<std::size_t>& path, int column, int row,
                        const PowerFeed& input) {
        const std::uint16_t id = m_numbering->number(circuit);
        const qreal left = m_railX + column * m_metrics.cellWidth;
        const qreal y = wireY(m_rungTop, row);
        if (circuit.isElement()) {
            const Labels l = labels(circuit.element);
            const int columns = span(l);
            ElementLayout& e =
                place(l, left, m_rungTop + row * m_metrics.cellHeight, column, row, columns);
            e.statement = m_statement;
            e.element = id;
            e.path = {m_item, path};
            const qreal symbolLeft = e.symbolRect.left();
            const qreal symbolRight = e.symbolRect.right();
            const qreal right = e.cell.right();
            wire(left, y, symbolLeft, y, input);
            wire(symbolRight, y, right, y, fedBy({id}));
            return {{columns, 1}, fedBy({id})};
        }
        Placed placed;
        std::vector<Placed> branches;
        int offset = 0;
        PowerFeed feed = input;
        for (std::size_t i = 0; i < circuit.parts.size(); ++i) {
            path.push_back(i);
            if (circuit.kind == Circuit::Kind::Series) {
                Placed part = placeCircuit(circuit.parts[i], path, column + offset, row, feed);
                offset += part.extent.columns;
                placed.extent.columns = offset;
                placed.extent.rows = std::max(placed.extent.rows, part.extent.rows);
                feed = std::move(part.output);
            } else {
                branches.push_back(
                    placeCircuit(circuit.parts[i], path, column, row + offset, input));
                placed.extent.columns =
                    std::max(placed.extent.columns, branches.back().extent.columns);
                placed.extent.rows += branches.back().extent.rows;
                offset += branches.back().extent.rows;
            }
            path.pop_back();
        }
        if (circuit.kind == Circuit::Kind::Series) {
            placed.output = std::move(feed);
            return placed;
        }
        // Parallel: bars down the left and right, and short branches drawn out to the right.
        const qreal right = left + placed.extent.columns * m_metrics.cellWidth;
        std::vector<std::uint16_t> joined;
        int branchRow = row;
        for (const auto& branch : branches) {
            const qreal branchY = wireY(m_rungTop, branchRow);
            wire(left + branch.extent.columns * m_metrics.cellWidth, branchY, right, branchY,
                 branch.output);
            joined.insert(joined.end(), branch.output.elements.begin(),
                          branch.output.elements.end());
            branchRow += branch.extent.rows;
        }
        const qreal lastY = wireY(m_rungTop, branchRow - branches.back().extent.rows);
        wire(left, y, left, lastY, input);
        placed.output = fedBy(std::move(joined));
        wire(right, y, right, lastY, placed.output);
        return placed;
    }

    qreal placeRung(const Rung& rung, std::size_t item, std::uint32_t firstStatement, qreal top) {
        m_rungTop = top;
        m_item = item;
        m_statement = firstStatement;
        const qreal y = wireY(top, 0);
        PowerFeed power{PowerFeed::Kind::Rail, firstStatement, {}};
        Extent condition;
        if (rung.condition) {
            lang::PreOrderNumbering<Circuit> numbering(
                *rung.condition, [](const Circuit& c) -> const auto& { return c.parts; });
            m_numbering = &numbering;
            std::vector<std::size_t> path;
            Placed placed = placeCircuit(*rung.condition, path, 0, 0, power);
            m_numbering = nullptr;
            condition = placed.extent;
            power = std::move(placed.output);
        }
        wire(m_railX + condition.columns * m_metrics.cellWidth, y, m_outputX, y, power);

        const int outputs = static_cast<int>(rung.outputs.size());
        const qreal lastY = wireY(top, outputs - 1);
        wire(m_outputX, y, m_outputX, lastY, power);
        for (int i = 0; i < outputs; ++i) {
            const Output& output = rung.outputs[static_cast<std::size_t>(i)];
            const Labels l = labels(output);
            const int columns = span(l);
            const int column = m_layout.conditionColumns + m_layout.outputColumns - columns;
            const qreal left = m_railX + column * m_metrics.cellWidth;
            ElementLayout& e = place(l, left, top + i * m_metrics.cellHeight, column, i, columns);
            e.statement = firstStatement + static_cast<std::uint32_t>(i);
            e.element = lang::kOutputElement;
            e.path = {item, {}};
            e.output = i;
            const qreal outY = wireY(top, i);
            const qreal symbolLeft = e.symbolRect.left();
            const qreal symbolRight = e.symbolRect.right();
            wire(m_outputX, outY, symbolLeft, outY, power);
            wire(symbolRight, outY, m_rightRailX, outY, {});
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
    qreal m_rungTop = 0;
    std::size_t m_item = 0;
    std::uint32_t m_statement = 0;
    lang::PreOrderNumbering<Circuit>* m_numbering = nullptr;
};

} // namespace

NetworkLayout layoutNetwork(const Network& network, const LayoutContext& context) {
    return Layouter(network, context).run();
}

} // namespace rs::ladder
