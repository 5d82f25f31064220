// SPDX-License-Identifier: GPL-3.0-or-later
// The system instructions as the simulator runs them from the image
// (docs/image-format.md, "System instructions").
#include "SimulationFixture.h"

#include <gtest/gtest.h>

#include <string>

using rs::test::Simulated;
using namespace rs;

namespace {

// Unit 0 exports R0.5 (42) and DR0.10 (100000); unit 1 checks them.
std::string exported(const std::string& unitOneCode) {
    return "! id_pluto:00=000000000000\n"
           ";@var R0.5 export=\"yes\"\n"
           ";@var DR0.10 export=\"yes\"\n"
           "! type_pluto:00=A20,is3\n"
           "! id_pluto:01=000000000001\n"
           "! type_pluto:01=A20,is3\n"
           "! pgm_pluto:00\n"
           "S0.0_0\n"
           "(R0.5 = 42)\n"
           "(DR0.10 = 100000)\n"
           "! pgm_pluto:01\n"
           "S1.0_0\n" +
           unitOneCode;
}

const std::string kBoth = ";@system RegisterValid Input=\"R0.5\" Valid=\"M1.1\" Value=\"R1.6\"\n"
                          ";@system DRegisterValid Input=\"DR0.10\" Valid=\"M1.2\" "
                          "Value=\"DR1.20\"\n";

std::vector<compiler::UnitImage> images(const std::string& text) {
    compiler::CompileResult result =
        compiler::compileText(text, {.warnUnconfiguredIo = false, .onlyUnit = {}});
    EXPECT_EQ(result.errors(), 0);
    return result.images;
}

} // namespace

TEST(SystemCall, AnExportedRegisterIsValidWhileItsUnitIsOnTheBus) {
    Simulated s(exported(kBoth));
    s.scans(1); // unit 0 writes its registers; unit 1 reads them from the bus a scan later
    EXPECT_EQ(s["M1.1"], 1);
    EXPECT_EQ(s["R1.6"], 0);
    s.scans(1);
    EXPECT_EQ(s["M1.1"], 1);
    EXPECT_EQ(s["R1.6"], 42);
    EXPECT_EQ(s["M1.2"], 1);
    EXPECT_EQ(s["DR1.20"], 100000);
}

TEST(SystemCall, WithoutTheExportingUnitOnTheBusNothingIsValidAndTheValueIs0) {
    auto all = images(exported(kBoth));
    ASSERT_EQ(all.size(), 2u);
    // What unit 0 would publish, were it there.
    auto bus = std::make_unique<sim::UnitEngine::Bus>();
    (*bus)[0].registers[5] = 42;
    (*bus)[0].registers[10] = 1;
    sim::UnitEngine unit(all[1], *bus); // on a bus of its own, until told otherwise
    unit.scan(0, 10);
    EXPECT_EQ(unit.read(Simulated::at("M1.1")), 0);
    EXPECT_EQ(unit.read(Simulated::at("R1.6")), 0);
    EXPECT_EQ(unit.read(Simulated::at("M1.2")), 0);
    EXPECT_EQ(unit.read(Simulated::at("DR1.20")), 0);
    std::array<bool, 32> present{};
    present[0] = true;
    unit.setPresent(present);
    unit.scan(10, 10);
    EXPECT_EQ(unit.read(Simulated::at("M1.1")), 1);
    EXPECT_EQ(unit.read(Simulated::at("R1.6")), 42);
    EXPECT_EQ(unit.read(Simulated::at("M1.2")), 1);
    EXPECT_EQ(unit.read(Simulated::at("DR1.20")), 1);

    // A simulation of unit 1 alone: unit 0 is not on the bus.
    sim::Simulation alone({all[1]});
    alone.run(50);
    EXPECT_EQ(alone.value(Simulated::at("SM1.100")), 0);
    EXPECT_EQ(alone.value(Simulated::at("M1.1")), 0);
    EXPECT_EQ(alone.value(Simulated::at("R1.6")), 0);
}

TEST(SystemCall, ItsBitOutputsGoOffWhenItsStepIsLeftAsCoilsDo) {
    Simulated s(exported("M1.0 = I1.0\n"
                         "S1.1_0\n"
                         "J(1) = I1.1\n"
                         "S1.1_1\n"
                         ";@system RegisterValid Input=\"R0.5\" Valid=\"M1.1\" Value=\"R1.6\"\n"
                         "J(0) = I1.2\n"));
    s.set("I1.1", 1);
    s.scans(3);
    EXPECT_EQ(s["S1.1"], 1);
    EXPECT_EQ(s["M1.1"], 1);
    EXPECT_EQ(s["R1.6"], 42);
    s.set("I1.1", 0);
    s.set("I1.2", 1);
    s.scans(1);
    EXPECT_EQ(s["S1.1"], 0);
    EXPECT_EQ(s["M1.1"], 0);
    EXPECT_EQ(s["R1.6"], 42) << "a number keeps its value, as arithmetic's does";
}

TEST(SystemCall, AForcedOutputKeepsItsForcedValue) {
    Simulated s(exported(kBoth));
    s.set("M1.1", 0);
    s.set("R1.6", -5);
    s.scans(3);
    EXPECT_EQ(s["M1.1"], 0);
    EXPECT_EQ(s["R1.6"], -5);
    s.simulation->release(Simulated::at("R1.6"));
    s.scans(1);
    EXPECT_EQ(s["R1.6"], 42);
}

TEST(SystemCall, ConductionMarksTheCallRunWithPower) {
    Simulated s(exported(kBoth));
    s.scans(1);
    const sim::UnitEngine* unit = s.simulation->unit(1);
    const auto& code = unit->image().code;
    const auto& conduction = unit->conduction();
    ASSERT_EQ(code.size(), 8u);
    for (std::size_t i = 0; i < code.size(); ++i)
        EXPECT_EQ(conduction[i], sim::Conduction::On) << i;
}
