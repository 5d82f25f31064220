// SPDX-License-Identifier: GPL-3.0-or-later
#include "WaveformView.h"

#include "WaveformPainter.h"
#include "sim/Waveform.h"

#include <QMouseEvent>
#include <QPainter>
#include <QScrollBar>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace rs::ui {

namespace {

constexpr double kMinMsPerPixel = 0.05;
constexpr double kMaxMsPerPixel = 60000.0;
constexpr double kZoomStep = 1.5;

} // namespace

WaveformView::WaveformView(const sim::Waveform* waveform, QWidget* parent)
    : QAbstractScrollArea(parent), m_waveform(waveform) {
    setObjectName(QStringLiteral("waveformView"));
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOn);
    viewport()->setBackgroundRole(QPalette::Base);
    viewport()->setAutoFillBackground(true);
    updateScrollBars();
}

QSize WaveformView::sizeHint() const {
    return {640, kRulerHeight + 6 * kRowHeight};
}

int WaveformView::plotWidth() const {
    return std::max(viewport()->width() - kNameWidth, 1);
}

std::int64_t WaveformView::firstVisibleMs() const {
    return m_waveform->startMs() +
           static_cast<std::int64_t>(horizontalScrollBar()->value() * m_msPerPixel);
}

void WaveformView::updateScrollBars() {
    const double span = static_cast<double>(m_waveform->endMs() - m_waveform->startMs());
    const int total = static_cast<int>(std::ceil(span / m_msPerPixel));
    QScrollBar* horizontal = horizontalScrollBar();
    horizontal->setRange(0, std::max(total - plotWidth() + 20, 0));
    horizontal->setPageStep(plotWidth());
    horizontal->setSingleStep(20);
    const int rows = static_cast<int>(m_waveform->rows());
    const int visibleRows = std::max((viewport()->height() - kRulerHeight) / kRowHeight, 1);
    verticalScrollBar()->setRange(0, std::max(rows - visibleRows, 0));
    verticalScrollBar()->setPageStep(visibleRows);
    if (m_follow)
        horizontal->setValue(horizontal->maximum());
}

void WaveformView::setLabels(std::function<QString(int row)> labels) {
    m_labels = std::move(labels);
    viewport()->update();
}

void WaveformView::recordingChanged() {
    if (m_selected >= static_cast<int>(m_waveform->rows()))
        m_selected = -1;
    updateScrollBars();
    viewport()->update();
}

void WaveformView::setMsPerPixel(double msPerPixel) {
    m_msPerPixel = std::clamp(msPerPixel, kMinMsPerPixel, kMaxMsPerPixel);
    updateScrollBars();
    viewport()->update();
}

void WaveformView::zoomIn() {
    m_fitted = false;
    setMsPerPixel(m_msPerPixel / kZoomStep);
}

void WaveformView::zoomOut() {
    m_fitted = false;
    setMsPerPixel(m_msPerPixel * kZoomStep);
}

void WaveformView::zoomToFit() {
    const double span = static_cast<double>(m_waveform->endMs() - m_waveform->startMs());
    m_follow = true;
    m_fitted = true;
    setMsPerPixel(std::max(span, 1.0) / std::max(plotWidth() - 20, 1));
}

void WaveformView::resizeEvent(QResizeEvent* event) {
    QAbstractScrollArea::resizeEvent(event);
    if (m_fitted)
        zoomToFit();
    else
        updateScrollBars();
}

void WaveformView::scrollContentsBy(int, int) {
    const QScrollBar* horizontal = horizontalScrollBar();
    m_follow = horizontal->value() >= horizontal->maximum();
    viewport()->update();
}

void WaveformView::wheelEvent(QWheelEvent* event) {
    if (event->modifiers() & Qt::ControlModifier) {
        // Zoom about the time under the pointer.
        const double x = event->position().x() - kNameWidth;
        const double anchor = static_cast<double>(firstVisibleMs()) + x * m_msPerPixel;
        if (event->angleDelta().y() > 0)
            zoomIn();
        else
            zoomOut();
        m_follow = false;
        horizontalScrollBar()->setValue(static_cast<int>(
            (anchor - static_cast<double>(m_waveform->startMs())) / m_msPerPixel - x));
        event->accept();
        return;
    }
    if (event->modifiers() & Qt::ShiftModifier) {
        horizontalScrollBar()->setValue(horizontalScrollBar()->value() - event->angleDelta().y());
        event->accept();
        return;
    }
    QAbstractScrollArea::wheelEvent(event);
}

void WaveformView::mousePressEvent(QMouseEvent* event) {
    const int y = static_cast<int>(event->position().y()) - kRulerHeight;
    const int row = y < 0 ? -1 : y / kRowHeight + verticalScrollBar()->value();
    m_selected = row < static_cast<int>(m_waveform->rows()) ? row : -1;
    emit selectionChanged(m_selected);
    viewport()->update();
}

void WaveformView::paintEvent(QPaintEvent*) {
    QPainter painter(viewport());
    const int width = viewport()->width();
    render::WaveformPainter waveform(*m_waveform, palette());
    if (m_labels)
        waveform.setLabels(m_labels);
    waveform.paint(painter, width, viewport()->height(),
                   {firstVisibleMs(), m_msPerPixel, verticalScrollBar()->value(), m_selected});
    if (m_waveform->rows() == 0) {
        painter.setPen(palette().color(QPalette::PlaceholderText));
        painter.drawText(QRect(kNameWidth, kRulerHeight, width - kNameWidth,
                               viewport()->height() - kRulerHeight),
                         Qt::AlignCenter,
                         tr("Add variables to plot them over the simulation's time."));
    }
}

} // namespace rs::ui
