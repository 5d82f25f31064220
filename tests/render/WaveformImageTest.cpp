// SPDX-License-Identifier: GPL-3.0-or-later
#include "WaveformPainter.h"

#include "compiler/Compiler.h"
#include "sim/Simulation.h"
#include "sim/WaveformRecorder.h"

#include <QGuiApplication>
#include <QPalette>

#include <gtest/gtest.h>

using namespace rs;

namespace {

// I0.0 comes on at 100 ms; Q0.2 follows it 200 ms later (TON).
sim::WaveformRecorder delayedOutput() {
    const auto compiled =
        compiler::compileText("! id_pluto:00=000000000000\n! pgm_pluto:00\n"
                              "! I0.0,a_pulse\nS0.0_0\nQ0.2 = I0.0 * TON(0s20)\n");
    EXPECT_EQ(compiled.errors(), 0);
    sim::Simulation simulation(compiled.images);
    sim::WaveformRecorder recorder;
    recorder.add(lang::readAddressWord("I0.0").address);
    recorder.add(lang::readAddressWord("Q0.2").address);
    recorder.sample(simulation);
    for (int scan = 0; scan < 50; ++scan) {
        if (simulation.timeMs() == 100)
            simulation.set(lang::readAddressWord("I0.0").address, 1);
        simulation.scan();
        recorder.sample(simulation);
    }
    return recorder;
}

// Whether the row's trace is at its high level at x: the bit colour there and
// not at the low level.
bool highAt(const QImage& image, int row, int x) {
    const int top =
        render::WaveformPainter::kRulerHeight + row * render::WaveformPainter::kRowHeight;
    const QRgb base = QGuiApplication::palette().color(QPalette::Base).rgb();
    auto inked = [&](int y) {
        for (int dy = -1; dy <= 1; ++dy)
            if (image.pixel(x, y + dy) != base)
                return true;
        return false;
    };
    const bool high = inked(top + 5);
    const bool low = inked(top + render::WaveformPainter::kRowHeight - 6);
    EXPECT_NE(high, low) << "row " << row << " at x " << x;
    return high;
}

} // namespace

TEST(WaveformImage, DrawsTheWholeRecordingOneRowPerTrace) {
    const sim::WaveformRecorder recorder = delayedOutput();
    const QImage image =
        render::waveformImage(recorder, {QStringLiteral("Start"), QStringLiteral("Lamp")}, 650,
                              QGuiApplication::palette());
    ASSERT_EQ(image.width(), 650);
    ASSERT_EQ(image.height(),
              render::WaveformPainter::kRulerHeight + 2 * render::WaveformPainter::kRowHeight);
    // 500 ms over 650 - 150 - 12 pixels.
    const double msPerPixel = 500.0 / (650 - render::WaveformPainter::kNameWidth - 12);
    auto x = [&](int ms) {
        return render::WaveformPainter::kNameWidth + static_cast<int>(ms / msPerPixel);
    };
    EXPECT_FALSE(highAt(image, 0, x(50)));
    EXPECT_TRUE(highAt(image, 0, x(150)));
    EXPECT_FALSE(highAt(image, 1, x(250)));
    EXPECT_TRUE(highAt(image, 1, x(350)));
    EXPECT_TRUE(highAt(image, 1, x(495)));
}

TEST(WaveformImage, HasTwiceThePixelsAtTwiceTheRatio) {
    const sim::WaveformRecorder recorder = delayedOutput();
    const QImage image = render::waveformImage(recorder, {}, 400, QGuiApplication::palette(), 2.0);
    EXPECT_EQ(image.width(), 800);
    EXPECT_EQ(image.deviceIndependentSize().width(), 400);
}
