// SPDX-License-Identifier: GPL-3.0-or-later
#include "WaveformView.h"

#include "shell/StatusColors.h"
#include "sim/WaveformRecorder.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QScrollBar>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace rs::ui {

namespace {

constexpr double kMinMsPerPixel = 0.05;
constexpr double kMaxMsPerPixel = 60000.0;
constexpr double kZoomStep = 1.5;
constexpr int kMinTickSpacing = 80; // pixels between labelled ticks

QColor bitColor(const QPalette& palette) {
    return isDark(palette) ? QColor(80, 220, 80) : QColor(0, 140, 0);
}

QString timeLabel(std::int64_t ms, std::int64_t step) {
    if (step >= 1000 && ms % 1000 == 0)
        return QStringLiteral("%1 s").arg(ms / 1000);
    if (step >= 100)
        return QStringLiteral("%1 s").arg(static_cast<double>(ms) / 1000.0, 0, 'f', 1);
    return QStringLiteral("%1 ms").arg(ms);
}

// A round tick step (1, 2, 5 x 10^n ms) at least `minimum` ms long.
std::int64_t tickStep(double minimum) {
    std::int64_t step = 1;
    while (true) {
        for (int factor : {1, 2, 5})
            if (static_cast<double>(step * factor) >= minimum)
                return step * factor;
        step *= 10;
    }
}

} // namespace

WaveformView::WaveformView(const sim::WaveformRecorder* recorder, QWidget* parent)
    : QAbstractScrollArea(parent), m_recorder(recorder) {
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
    return m_recorder->startMs() +
           static_cast<std::int64_t>(horizontalScrollBar()->value() * m_msPerPixel);
}

double WaveformView::xOf(std::int64_t timeMs) const {
    return kNameWidth + static_cast<double>(timeMs - firstVisibleMs()) / m_msPerPixel;
}

void WaveformView::updateScrollBars() {
    const double span = static_cast<double>(m_recorder->endMs() - m_recorder->startMs());
    const int total = static_cast<int>(std::ceil(span / m_msPerPixel));
    QScrollBar* horizontal = horizontalScrollBar();
    horizontal->setRange(0, std::max(total - plotWidth() + 20, 0));
    horizontal->setPageStep(plotWidth());
    horizontal->setSingleStep(20);
    const int rows = static_cast<int>(m_recorder->traces().size());
    const int visibleRows = std::max((viewport()->height() - kRulerHeight) / kRowHeight, 1);
    verticalScrollBar()->setRange(0, std::max(rows - visibleRows, 0));
    verticalScrollBar()->setPageStep(visibleRows);
    if (m_follow)
        horizontal->setValue(horizontal->maximum());
}

void WaveformView::setNames(std::function<QString(const lang::Address&)> names) {
    m_names = std::move(names);
    viewport()->update();
}

void WaveformView::recordingChanged() {
    if (m_selected >= static_cast<int>(m_recorder->traces().size()))
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
    const double span = static_cast<double>(m_recorder->endMs() - m_recorder->startMs());
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
            (anchor - static_cast<double>(m_recorder->startMs())) / m_msPerPixel - x));
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
    m_selected = row < static_cast<int>(m_recorder->traces().size()) ? row : -1;
    emit selectionChanged(m_selected);
    viewport()->update();
}

void WaveformView::paintRuler(QPainter& painter, int width) {
    const QPalette& pal = palette();
    painter.fillRect(QRect(0, 0, width, kRulerHeight), pal.color(QPalette::Window));
    painter.setPen(pal.color(QPalette::Mid));
    painter.drawLine(0, kRulerHeight - 1, width, kRulerHeight - 1);
    const std::int64_t step = tickStep(kMinTickSpacing * m_msPerPixel);
    const std::int64_t first = firstVisibleMs();
    const std::int64_t last = first + static_cast<std::int64_t>(plotWidth() * m_msPerPixel);
    for (std::int64_t t = (first / step) * step; t <= last; t += step) {
        const double x = xOf(t);
        if (x < kNameWidth)
            continue;
        painter.setPen(pal.color(QPalette::Mid));
        painter.drawLine(QPointF(x, kRulerHeight - 6), QPointF(x, viewport()->height()));
        painter.setPen(pal.color(QPalette::WindowText));
        painter.drawText(QPointF(x + 3, kRulerHeight - 7), timeLabel(t, step));
    }
}

void WaveformView::paintEvent(QPaintEvent*) {
    QPainter painter(viewport());
    const QPalette& pal = palette();
    const int width = viewport()->width();
    paintRuler(painter, width);
    const auto& traces = m_recorder->traces();
    const QColor bits = bitColor(pal);
    const std::int64_t first = firstVisibleMs();
    const std::int64_t end = m_recorder->endMs();
    const double right = std::min<double>(xOf(end), width);
    int y = kRulerHeight;
    for (int row = verticalScrollBar()->value();
         row < static_cast<int>(traces.size()) && y < viewport()->height(); ++row) {
        const sim::WaveformRecorder::Trace& trace = traces[static_cast<std::size_t>(row)];
        const QRect nameRect(0, y, kNameWidth, kRowHeight);
        painter.fillRect(nameRect, row == m_selected ? pal.color(QPalette::Highlight)
                                                     : pal.color(QPalette::Window));
        painter.setPen(row == m_selected ? pal.color(QPalette::HighlightedText)
                                         : pal.color(QPalette::WindowText));
        const QString name = m_names ? m_names(trace.address) : QString();
        const QString label = QString::fromStdString(lang::toString(trace.address)) +
                              (name.isEmpty() ? QString() : QStringLiteral("  ") + name);
        const QRect textRect = nameRect.adjusted(6, 0, -4, 0);
        painter.drawText(textRect, Qt::AlignVCenter | Qt::AlignLeft,
                         painter.fontMetrics().elidedText(label, Qt::ElideRight, textRect.width()));
        painter.setPen(pal.color(QPalette::Midlight));
        painter.drawLine(0, y + kRowHeight - 1, width, y + kRowHeight - 1);

        // The change in effect at the left edge, then every change up to the right edge.
        const auto& changes = trace.changes;
        auto it = std::upper_bound(
            changes.begin(), changes.end(), first,
            [](std::int64_t t, const sim::WaveformRecorder::Change& c) { return t < c.timeMs; });
        if (it != changes.begin())
            --it;
        const double high = y + 5;
        const double low = y + kRowHeight - 6;
        painter.save();
        painter.setClipRect(QRect(kNameWidth, y, width - kNameWidth, kRowHeight));
        if (trace.address.isBit() && trace.address.kind != lang::AddressKind::AnalogInput) {
            QPainterPath path;
            bool started = false;
            for (; it != changes.end(); ++it) {
                const double x = std::max(xOf(it->timeMs), double(kNameWidth) - 1);
                if (x > width)
                    break;
                const double level = it->value ? high : low;
                if (!started) {
                    path.moveTo(x, level);
                    started = true;
                } else {
                    path.lineTo(x, path.currentPosition().y());
                    path.lineTo(x, level);
                }
            }
            if (started)
                path.lineTo(right, path.currentPosition().y());
            painter.setPen(QPen(bits, 2));
            painter.drawPath(path);
        } else {
            painter.setPen(QPen(pal.color(QPalette::Text), 1));
            for (; it != changes.end(); ++it) {
                const double x0 = std::max(xOf(it->timeMs), double(kNameWidth) - 4);
                if (x0 > width)
                    break;
                const auto next = std::next(it);
                const double x1 = next == changes.end() ? right : xOf(next->timeMs);
                const double slope = std::min(3.0, (x1 - x0) / 2);
                const double middle = (high + low) / 2;
                QPainterPath band;
                band.moveTo(x0, middle);
                band.lineTo(x0 + slope, high);
                band.lineTo(x1 - slope, high);
                band.lineTo(x1, middle);
                band.lineTo(x1 - slope, low);
                band.lineTo(x0 + slope, low);
                band.closeSubpath();
                painter.drawPath(band);
                const QString text = QString::number(it->value);
                const QRectF textRect(x0 + slope, high, x1 - x0 - 2 * slope, low - high);
                if (painter.fontMetrics().horizontalAdvance(text) < textRect.width())
                    painter.drawText(textRect, Qt::AlignCenter, text);
            }
        }
        painter.restore();
        y += kRowHeight;
    }
    if (traces.empty()) {
        painter.setPen(pal.color(QPalette::PlaceholderText));
        painter.drawText(QRect(kNameWidth, kRulerHeight, width - kNameWidth,
                               viewport()->height() - kRulerHeight),
                         Qt::AlignCenter,
                         tr("Add variables to plot them over the simulation's time."));
    }
}

} // namespace rs::ui
