// SPDX-License-Identifier: GPL-3.0-or-later
#include "gateway/ModbusMap.h"
#include "compiler/Compiler.h"
#include "gateway/ModbusFrame.h"

#include <gtest/gtest.h>

using namespace rs;
using gateway::ModbusException;

namespace {

sim::Simulation plant() {
    const auto compiled = compiler::compileText("! id_pluto:00=000000000000\n"
                                                "! id_pluto:01=000000000001\n"
                                                "! type_pluto:00=A20,is3\n"
                                                "! type_pluto:01=A20,is3\n"
                                                "! pgm_pluto:00\n"
                                                "S0.0_0\n"
                                                "GM0.0 = I0.0\n"
                                                "! pgm_pluto:01\n"
                                                "S1.0_0\n");
    EXPECT_EQ(compiled.errors(), 0);
    return sim::Simulation(compiled.images);
}

gateway::ModbusResponse read(const sim::Simulation& simulation, int unit, int address, int count,
                             int function = 3) {
    gateway::DataToPluto toPluto = gateway::kNoDataToPluto;
    return gateway::answer({unit, function, address, count, {}}, gateway::dataFromPluto(simulation),
                           toPluto);
}

} // namespace

// Appendix D: "a request with start 1 and end 66 will give node status and
// Pluto global data".
TEST(ModbusMap, UnitThirtyThreeHoldsNodeStatusAndGlobalDataMostSignificantWordFirst) {
    sim::Simulation simulation = plant();
    simulation.set(lang::readAddressWord("I0.0").address, 1);
    simulation.scan();
    const auto response = read(simulation, 33, 1, 66);
    ASSERT_EQ(response.exception, ModbusException::None);
    ASSERT_EQ(response.registers.size(), 66u);
    EXPECT_EQ(response.registers[0], 0x0000); // Node Status MSW: Plutos 16-31
    EXPECT_EQ(response.registers[1], 0x0003); // LSW: Plutos 0 and 1
    EXPECT_EQ(response.registers[2], 0x0010); // Pluto 0 MSW: GM0.0 is bit 20
    EXPECT_EQ(response.registers[3], 0x0001); // Pluto 0 LSW: I0.0 is bit 0
    EXPECT_EQ(read(simulation, 33, 4, 1).registers, std::vector<std::uint16_t>{0x0001});
    // Additional data: start 67, end 130.
    EXPECT_EQ(read(simulation, 33, 67, 64).registers.size(), 64u);
}

TEST(ModbusMap, WhatTheManualDoesNotAllowIsAStandardException) {
    const sim::Simulation simulation = plant();
    EXPECT_EQ(read(simulation, 33, 1, 101).exception, ModbusException::IllegalDataValue);
    EXPECT_EQ(read(simulation, 33, 1, 0).exception, ModbusException::IllegalDataValue);
    EXPECT_EQ(read(simulation, 33, 0, 2).exception, ModbusException::IllegalDataAddress);
    EXPECT_EQ(read(simulation, 33, 100, 32).exception, ModbusException::IllegalDataAddress);
    EXPECT_EQ(read(simulation, 33, 129, 2).exception, ModbusException::None);
    EXPECT_EQ(read(simulation, 33, 1, 2, 4).exception, ModbusException::IllegalFunction);
    gateway::DataToPluto toPluto = gateway::kNoDataToPluto;
    EXPECT_EQ(gateway::answer({33, 16, 1, 2, {1, 2}}, gateway::dataFromPluto(simulation), toPluto)
                  .exception,
              ModbusException::IllegalFunction); // unit 33 is read only
    EXPECT_EQ(read(simulation, 5, 0, 1).exception, ModbusException::GatewayTargetFailed);
}

TEST(ModbusFrame, AWholeFrameIsReadAndAnythingElseRefused) {
    // Transaction 1, protocol 0, length 6, unit 33, read holding registers 1..66.
    const std::uint8_t read[] = {0, 1, 0, 0, 0, 6, 33, 3, 0, 1, 0, 66};
    const auto request = gateway::readModbusFrame(read, sizeof read);
    ASSERT_TRUE(request);
    EXPECT_EQ(request->unit, 33);
    EXPECT_EQ(request->function, 3);
    EXPECT_EQ(request->address, 1);
    EXPECT_EQ(request->count, 66);
    EXPECT_FALSE(gateway::readModbusFrame(read, sizeof read - 1)); // the length field disagrees
    EXPECT_FALSE(gateway::readModbusFrame(read, 7));               // no function code
    const std::uint8_t write[] = {0, 3, 0, 0, 0, 11, 1, 16, 0, 0, 0, 2, 4, 0, 13, 0, 3};
    const auto written = gateway::readModbusFrame(write, sizeof write);
    ASSERT_TRUE(written);
    EXPECT_EQ(written->values, (std::vector<std::uint16_t>{13, 3}));
}

// Appendix D, unit 1: one table for every client, read and written.
TEST(ModbusMap, DataToPlutoIsWrittenAndReadBackWithItsLengthKept) {
    const gateway::DataFromPluto none{};
    gateway::DataToPluto toPluto = gateway::kNoDataToPluto;
    // Length 13, areas 0 and 1 valid, area 0's bits 0x00FF, registers 100 and 200.
    EXPECT_EQ(
        gateway::answer({1, 16, 0, 5, {13, 0x0003, 0x00FF, 100, 200}}, none, toPluto).exception,
        ModbusException::None);
    const auto back = gateway::answer({1, 3, 0, 5, {}}, none, toPluto);
    EXPECT_EQ(back.registers, (std::vector<std::uint16_t>{13, 3, 0x00FF, 100, 200}));
    // Area 3's register 1 is the last word.
    EXPECT_EQ(gateway::answer({1, 16, 12, 2, {7, 8}}, none, toPluto).exception,
              ModbusException::None);
    EXPECT_EQ(toPluto[13], 8);
    EXPECT_EQ(gateway::answer({1, 16, 13, 2, {7, 8}}, none, toPluto).exception,
              ModbusException::IllegalDataAddress);
    EXPECT_EQ(gateway::answer({1, 16, 0, 2, {12, 1}}, none, toPluto).exception,
              ModbusException::IllegalDataValue); // the length cannot change
    EXPECT_EQ(gateway::answer({1, 16, 1, 2, {1}}, none, toPluto).exception,
              ModbusException::IllegalDataValue); // fewer values than registers
    EXPECT_EQ(gateway::answer({1, 6, 1, 1, {}}, none, toPluto).exception,
              ModbusException::IllegalFunction);
    EXPECT_EQ(toPluto[1], 3); // nothing refused was taken
}
