// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "LadderDrawing.h"
#ifndef Q_MOC_RUN
#include "ladder/ConfigOption.h"
#include "ladder/Layout.h"
#include "ladder/Network.h"
#endif

#include <QGraphicsItem>

namespace rs::ui {

// One network of a ladder page. It keeps the network's layout and lays it out
// again only when the network, its number, its first statement or the names
// change; painting draws the cached layout with the renderer, so a page of
// thousands of networks costs only what is on screen.
class NetworkItem : public QGraphicsItem {
public:
    static constexpr qreal kGutter = 24; // left of the network: the expand/collapse box

    NetworkItem(const LadderDrawing* drawing, int step, int index);

    // Lays the network out unless it is the one laid out already. Returns whether it did.
    bool setNetwork(const ladder::Network& network, const ladder::LayoutContext& context,
                    int namesVersion);
    // The network laid out already, numbered as `context` says (an edit
    // above it moved it): nothing is laid out again. Returns whether it moved.
    bool renumber(const ladder::LayoutContext& context);
    void setIndex(int step, int index);
    int step() const { return m_step; }
    int index() const { return m_index; }
    const ladder::Network& network() const { return m_network; }
    // Numbered as the item is now (renumber() only notes the numbers; they
    // are written into the layout when it is first asked for).
    const ladder::NetworkLayout& layout() const;
    std::uint32_t firstStatement() const { return m_firstStatement; }
    // A Config Option network: drawn with its check box at the right.
    const std::optional<ladder::ConfigOption>& option() const { return m_option; }
    QRectF optionBox() const;

    void setCollapsed(bool collapsed);
    bool collapsed() const { return m_collapsed; }

    // The element at a point in item coordinates, or -1.
    int elementAt(const QPointF& point) const;
    bool inCollapseBox(const QPointF& point) const;
    QRectF collapseBox() const; // in item coordinates
    // Where an element, or a group's elements together, stand in item coordinates.
    QRectF elementRect(const ladder::ElementLayout& element) const;
    QRectF groupRect(const ladder::ElementPath& path) const;

    // What the bar left of the network says at a point in item coordinates:
    // that it changed since validation; empty elsewhere or when it did not.
    QString validationNote(const QPointF& point) const;

    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
    void paintOverlay(QPainter& painter) const;
    void paintValidationBar(QPainter& painter) const;
    QRectF validationBar() const;
    void paintSketch(QPainter& painter) const;
    // Zoomed out so far that the network is a few pixels high: one bar, green
    // when any of its outputs is driven.
    void paintBar(QPainter& painter) const;

    const LadderDrawing* m_drawing;
    int m_step;
    int m_index;
    ladder::Network m_network;
    mutable ladder::NetworkLayout m_layout;
    int m_number = 0;
    std::uint32_t m_firstStatement = 0;
    QString m_title;
    // What m_layout is numbered with; an edit above moves many networks, of
    // which a frame draws a few.
    mutable int m_layoutNumber = 0;
    mutable std::uint32_t m_layoutFirstStatement = 0;
    std::uint32_t m_statementCount = 0;
    int m_namesVersion = -1;
    const blocks::BlockDefinition* m_block = nullptr; // of a block network, as laid out
    QString m_blockNote;
    bool m_laidOut = false;
    bool m_collapsed = false;
    std::optional<ladder::ConfigOption> m_option;
};

} // namespace rs::ui
