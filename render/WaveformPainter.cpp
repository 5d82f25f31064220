// SPDX-License-Identifier: GPL-3.0-or-later
#include "WaveformPainter.h"

#include "sim/Waveform.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>

namespace rs::render {

namespace {

constexpr int kMinTickSpacing = 80; // pixels between labelled ticks

bool isDark(const QPalette& palette) {
    return palette.color(QPalette::Window).lightness() < 128;
}

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

} // namespace

WaveformPainter::WaveformPainter(const sim::Waveform& waveform, const QPalette& palette)
    : m_waveform(waveform), m_palette(palette) {}

void WaveformPainter::setLabels(std::function<QString(int row)> labels) {
    m_labels = std::move(labels);
}

void WaveformPainter::setValueText(std::function<QString(int row, std::int64_t value)> valueText) {
    m_valueText = std::move(valueText);
}

std::int64_t WaveformPainter::tickStep(double minimumMs) {
    std::int64_t step = 1;
    while (true) {
        for (int factor : {1, 2, 5})
            if (static_cast<double>(step * factor) >= minimumMs)
                return step * factor;
        step *= 10;
    }
}

void WaveformPainter::paintRuler(QPainter& painter, int width, int height, const View& view) const {
    painter.fillRect(QRect(0, 0, width, kRulerHeight), m_palette.color(QPalette::Window));
    painter.setPen(m_palette.color(QPalette::Mid));
    painter.drawLine(0, kRulerHeight - 1, width, kRulerHeight - 1);
    const std::int64_t step = tickStep(kMinTickSpacing * view.msPerPixel);
    const std::int64_t last =
        view.firstMs + static_cast<std::int64_t>((width - kNameWidth) * view.msPerPixel);
    for (std::int64_t t = (view.firstMs / step) * step; t <= last; t += step) {
        const double x = kNameWidth + static_cast<double>(t - view.firstMs) / view.msPerPixel;
        if (x < kNameWidth)
            continue;
        painter.setPen(m_palette.color(QPalette::Mid));
        painter.drawLine(QPointF(x, kRulerHeight - 6), QPointF(x, height));
        painter.setPen(m_palette.color(QPalette::WindowText));
        painter.drawText(QPointF(x + 3, kRulerHeight - 7), timeLabel(t, step));
    }
}

int WaveformPainter::paint(QPainter& painter, int width, int height, const View& view) const {
    paintRuler(painter, width, height, view);
    const QColor bits = bitColor(m_palette);
    auto xOf = [&](std::int64_t timeMs) {
        return kNameWidth + static_cast<double>(timeMs - view.firstMs) / view.msPerPixel;
    };
    const double right = std::min<double>(xOf(m_waveform.endMs()), width);
    int y = kRulerHeight;
    int drawn = 0;
    for (int row = view.firstRow; row < static_cast<int>(m_waveform.rows()) && y < height; ++row) {
        const auto index = static_cast<std::size_t>(row);
        const bool selected = row == view.selectedRow;
        const QRect nameRect(0, y, kNameWidth, kRowHeight);
        painter.fillRect(nameRect, selected ? m_palette.color(QPalette::Highlight)
                                            : m_palette.color(QPalette::Window));
        painter.setPen(selected ? m_palette.color(QPalette::HighlightedText)
                                : m_palette.color(QPalette::WindowText));
        const QString label =
            m_labels ? m_labels(row) : QString::fromStdString(m_waveform.label(index));
        const QRect textRect = nameRect.adjusted(6, 0, -4, 0);
        painter.drawText(textRect, Qt::AlignVCenter | Qt::AlignLeft,
                         painter.fontMetrics().elidedText(label, Qt::ElideRight, textRect.width()));
        painter.setPen(m_palette.color(QPalette::Midlight));
        painter.drawLine(0, y + kRowHeight - 1, width, y + kRowHeight - 1);

        // The change in effect at the left edge, then every change up to the right edge.
        const auto& changes = m_waveform.changes(index);
        auto it = std::upper_bound(
            changes.begin(), changes.end(), view.firstMs,
            [](std::int64_t t, const sim::WaveformChange& c) { return t < c.timeMs; });
        if (it != changes.begin())
            --it;
        const double high = y + 5;
        const double low = y + kRowHeight - 6;
        painter.save();
        painter.setClipRect(QRect(kNameWidth, y, width - kNameWidth, kRowHeight));
        if (m_waveform.isBit(index)) {
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
            painter.setPen(QPen(m_palette.color(QPalette::Text), 1));
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
                const QString text =
                    m_valueText ? m_valueText(row, it->value) : QString::number(it->value);
                const QRectF textRect(x0 + slope, high, x1 - x0 - 2 * slope, low - high);
                if (painter.fontMetrics().horizontalAdvance(text) < textRect.width())
                    painter.drawText(textRect, Qt::AlignCenter, text);
            }
        }
        painter.restore();
        y += kRowHeight;
        ++drawn;
    }
    return drawn;
}

QImage waveformImage(const sim::Waveform& waveform, const std::vector<QString>& labels, int width,
                     const QPalette& palette, qreal devicePixelRatio,
                     std::function<QString(int row, std::int64_t value)> valueText) {
    const int rows = static_cast<int>(waveform.rows());
    const int height = WaveformPainter::kRulerHeight + rows * WaveformPainter::kRowHeight;
    QImage image(QSize(width, height) * devicePixelRatio, QImage::Format_ARGB32_Premultiplied);
    image.setDevicePixelRatio(devicePixelRatio);
    image.fill(palette.color(QPalette::Base));
    // A margin on the right, so the last change is not drawn on the edge.
    const int plot = std::max(width - WaveformPainter::kNameWidth - 12, 1);
    const double span =
        static_cast<double>(std::max<std::int64_t>(waveform.endMs() - waveform.startMs(), 1));
    WaveformPainter painter(waveform, palette);
    painter.setLabels([&labels](int row) {
        return row < static_cast<int>(labels.size()) ? labels[static_cast<std::size_t>(row)]
                                                     : QString();
    });
    painter.setValueText(std::move(valueText));
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    painter.paint(p, width, height, {waveform.startMs(), span / plot, 0, -1});
    return image;
}

} // namespace rs::render
