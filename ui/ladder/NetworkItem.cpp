// SPDX-License-Identifier: GPL-3.0-or-later
#include "NetworkItem.h"

#include "NetworkPainter.h"

#include <QPainter>
#include <QStyleOptionGraphicsItem>

#include <algorithm>

namespace rs::ui {

namespace {

constexpr qreal kSelectionPad = 3;
constexpr qreal kSketchBelow = 0.3; // zoom under which networks are sketched
// A network fewer device pixels high than this is one bar: its wires would
// fall on the same few pixels, and a page of thousands of them must repaint
// within a live update.
constexpr qreal kBarBelowPixels = 8;
constexpr qreal kOptionWidth = 150; // right of an option network: its check box

bool startsWith(const std::vector<std::size_t>& path, const std::vector<std::size_t>& prefix) {
    return path.size() >= prefix.size() && std::equal(prefix.begin(), prefix.end(), path.begin());
}

} // namespace

NetworkItem::NetworkItem(const LadderDrawing* drawing, int step, int index)
    : m_drawing(drawing), m_step(step), m_index(index) {}

bool NetworkItem::setNetwork(const ladder::Network& network, const ladder::LayoutContext& context,
                             int namesVersion) {
    if (m_laidOut && network == m_network && namesVersion == m_namesVersion &&
        context.block == m_block && context.blockNote == m_blockNote)
        return renumber(context);
    prepareGeometryChange();
    m_network = network;
    m_number = context.number;
    m_firstStatement = context.firstStatement;
    m_statementCount = static_cast<std::uint32_t>(ladder::statementCount(network));
    m_namesVersion = namesVersion;
    m_block = context.block;
    m_blockNote = context.blockNote;
    m_layout = ladder::layoutNetwork(network, context);
    m_title = context.title;
    m_layoutNumber = m_number;
    m_layoutFirstStatement = m_firstStatement;
    m_option = ladder::configOptionOf(network);
    m_laidOut = true;
    update();
    return true;
}

bool NetworkItem::renumber(const ladder::LayoutContext& context) {
    if (context.number == m_number && context.firstStatement == m_firstStatement)
        return false;
    m_number = context.number;
    m_firstStatement = context.firstStatement;
    m_title = context.title;
    update();
    return true;
}

const ladder::NetworkLayout& NetworkItem::layout() const {
    if (m_layoutNumber != m_number || m_layoutFirstStatement != m_firstStatement) {
        ladder::LayoutContext from;
        from.number = m_layoutNumber;
        from.firstStatement = m_layoutFirstStatement;
        ladder::LayoutContext to;
        to.number = m_number;
        to.title = m_title;
        to.firstStatement = m_firstStatement;
        ladder::moveLayout(m_layout, from, to);
        m_layoutNumber = m_number;
        m_layoutFirstStatement = m_firstStatement;
    }
    return m_layout;
}

void NetworkItem::setIndex(int step, int index) {
    m_step = step;
    m_index = index;
}

void NetworkItem::setCollapsed(bool collapsed) {
    if (collapsed == m_collapsed)
        return;
    prepareGeometryChange();
    m_collapsed = collapsed;
}

QRectF NetworkItem::boundingRect() const {
    const qreal height = m_collapsed ? m_layout.metrics.titleHeight + m_layout.metrics.margin + 6
                                     : m_layout.size.height();
    return {0, 0, kGutter + m_layout.size.width() + (m_option ? kOptionWidth : 0), height};
}

QRectF NetworkItem::optionBox() const {
    const qreal side = 16;
    return {kGutter + m_layout.size.width() + 12,
            m_layout.metrics.margin + (m_layout.metrics.titleHeight - side) / 2, side, side};
}

QRectF NetworkItem::collapseBox() const {
    const qreal side = 11;
    return {(kGutter - side) / 2,
            m_layout.metrics.margin + (m_layout.metrics.titleHeight - side) / 2, side, side};
}

bool NetworkItem::inCollapseBox(const QPointF& point) const {
    return collapseBox().adjusted(-4, -4, 4, 4).contains(point);
}

int NetworkItem::elementAt(const QPointF& point) const {
    if (m_collapsed)
        return -1;
    const QPointF local = point - QPointF(kGutter, 0);
    const auto& elements = layout().elements;
    for (std::size_t i = 0; i < elements.size(); ++i)
        if (elements[i].cell.contains(local))
            return static_cast<int>(i);
    return -1;
}

QRectF NetworkItem::elementRect(const ladder::ElementLayout& element) const {
    return element.cell.translated(kGutter, 0);
}

QRectF NetworkItem::groupRect(const ladder::ElementPath& path) const {
    QRectF rect;
    for (const auto& element : layout().elements)
        if (element.output < 0 && element.path.item == path.item &&
            startsWith(element.path.node, path.node))
            rect = rect.united(elementRect(element));
    return rect;
}

void NetworkItem::paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget*) {
    const render::LadderStyle& style = m_drawing->style;
    const QRectF bounds = boundingRect();
    const qreal detail = option->levelOfDetailFromTransform(painter->worldTransform());
    if (detail * bounds.height() < kBarBelowPixels) {
        paintBar(*painter); // on the view's background, which is the page's
        paintValidationBar(*painter);
        return;
    }
    painter->fillRect(bounds, style.background);
    // Zoomed far out, text would be specks: wires and symbols as plain shapes
    // draw a thousand networks in the time of a few.
    if (detail < kSketchBelow) {
        paintSketch(*painter);
        paintValidationBar(*painter);
        return;
    }
    painter->save();
    painter->translate(kGutter, 0);
    if (m_collapsed)
        painter->setClipRect(QRectF(0, 0, m_layout.size.width(),
                                    m_layout.metrics.titleHeight + m_layout.metrics.margin));
    render::paintNetwork(*painter, layout(), style,
                         m_drawing->live ? &m_drawing->live->power : nullptr);
    painter->restore();
    if (m_drawing->marked.count({m_step, m_index}) > 0)
        painter->fillRect(
            QRectF(0, 0, bounds.width(), m_layout.metrics.titleHeight + m_layout.metrics.margin),
            m_drawing->markedNetwork);

    if (m_option) {
        const QRectF box = optionBox();
        painter->setPen(QPen(style.ink, 1.5));
        painter->setBrush(style.background);
        painter->drawRect(box);
        if (m_option->checked) {
            painter->setPen(QPen(style.powered, 2.5));
            painter->drawPolyline(
                QPolygonF({box.topLeft() + QPointF(3, 8), box.topLeft() + QPointF(7, 12),
                           box.topLeft() + QPointF(13, 4)}));
        }
        painter->setPen(style.ink);
        painter->setFont(style.font(style.labelPixelSize, true));
        painter->drawText(
            QRectF(box.right() + 6, box.top() - 2, kOptionWidth - 40, box.height() + 4),
            Qt::AlignLeft | Qt::AlignVCenter,
            m_option->checked ? QObject::tr("Option on") : QObject::tr("Option off"));
    }
    // The expand/collapse box.
    painter->setPen(QPen(style.ink, 1));
    painter->setBrush(Qt::NoBrush);
    const QRectF box = collapseBox();
    painter->drawRect(box);
    painter->drawLine(QPointF(box.left() + 2, box.center().y()),
                      QPointF(box.right() - 2, box.center().y()));
    if (m_collapsed)
        painter->drawLine(QPointF(box.center().x(), box.top() + 2),
                          QPointF(box.center().x(), box.bottom() - 2));
    // A line under each network separates it from the next.
    painter->setPen(QPen(style.commentInk, 0.5));
    painter->drawLine(bounds.bottomLeft(), bounds.bottomRight());
    paintValidationBar(*painter);
    paintOverlay(*painter);
}

QRectF NetworkItem::validationBar() const {
    return {1, 1, 4, boundingRect().height() - 2};
}

void NetworkItem::paintValidationBar(QPainter& painter) const {
    const auto mark = m_drawing->sinceValidation.find({m_step, m_index});
    if (mark == m_drawing->sinceValidation.end())
        return;
    painter.fillRect(validationBar(), mark->second ? m_drawing->addedSinceValidation
                                                   : m_drawing->changedSinceValidation);
}

QString NetworkItem::validationNote(const QPointF& point) const {
    const auto mark = m_drawing->sinceValidation.find({m_step, m_index});
    if (mark == m_drawing->sinceValidation.end() ||
        !validationBar().adjusted(-1, 0, 3, 0).contains(point))
        return {};
    return mark->second ? QObject::tr("Added since validation on %1").arg(m_drawing->validatedOn)
                        : QObject::tr("Changed since validation on %1").arg(m_drawing->validatedOn);
}

void NetworkItem::paintBar(QPainter& painter) const {
    const render::LadderStyle& style = m_drawing->style;
    const render::PowerSnapshot* power = m_drawing->live ? &m_drawing->live->power : nullptr;
    bool energised = false;
    // The network's statements are numbered one after the other: one search,
    // then a walk, for a page of thousands of bars.
    if (power)
        for (auto it = power->statements.lower_bound(m_firstStatement);
             it != power->statements.end() && it->first < m_firstStatement + m_statementCount; ++it)
            if (it->second.energised) {
                energised = true;
                break;
            }
    const QRectF bounds = boundingRect();
    painter.fillRect(
        QRectF(kGutter, bounds.height() * 0.2, m_layout.size.width(), bounds.height() * 0.6),
        energised ? style.powered : style.commentInk);
}

void NetworkItem::paintSketch(QPainter& painter) const {
    const render::LadderStyle& style = m_drawing->style;
    const render::PowerSnapshot* power = m_drawing->live ? &m_drawing->live->power : nullptr;
    painter.save();
    painter.translate(kGutter, 0);
    painter.setRenderHint(QPainter::Antialiasing, false);
    painter.fillRect(QRectF(0, m_layout.metrics.margin, m_layout.size.width() / 3,
                            m_layout.metrics.titleHeight * 0.6),
                     style.commentInk);
    if (!m_collapsed) {
        for (const auto& wire : layout().wires) {
            const bool powered = power && power->powers(wire.feed);
            painter.setPen(QPen(powered ? style.powered : style.ink, wire.rail ? 3 : 0));
            painter.drawLine(wire.line);
        }
        // Live, an element that is open (or an output that is 0) is only
        // outlined, as it is hollow at full size.
        for (const auto& element : layout().elements) {
            const bool powered = power && power->conducts(element.statement, element.element);
            const QColor& colour = powered ? style.powered : style.ink;
            if (!power || power->closed(element.statement, element.element)) {
                painter.fillRect(element.symbolRect, colour);
            } else {
                painter.setPen(QPen(colour, 0));
                painter.setBrush(Qt::NoBrush);
                painter.drawRect(element.symbolRect);
            }
        }
    }
    painter.restore();
}

void NetworkItem::paintOverlay(QPainter& painter) const {
    const LadderDrawing& drawing = *m_drawing;
    const QRectF bounds = boundingRect();
    if (drawing.editingNetwork == std::make_pair(m_step, m_index)) {
        painter.setPen(QPen(drawing.editing, 2.5));
        painter.setBrush(Qt::NoBrush);
        painter.drawRect(bounds.adjusted(1.5, 1.5, -1.5, -1.5));
    }
    const LadderCursor& cursor = drawing.cursor;
    if (cursor.sameNetwork(m_step, m_index)) {
        QRectF selected;
        if (cursor.wholeNetwork()) {
            selected = bounds.adjusted(kGutter - 2, 1, -1, -1);
        } else if (cursor.node) {
            selected = groupRect(*cursor.node);
        } else {
            for (const auto& element : layout().elements)
                if (element.output == cursor.outputIndex &&
                    element.path.item == cursor.output->item)
                    selected = elementRect(element);
        }
        if (!selected.isNull()) {
            QPen pen(drawing.selection, 2);
            if (cursor.wholeNetwork())
                pen.setStyle(Qt::DashLine);
            painter.setPen(pen);
            painter.setBrush(Qt::NoBrush);
            painter.drawRoundedRect(selected.adjusted(-kSelectionPad + 4, 2, kSelectionPad - 4, -2),
                                    4, 4);
        }
    }
    if (m_collapsed)
        return;
    QFont small = drawing.style.font(drawing.style.labelPixelSize, true);
    painter.setFont(small);
    for (const auto& element : layout().elements) {
        const auto key = std::make_pair(element.statement, element.element);
        const QRectF cell = elementRect(element);
        const bool problem =
            drawing.problems.count(key) > 0 ||
            (element.output >= 0 && drawing.problems.count({element.statement, 0}) > 0);
        if (problem) {
            painter.setPen(QPen(drawing.problem, 2, Qt::DotLine));
            painter.setBrush(Qt::NoBrush);
            painter.drawRect(cell.adjusted(4, 3, -4, -3));
        }
        if (!drawing.live)
            continue;
        // Why the selected output is off: the first element that blocks each
        // path (dashed); why it is on: the path that holds it (dotted).
        const bool blocking = drawing.blocking.count(key) > 0;
        if (blocking || drawing.holding.count(key) > 0) {
            painter.setPen(QPen(drawing.explained, 3, blocking ? Qt::DashLine : Qt::DotLine));
            painter.setBrush(Qt::NoBrush);
            painter.drawRoundedRect(cell.adjusted(3, 2, -3, -2), 5, 5);
        }
        if (const auto note = drawing.live->annotations.find(key);
            note != drawing.live->annotations.end()) {
            // The value takes the place of the address or preset it tells
            // about ("1.20 s / 3.00 s" for "3s00"): below the cell the text
            // would run into the next rung or the network's border. It stays
            // within its cell, shortened if it must be.
            const QRectF label = element.addressRect.translated(kGutter, 0);
            painter.fillRect(label, drawing.style.background);
            painter.setPen(drawing.style.powered);
            const QString text = painter.fontMetrics().elidedText(
                note->second, Qt::ElideRight, static_cast<int>(cell.width()) - 4);
            painter.drawText(QRectF(cell.left(), label.top(), cell.width(), label.height()),
                             Qt::AlignCenter, text);
        }
        const bool forced =
            (!element.address.isEmpty() && drawing.live->forced.count(element.address) > 0) ||
            drawing.live->forcedElements.count(key) > 0;
        if (forced) {
            const QRectF symbol = element.symbolRect.translated(kGutter, 0);
            const QRectF badge(symbol.right() - 7, symbol.top() - 9, 14, 14);
            painter.setPen(Qt::NoPen);
            painter.setBrush(drawing.problem);
            painter.drawRect(badge);
            painter.setPen(Qt::white);
            painter.drawText(badge, Qt::AlignCenter, QStringLiteral("F"));
        }
    }
}

} // namespace rs::ui
