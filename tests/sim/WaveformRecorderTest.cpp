// SPDX-License-Identifier: GPL-3.0-or-later
#include "sim/WaveformRecorder.h"

#include "compiler/Compiler.h"
#include "sim/Simulation.h"

#include <gtest/gtest.h>

using namespace rs;

namespace {

lang::Address addressOf(const char* word) {
    return lang::readAddressWord(word).address;
}

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

} // namespace

TEST(WaveformRecorder, RecordsChangesOnlyStampedWithTheNextScansTime) {
    const sim::WaveformRecorder recorder = record();
    EXPECT_EQ(recorder.startMs(), 0);
    EXPECT_EQ(recorder.endMs(), 100);
    const auto& q = recorder.traces()[0].changes;
    ASSERT_EQ(q.size(), 2u);
    EXPECT_EQ(q[1].timeMs, 60); // the scan at 50 ms sees I0.0 and ends at 60 ms
    EXPECT_EQ(q[1].value, 1);
    EXPECT_EQ(recorder.traces()[1].changes.back().value, 5);
}

TEST(WaveformRecorder, VcdHoldsEveryChange) {
    const std::string vcd = record().vcd("t");
    EXPECT_NE(vcd.find("$var wire 1 ! Q2 $end"), std::string::npos) << vcd;
    EXPECT_NE(vcd.find("$var integer 32 \" R1 $end"), std::string::npos);
    EXPECT_NE(vcd.find("#60\n1!\nb1 \"\n"), std::string::npos);
    EXPECT_NE(vcd.find("#100\nb101 \"\n"), std::string::npos);
}
