// SPDX-License-Identifier: GPL-3.0-or-later
#include "LadderView.h"

#include "NetworkItem.h"

#include <QAction>
#include <QApplication>
#include <QContextMenuEvent>
#include <QHelpEvent>
#include <QMimeData>
#include <QPainter>
#include <QScrollBar>
#include <QToolTip>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace rs::ui {

namespace {

constexpr qreal kZoomStep = 1.25;
constexpr int kPixelsPerNotch = 120;
constexpr int kGlideMs = 120;
constexpr int kFocusBand = 2; // pixels around the viewport, outside what scrolls

} // namespace

LadderView::LadderView(QGraphicsScene* scene, QWidget* parent) : QGraphicsView(scene, parent) {
    setAlignment(Qt::AlignLeft | Qt::AlignTop);
    setFocusPolicy(Qt::StrongFocus);
    setFrameShape(QFrame::NoFrame);
    setViewportMargins(kFocusBand, kFocusBand, kFocusBand, kFocusBand);
    setAcceptDrops(true);
    // Items paint opaque backgrounds and restore the painter themselves.
    setOptimizationFlags(QGraphicsView::DontSavePainterState);
    setViewportUpdateMode(QGraphicsView::MinimalViewportUpdate);
    // The background brush fills the whole viewport in drawBackground; a widget
    // fill of its own before it would write every pixel twice a frame.
    viewport()->setAutoFillBackground(false);
    viewport()->setAttribute(Qt::WA_OpaquePaintEvent);
    setRenderHints(QPainter::Antialiasing | QPainter::TextAntialiasing);
    m_glide.setDuration(kGlideMs);
    m_glide.setEasingCurve(QEasingCurve::OutCubic);
    connect(&m_glide, &QVariantAnimation::valueChanged, this,
            [this](const QVariant& value) { verticalScrollBar()->setValue(value.toInt()); });
}

bool LadderView::event(QEvent* event) {
    const bool handled = QGraphicsView::event(event);
    if (event->type() == QEvent::Paint) {
        // The band is the view's own, not the viewport's: scrolling never moves it.
        QPainter painter(this);
        painter.setClipRegion(QRegion(rect()).subtracted(viewport()->geometry()));
        if (hasFocus()) {
            painter.fillRect(rect(), palette().color(QPalette::Highlight));
        } else {
            painter.fillRect(rect(), palette().color(QPalette::Base));
            painter.setPen(palette().color(QPalette::Mid));
            painter.drawRect(rect().adjusted(0, 0, -1, -1));
        }
    }
    return handled;
}

bool LadderView::viewportEvent(QEvent* event) {
    // The bar of a network changed since validation says so; items keep no
    // tool tips, which would show over every element.
    if (event->type() == QEvent::ToolTip) {
        const auto* help = static_cast<QHelpEvent*>(event);
        const QPointF at = mapToScene(help->pos());
        for (QGraphicsItem* item : items(help->pos()))
            if (const auto* network = dynamic_cast<const NetworkItem*>(item)) {
                const QString note = network->validationNote(network->mapFromScene(at));
                if (!note.isEmpty()) {
                    QToolTip::showText(help->globalPos(), note, viewport());
                    return true;
                }
            }
        QToolTip::hideText();
    }
    return QGraphicsView::viewportEvent(event);
}

void LadderView::focusInEvent(QFocusEvent* event) {
    QGraphicsView::focusInEvent(event);
    update();
}

void LadderView::focusOutEvent(QFocusEvent* event) {
    QGraphicsView::focusOutEvent(event);
    update();
}

void LadderView::setZoom(qreal zoom) {
    zoom = std::clamp(zoom, kMinimumZoom, kMaximumZoom);
    if (std::abs(zoom - m_zoom) < 1e-6)
        return;
    m_zoom = zoom;
    setTransform(QTransform::fromScale(zoom, zoom));
    emit zoomChanged(zoom);
}

void LadderView::zoomIn() {
    setZoom(m_zoom * kZoomStep);
}

void LadderView::zoomOut() {
    setZoom(m_zoom / kZoomStep);
}

void LadderView::wheelEvent(QWheelEvent* event) {
    if (event->modifiers() & Qt::ControlModifier) {
        const QPointF under = mapToScene(event->position().toPoint());
        if (event->angleDelta().y() > 0)
            zoomIn();
        else if (event->angleDelta().y() < 0)
            zoomOut();
        // Keep the point under the mouse where it was.
        const QPointF now = mapToScene(event->position().toPoint());
        const QPointF shift = (now - under) * m_zoom;
        horizontalScrollBar()->setValue(horizontalScrollBar()->value() - qRound(shift.x()));
        verticalScrollBar()->setValue(verticalScrollBar()->value() - qRound(shift.y()));
        event->accept();
        return;
    }
    // A wheel notch glides to its place instead of jumping; a touchpad's pixel
    // deltas are smooth already and go the usual way.
    if (event->pixelDelta().isNull() && event->angleDelta().y() != 0 &&
        !(event->modifiers() & Qt::ShiftModifier)) {
        QScrollBar* bar = verticalScrollBar();
        const bool gliding = m_glide.state() == QAbstractAnimation::Running;
        const int from = bar->value();
        const int to = std::clamp((gliding ? m_glideTarget : from) -
                                      event->angleDelta().y() * kPixelsPerNotch / 120,
                                  bar->minimum(), bar->maximum());
        m_glideTarget = to;
        m_glide.stop();
        m_glide.setStartValue(from);
        m_glide.setEndValue(to);
        m_glide.start();
        event->accept();
        return;
    }
    QGraphicsView::wheelEvent(event);
}

void LadderView::keyPressEvent(QKeyEvent* event) {
    const Qt::KeyboardModifiers modifiers =
        event->modifiers() & ~(Qt::KeypadModifier | Qt::GroupSwitchModifier);
    const auto key = Qt::Key(event->key());
    std::vector<QKeySequence> pressed = {QKeySequence(QKeyCombination(modifiers, key))};
    // A symbol typed with Shift (+ | / = on many layouts) is the symbol's key.
    const bool letter = key <= 0xffff && QChar(static_cast<char16_t>(key)).isLetter();
    if (!letter && modifiers == Qt::ShiftModifier)
        pressed.emplace_back(key);
    for (const QKeySequence& sequence : pressed)
        for (QAction* action : m_keyActions)
            if (action->isEnabled() && action->shortcuts().contains(sequence)) {
                action->trigger();
                event->accept();
                return;
            }
    QGraphicsView::keyPressEvent(event);
}

void LadderView::mousePressEvent(QMouseEvent* event) {
    setFocus(Qt::MouseFocusReason);
    m_pressAt = event->position().toPoint();
    m_mayDrag = event->button() == Qt::LeftButton;
    emit pressed(mapToScene(m_pressAt), event->button(), event->modifiers());
    event->accept();
}

void LadderView::mouseMoveEvent(QMouseEvent* event) {
    if (m_mayDrag && (event->buttons() & Qt::LeftButton) &&
        (event->position().toPoint() - m_pressAt).manhattanLength() >=
            QApplication::startDragDistance()) {
        m_mayDrag = false;
        emit dragStarted(mapToScene(m_pressAt));
    }
    event->accept();
}

void LadderView::mouseReleaseEvent(QMouseEvent* event) {
    m_mayDrag = false;
    event->accept();
}

void LadderView::mouseDoubleClickEvent(QMouseEvent* event) {
    emit doubleClicked(mapToScene(event->position().toPoint()));
    event->accept();
}

void LadderView::contextMenuEvent(QContextMenuEvent* event) {
    emit menuRequested(mapToScene(event->pos()), event->globalPos());
    event->accept();
}

namespace {

// The manual's drag and drop copies (11.5); Shift moves.
bool movesElement(const QDropEvent& event) {
    return event.modifiers() & Qt::ShiftModifier;
}

} // namespace

void LadderView::dragEnterEvent(QDragEnterEvent* event) {
    dragMoveEvent(event);
}

void LadderView::dragMoveEvent(QDragMoveEvent* event) {
    if (!event->mimeData()->hasFormat(QLatin1String(kElementMimeType))) {
        event->ignore();
        return;
    }
    const bool move = movesElement(*event);
    event->setDropAction(move ? Qt::MoveAction : Qt::CopyAction);
    event->accept();
    emit dragHovered(mapToScene(event->position().toPoint()),
                     event->mimeData()->data(QLatin1String(kElementMimeType)), move);
}

void LadderView::dragLeaveEvent(QDragLeaveEvent* event) {
    QGraphicsView::dragLeaveEvent(event);
    emit dragLeft();
}

void LadderView::dropEvent(QDropEvent* event) {
    if (!event->mimeData()->hasFormat(QLatin1String(kElementMimeType)))
        return;
    const bool move = movesElement(*event);
    event->setDropAction(move ? Qt::MoveAction : Qt::CopyAction);
    event->accept();
    emit dragLeft();
    emit dropped(mapToScene(event->position().toPoint()),
                 event->mimeData()->data(QLatin1String(kElementMimeType)), move);
}

} // namespace rs::ui
