// SPDX-License-Identifier: GPL-3.0-or-later
#include "DiagnosticsText.h"
#include "sim/WaveformView.h"

#include "compiler/Compiler.h"
#include "sim/Simulation.h"
#include "sim/WaveformRecorder.h"

#include <QImage>
#include <QScrollBar>

#include <gtest/gtest.h>

using namespace rs;
using rs::test::addressOf;

namespace {

// Q0.2 follows I0.0, which comes on at 50 ms; R0.1 counts the scans from then.
sim::WaveformRecorder record() {
    const auto compiled = compiler::compileText("! id_pluto:00=000000000000\n! pgm_pluto:00\n"
                                                "! I0.0,a_pulse\nS0.0_0\nQ0.2 = I0.0\n"
                                                "(R0.1 += 1) = I0.0\n");
    EXPECT_EQ(compiled.errors(), 0);
    sim::Simulation simulation(compiled.images);
    sim::WaveformRecorder recorder;
    recorder.add(addressOf("Q0.2"));
    recorder.add(addressOf("R0.1"));
    recorder.sample(simulation);
    for (int scan = 0; scan < 10; ++scan) {
        if (scan == 5)
            simulation.set(addressOf("I0.0"), 1);
        simulation.scan();
        recorder.sample(simulation);
    }
    return recorder;
}

// Whether anything is drawn within two pixels of the point, on the base colour.
bool inked(const QImage& image, int x, int y, QRgb base) {
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            if (image.pixel(x + dx, y + dy) != base)
                return true;
    return false;
}

} // namespace

TEST(SimulationWaveform, BitsAreDrawnLowThenHighAndNumbersAsBands) {
    const sim::WaveformRecorder recorder = record();
    ui::WaveformView view(&recorder);
    view.resize(ui::WaveformView::kNameWidth + 420, 200);
    view.zoomToFit();
    const QImage image = view.viewport()->grab().toImage();
    const QRgb base = image.pixel(image.width() - 30, image.height() - 10);
    const double msPerPixel = view.msPerPixel();
    auto x = [&](int ms) {
        return ui::WaveformView::kNameWidth + static_cast<int>(ms / msPerPixel);
    };
    const int top = ui::WaveformView::kRulerHeight;
    const int high = top + 5;
    const int low = top + ui::WaveformView::kRowHeight - 6;
    EXPECT_TRUE(inked(image, x(30), low, base));
    EXPECT_FALSE(inked(image, x(30), high, base));
    EXPECT_TRUE(inked(image, x(85), high, base));
    EXPECT_FALSE(inked(image, x(85), low, base));
    // R0.1: a band per value from 60 ms, its edges at the top and the bottom of the row.
    const int bandTop = top + ui::WaveformView::kRowHeight + 5;
    const int bandBottom = top + 2 * ui::WaveformView::kRowHeight - 6;
    EXPECT_TRUE(inked(image, x(75), bandTop, base));
    EXPECT_TRUE(inked(image, x(75), bandBottom, base));
}
