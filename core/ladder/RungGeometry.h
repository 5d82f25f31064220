// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Layout.h"
#include "SeriesParallel.h"
#include "lang/ElementNumbering.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

// The geometry every target's rungs share: series parts side by side,
// parallel branches one below the other, outputs at the right, wires that
// carry the power feed of what drives them (docs/ladder.md). What an element
// looks like is the target's: `labelsOf(element)` gives its ElementLabels.
namespace rs::ladder {

// An element before it has a place: how it is drawn and what is written on it.
struct ElementLabels {
    ElementKind kind = ElementKind::NormallyOpen; // Pluto's kind; the editor's handle on it
    Shape shape = Shape::Contact;
    QString mark; // inside a contact or coil: "P", "S", "/" for a normally closed contact
    bool negated = false;
    QString name;
    QString address;
    QString text; // inside a box
};

inline constexpr qreal kSymbolWidth = 24; // a contact or coil
inline constexpr qreal kSymbolHeight = 26;
inline constexpr qreal kBoxInset = 12; // between a box and its cell's sides
inline constexpr qreal kBoxHeight = 28;
inline constexpr qreal kLabelInset = 3;

class RungGeometry {
public:
    RungGeometry(NetworkLayout& layout, const LayoutMetrics& metrics, qreal railX)
        : m_layout(layout), m_metrics(metrics), m_railX(railX) {}

    struct Extent {
        int columns = 0;
        int rows = 0;
    };

    // A box whose text does not fit one column takes two.
    int span(const ElementLabels& l) const {
        if (l.shape != Shape::Box)
            return 1;
        return l.text.size() * m_metrics.charWidth > m_metrics.cellWidth - 2 * kBoxInset ? 2 : 1;
    }

    template <class E, class LabelsOf>
    Extent extent(const SeriesParallel<E>& circuit, const LabelsOf& labelsOf) const {
        if (circuit.isElement())
            return {span(labelsOf(circuit.element)), 1};
        Extent total;
        for (const auto& part : circuit.parts) {
            const Extent e = extent(part, labelsOf);
            if (circuit.kind == SeriesParallel<E>::Kind::Series) {
                total.columns += e.columns;
                total.rows = std::max(total.rows, e.rows);
            } else {
                total.columns = std::max(total.columns, e.columns);
                total.rows += e.rows;
            }
        }
        return total;
    }

    qreal wireY(qreal rungTop, int row) const {
        return rungTop + row * m_metrics.cellHeight + m_metrics.cellHeight / 2;
    }

    void wire(qreal x1, qreal y1, qreal x2, qreal y2, PowerFeed feed) {
        if (x1 != x2 || y1 != y2)
            m_layout.wires.push_back({QLineF(x1, y1, x2, y2), std::move(feed), false});
    }

    PowerFeed fedBy(std::uint32_t statement, std::vector<std::uint16_t> elements) const {
        return {PowerFeed::Kind::Elements, statement, std::move(elements)};
    }

    ElementLayout& place(const ElementLabels& l, qreal left, qreal top, int column, int row,
                         int columns) {
        ElementLayout e;
        e.kind = l.kind;
        e.shape = l.shape;
        e.mark = l.mark;
        e.negated = l.negated;
        e.column = column;
        e.row = row;
        e.columnSpan = columns;
        e.cell = QRectF(left, top, columns * m_metrics.cellWidth, m_metrics.cellHeight);
        const qreal middle = e.cell.center().y();
        if (l.shape == Shape::Box)
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

    // Places a condition node with its top-left grid cell at (column, row)
    // of the rung whose top is `rungTop`, numbered by the one rule
    // (lang/ElementNumbering.h); `path` is the node's place in the circuit,
    // grown and shrunk on the way down rather than copied.
    template <class E, class LabelsOf>
    Placed placeCircuit(const SeriesParallel<E>& circuit,
                        lang::PreOrderNumbering<SeriesParallel<E>>& numbering,
                        const LabelsOf& labelsOf, ElementPath& path, std::uint32_t statement,
                        qreal rungTop, int column, int row, const PowerFeed& input) {
        const std::uint16_t id = numbering.number(circuit);
        const qreal left = m_railX + column * m_metrics.cellWidth;
        const qreal y = wireY(rungTop, row);
        if (circuit.isElement()) {
            const ElementLabels l = labelsOf(circuit.element);
            const int columns = span(l);
            ElementLayout& e =
                place(l, left, rungTop + row * m_metrics.cellHeight, column, row, columns);
            e.statement = statement;
            e.element = id;
            e.path = path;
            const qreal symbolLeft = e.symbolRect.left();
            const qreal symbolRight = e.symbolRect.right();
            const qreal right = e.cell.right();
            wire(left, y, symbolLeft, y, input);
            wire(symbolRight, y, right, y, fedBy(statement, {id}));
            return {{columns, 1}, fedBy(statement, {id})};
        }
        const bool series = circuit.kind == SeriesParallel<E>::Kind::Series;
        Placed placed;
        std::vector<Placed> branches;
        int offset = 0;
        PowerFeed feed = input;
        for (std::size_t i = 0; i < circuit.parts.size(); ++i) {
            path.node.push_back(i);
            if (series) {
                Placed part = placeCircuit(circuit.parts[i], numbering, labelsOf, path, statement,
                                           rungTop, column + offset, row, feed);
                offset += part.extent.columns;
                placed.extent.columns = offset;
                placed.extent.rows = std::max(placed.extent.rows, part.extent.rows);
                feed = std::move(part.output);
            } else {
                branches.push_back(placeCircuit(circuit.parts[i], numbering, labelsOf, path,
                                                statement, rungTop, column, row + offset, input));
                placed.extent.columns =
                    std::max(placed.extent.columns, branches.back().extent.columns);
                placed.extent.rows += branches.back().extent.rows;
                offset += branches.back().extent.rows;
            }
            path.node.pop_back();
        }
        if (series) {
            placed.output = std::move(feed);
            return placed;
        }
        // Parallel: bars down the left and right, and short branches drawn out to the right.
        const qreal right = left + placed.extent.columns * m_metrics.cellWidth;
        std::vector<std::uint16_t> joined;
        int branchRow = row;
        for (const auto& branch : branches) {
            const qreal branchY = wireY(rungTop, branchRow);
            wire(left + branch.extent.columns * m_metrics.cellWidth, branchY, right, branchY,
                 branch.output);
            joined.insert(joined.end(), branch.output.elements.begin(),
                          branch.output.elements.end());
            branchRow += branch.extent.rows;
        }
        const qreal lastY = wireY(rungTop, branchRow - branches.back().extent.rows);
        wire(left, y, left, lastY, input);
        placed.output = fedBy(statement, std::move(joined));
        wire(right, y, right, lastY, placed.output);
        return placed;
    }

private:
    NetworkLayout& m_layout;
    const LayoutMetrics& m_metrics;
    qreal m_railX;
};

} // namespace rs::ladder
