#include "sim/WaveformRecorder.h"
#include "sim/WaveformView.h"

#include "compiler/Compiler.h"
#include "sim/Simulation.h"

#include <QImage>
#include <QScrollBar>

#include <gtest/gtest.h>

using namespace rs;

namespace {

lang::Address addressOf(const char* word) {
    return lang::readAddressWord(word).address;
}

// Q0.2 follows I0.0, which comes on at 50 ms; R0.1 counts the scans from then.
ui::WaveformRecorder record() {
    const auto compiled = compiler::compileText("! id_pluto:00=000000000000\n! pgm_pluto:00\n"
                                                "! I0.0,a_pulse\nS0.0_0\nQ0.2 = I0.0\n"
                                                "(R0.1 += 1) = I0.0\n");
    EXPECT_EQ(compiled.errors(), 0);
    sim::Simulation simulation(compiled.images);
    ui::WaveformRecorder recorder;
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

TEST(SimulationWaveform, RecordsChangesOnlyStampedWithTheNextScansTime) {
    const ui::WaveformRecorder recorder = record();
    EXPECT_EQ(recorder.startMs(), 0);
    EXPECT_EQ(recorder.endMs(), 100);
    const auto& q = recorder.traces()[0].changes;
    ASSERT_EQ(q.size(), 2u);
    EXPECT_EQ(q[1].timeMs, 60); // the scan at 50 ms sees I0.0 and ends at 60 ms
    EXPECT_EQ(q[1].value, 1);
    EXPECT_EQ(recorder.traces()[1].changes.back().value, 5);
}

TEST(SimulationWaveform, VcdHoldsEveryChange) {
    const std::string vcd = record().vcd("t");
    EXPECT_NE(vcd.find("$var wire 1 ! Q2 $end"), std::string::npos) << vcd;
    EXPECT_NE(vcd.find("$var integer 32 \" R1 $end"), std::string::npos);
    EXPECT_NE(vcd.find("#60\n1!\nb1 \"\n"), std::string::npos);
    EXPECT_NE(vcd.find("#100\nb101 \"\n"), std::string::npos);
}

TEST(SimulationWaveform, BitsAreDrawnLowThenHighAndNumbersAsBands) {
    const ui::WaveformRecorder recorder = record();
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
