// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QGraphicsView>
#include <QVariantAnimation>

#include <utility>
#include <vector>

class QAction;

namespace rs::ui {

// The scrolling view of a ladder page's scene, in a band that takes the
// highlight colour while the view has the keyboard focus. It zooms with Ctrl+wheel and
// hands clicks, double clicks, context menus and drags to the page, which
// knows what the items stand for. A key pressed in the view triggers the
// page's action with that shortcut.
class LadderView : public QGraphicsView {
    Q_OBJECT
public:
    static constexpr qreal kMinimumZoom = 0.1;
    static constexpr qreal kMaximumZoom = 4;

    explicit LadderView(QGraphicsScene* scene, QWidget* parent = nullptr);

    qreal zoom() const { return m_zoom; }
    void setZoom(qreal zoom);
    void zoomIn();
    void zoomOut();
    // The actions a key pressed in the view triggers, by their shortcuts.
    void setKeyActions(std::vector<QAction*> actions) { m_keyActions = std::move(actions); }

public slots:
    // The window's Edit > Cut, Copy and Paste act on the widget with the focus.
    void cut() { emit cutRequested(); }
    void copy() { emit copyRequested(); }
    void paste() { emit pasteRequested(); }

signals:
    void pressed(const QPointF& scenePosition, Qt::MouseButton button,
                 Qt::KeyboardModifiers modifiers);
    void doubleClicked(const QPointF& scenePosition);
    void menuRequested(const QPointF& scenePosition, const QPoint& globalPosition);
    // The left button went down at `from` and the mouse moved far enough to drag.
    void dragStarted(const QPointF& from);
    // An element's drag is over the view: plain copies, with Shift it moves.
    void dragHovered(const QPointF& scenePosition, const QByteArray& payload, bool move);
    void dragLeft();
    void dropped(const QPointF& scenePosition, const QByteArray& payload, bool move);
    void zoomChanged(qreal zoom);
    void cutRequested();
    void copyRequested();
    void pasteRequested();

protected:
    bool event(QEvent* event) override;
    bool viewportEvent(QEvent* event) override;
    void focusInEvent(QFocusEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dragMoveEvent(QDragMoveEvent* event) override;
    void dragLeaveEvent(QDragLeaveEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    std::vector<QAction*> m_keyActions;
    qreal m_zoom = 1;
    QVariantAnimation m_glide; // smooth scrolling by wheel notches
    int m_glideTarget = 0;
    QPoint m_pressAt;
    bool m_mayDrag = false;
};

// The MIME type of an element dragged within or between ladder pages.
inline constexpr const char* kElementMimeType = "application/x-rungsmith-ladder-element";

} // namespace rs::ui
