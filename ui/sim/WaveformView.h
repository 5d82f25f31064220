// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "WaveformPainter.h"

#include <QAbstractScrollArea>

#include <cstdint>
#include <functional>

namespace rs::sim {
class Waveform;
}

namespace rs::ui {

// Draws what the recorder holds over virtual time: bits as 0/1 traces,
// numbers as bands with their value. Time runs left to right; the scroll bar
// moves along it, Ctrl+wheel or zoomIn()/zoomOut() change the scale, and the
// view follows the newest sample while it is scrolled to the end.
class WaveformView : public QAbstractScrollArea {
    Q_OBJECT
public:
    static constexpr int kNameWidth = render::WaveformPainter::kNameWidth;
    static constexpr int kRulerHeight = render::WaveformPainter::kRulerHeight;
    static constexpr int kRowHeight = render::WaveformPainter::kRowHeight;

    explicit WaveformView(const sim::Waveform* waveform, QWidget* parent = nullptr);

    // The label of each row; its address as the target writes it when not set.
    void setLabels(std::function<QString(int row)> labels);

    // The recording grew or changed: new extent, and the end shown when following.
    void recordingChanged();

    double msPerPixel() const { return m_msPerPixel; }
    void setMsPerPixel(double msPerPixel);
    void zoomIn();
    void zoomOut();
    void zoomToFit();
    // The time at the left edge of the plot.
    std::int64_t firstVisibleMs() const;
    // Which trace is chosen (for removal), -1 when none.
    int selectedRow() const { return m_selected; }

    QSize sizeHint() const override;

signals:
    void selectionChanged(int row);

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void scrollContentsBy(int dx, int dy) override;

private:
    void updateScrollBars();
    int plotWidth() const;

    const sim::Waveform* m_waveform;
    std::function<QString(int row)> m_labels;
    double m_msPerPixel = 1.0;
    bool m_follow = true;
    bool m_fitted = false; // zoomToFit() was the last zoom: a resize fits again
    int m_selected = -1;
};

} // namespace rs::ui
