// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QImage>
#include <QPalette>
#include <QString>

#include <cstdint>
#include <functional>

class QPainter;

namespace rs::sim {
class Waveform;
}

// Draws what a waveform holds over virtual time, for any target: a time ruler on
// top, then a row per trace with its label on the left, bits as 0/1 traces
// and numbers as bands with their value. The simulator's waveform panel
// scrolls over it; a block's documentation page draws a whole recording as a
// picture.
namespace rs::render {

class WaveformPainter {
public:
    static constexpr int kNameWidth = 150;
    static constexpr int kRulerHeight = 22;
    static constexpr int kRowHeight = 28;

    // The part drawn: time from firstMs at msPerPixel, rows from firstRow.
    struct View {
        std::int64_t firstMs = 0;
        double msPerPixel = 1.0;
        int firstRow = 0;
        int selectedRow = -1; // drawn highlighted; -1 for none
    };

    WaveformPainter(const sim::Waveform& waveform, const QPalette& palette);

    // The label of each row; the address when not set.
    void setLabels(std::function<QString(int row)> labels);
    // How a number is written in its band; in decimal when not set.
    void setValueText(std::function<QString(int row, std::int64_t value)> valueText);

    // Fills `width` x `height` from (0, 0); returns the rows drawn.
    int paint(QPainter& painter, int width, int height, const View& view) const;

    // A round tick step (1, 2, 5 x 10^n ms) at least `minimumMs` long.
    static std::int64_t tickStep(double minimumMs);

private:
    void paintRuler(QPainter& painter, int width, int height, const View& view) const;

    const sim::Waveform& m_waveform;
    QPalette m_palette;
    std::function<QString(int row)> m_labels;
    std::function<QString(int row, std::int64_t value)> m_valueText;
};

// The whole recording, every row, `width` pixels wide (device independent),
// at the given pixel ratio: a picture for a page.
QImage waveformImage(const sim::Waveform& waveform, const std::vector<QString>& labels, int width,
                     const QPalette& palette, qreal devicePixelRatio = 1.0,
                     std::function<QString(int row, std::int64_t value)> valueText = {});

} // namespace rs::render
