// SPDX-License-Identifier: GPL-3.0-or-later
#include "gateway/GatewayData.h"
#include "DiagnosticsText.h"
#include "compiler/Compiler.h"

#include <gtest/gtest.h>

using namespace rs;
using rs::test::addressOf;

namespace {

sim::Simulation simulate(const std::string& text) {
    const auto compiled = compiler::compileText(text);
    EXPECT_EQ(compiled.errors(), 0);
    return sim::Simulation(compiled.images);
}

} // namespace

// Manual 4.2, "A20 and Double family", read as ../shared/spec/gateway.md says.
TEST(GatewayData, AnA20sGlobalDataInTheFamilyLayout) {
    sim::Simulation simulation = simulate("! id_pluto:02=000000000002\n"
                                          "! type_pluto:02=A20,is3\n"
                                          "! pgm_pluto:02\n"
                                          "S2.0_0\n"
                                          "Q2.1 = I2.0\n"
                                          "GM2.0 = I2.17\n"
                                          "GM2.11 = I2.17\n");
    EXPECT_EQ(gateway::globalData(simulation, 2), 0u);
    simulation.set(addressOf("I2.0"), 1);
    simulation.set(addressOf("I2.17"), 1);
    simulation.scan();
    // I2.0 bit 0, I2.17 bit 15, Q2.1 bit 17, GM2.0 bit 20, GM2.11 bit 31.
    EXPECT_EQ(gateway::globalData(simulation, 2),
              (1u << 0) | (1u << 15) | (1u << 17) | (1u << 20) | (1u << 31));
    // Register 3 + 2n holds the most significant word: Q and GM.
    EXPECT_EQ(gateway::globalData(simulation, 2) >> 16, 0x8012u);
}

TEST(GatewayData, NodeStatusFollowsTheBus) {
    sim::Simulation simulation = simulate("! id_pluto:00=000000000000\n"
                                          "! id_pluto:17=000000000011\n"
                                          "! pgm_pluto:00\n"
                                          "S0.0_0\n"
                                          "! pgm_pluto:17\n"
                                          "S17.0_0\n");
    EXPECT_EQ(gateway::nodeStatus(simulation), (1u << 0) | (1u << 17));
    simulation.setOnBus(17, false);
    EXPECT_EQ(gateway::nodeStatus(simulation), 1u);
}

TEST(GatewayData, TheOtherFamiliesLayouts) {
    sim::UnitMemory m;
    m.inputs[0] = 1;
    m.inputs[3] = 1;
    m.inputs[10] = 1;
    m.outputs[2] = 1;
    m.globalMemories[4] = 1;
    m.globalMemories[27] = 1;
    m.asiSafeInputs[1] = 1;
    m.asiSafeInputs[15] = 1;
    m.analogInputs[1] = 7000;
    using target::UnitType;
    // AS-i: I.0, then the safety slaves 1-15, then Q and GM as the A20.
    EXPECT_EQ(gateway::globalData(UnitType::ASi, m),
              (1u << 0) | (1u << 1) | (1u << 15) | (1u << 18) | (1u << 24));
    // B42 AS-i: I.0-I.3, then GM0-GM27; no safety outputs.
    EXPECT_EQ(gateway::globalData(UnitType::B42ASi, m),
              (1u << 0) | (1u << 3) | (1u << 8) | (1u << 31));
    // D20: IA0-IA3 where I0-I3 stand, read as bits.
    EXPECT_EQ(gateway::globalData(UnitType::D20, m),
              (1u << 1) | (1u << 8) | (1u << 18) | (1u << 24));
    // B22: the same as the A20 without the safety outputs.
    EXPECT_EQ(gateway::globalData(UnitType::B22, m),
              (1u << 0) | (1u << 3) | (1u << 8) | (1u << 24));
    EXPECT_EQ(gateway::globalData(UnitType::A20, m),
              (1u << 0) | (1u << 3) | (1u << 8) | (1u << 18) | (1u << 24));
}
