// SPDX-License-Identifier: GPL-3.0-or-later
// A gateway on the simulated bus (Gateway manual 4.3-4.5, Appendix D;
// docs/gateway.md): the ToGateway telegrams in the additional data areas,
// Data to Pluto in the units' External Comm Blocks, the configuration and
// local data units of the Modbus map.
#include "gateway/GatewayNode.h"
#include "DiagnosticsText.h"
#include "compiler/Compiler.h"
#include "project/ProjectFile.h"

#include <gtest/gtest.h>

using namespace rs;
using rs::test::addressOf;
using rs::test::diagnosticsText;

namespace {

compiler::CompileResult compiled(const std::string& text) {
    const auto read = project::readProject(text);
    EXPECT_TRUE(read.ok()) << diagnosticsText(read.diagnostics);
    return compiler::compile(read.project);
}

// Gateway 0 (a GATE-E1) and Pluto 1, an A20 with `code` and `records`.
struct Plant {
    explicit Plant(const std::string& gateway, const std::string& code,
                   const std::string& records = {})
        : result(compiled(gateway +
                          "! id_pluto:01=000000000001\n"
                          "! type_pluto:01=A20,is3\n"
                          "! pgm_pluto:01\n" +
                          records + "S1.0_0\n" + code)),
          simulation(result.images), node(0, project::readProject(gateway).project.gateways.at(0)) {
        EXPECT_EQ(result.errors(), 0) << diagnosticsText(result.diagnostics);
        node.exchange(simulation);
    }
    void scan(int scans = 1) {
        for (int i = 0; i < scans; ++i) {
            simulation.scan();
            node.exchange(simulation);
        }
    }
    std::int64_t value(const char* word) const { return simulation.value(addressOf(word)); }
    std::uint32_t unit33(int address) const {
        return std::uint32_t{node.dataFromPluto()[static_cast<std::size_t>(address)]} << 16 |
               node.dataFromPluto()[static_cast<std::size_t>(address) + 1];
    }
    gateway::ModbusResponse write(int unit, int at, std::vector<std::uint16_t> values) {
        const int count = static_cast<int>(values.size());
        return node.answer({unit, 16, at, count, std::move(values)});
    }
    gateway::ModbusResponse read(int unit, int at, int count) {
        return node.answer({unit, 3, at, count, {}});
    }

    compiler::CompileResult result;
    sim::Simulation simulation;
    gateway::GatewayNode node;
};

const std::string kGateway = ";@gateway 0 type=\"GATE-E1\" to_pluto=\"0,2\" cycle_ms=\"40\"\n"
                             ";@gateway_area 0 0 pluto=\"1\" io_type=\"5\"\n"
                             ";@gateway_area 0 1 pluto=\"1\" io_type=\"100\"\n"
                             ";@gateway_area 0 2 pluto=\"1\" io_type=\"5\"\n";

const std::string kUserA =
    ";@system ToGateway_User_A No=\"5\" Send=\"I1.0\" Reg_0=\"R1.0\" Reg_1=\"-2\" Q=\"Q1.10\"\n";

} // namespace

TEST(GatewayNode, AUserBlocksTelegramFillsTheFirstAreaConfiguredForIt) {
    Plant plant(kGateway, "(R1.0 = 4660) = /M1.99\n" + kUserA);
    plant.scan();
    EXPECT_EQ(plant.value("Q1.10"), 0); // Send is 0
    EXPECT_EQ(plant.unit33(67), 0u);
    plant.simulation.set(addressOf("I1.0"), 1);
    plant.scan();
    EXPECT_EQ(plant.value("Q1.10"), 1);
    // Bytes 0-1 Reg_0 (0x1234), bytes 2-3 Reg_1 (-2): MSW first at 67.
    EXPECT_EQ(plant.unit33(67), 0xFFFE1234u);
    EXPECT_EQ(plant.node.additionalData(0), 0xFFFE1234u);
    // The same Pluto and IO-type in area 2: "only the first allocated area".
    EXPECT_EQ(plant.unit33(71), 0u);
}

TEST(GatewayNode, AnAreaReadsZeroAfter300msWithoutATelegram) {
    Plant plant(kGateway, "(R1.0 = 1) = /M1.99\n" + kUserA);
    plant.simulation.set(addressOf("I1.0"), 1);
    plant.scan();
    ASSERT_EQ(plant.unit33(67), 0xFFFE0001u);
    plant.simulation.set(addressOf("I1.0"), 0);
    plant.scan(30); // 300 ms after the last telegram: still within the timeout
    EXPECT_EQ(plant.unit33(67), 0xFFFE0001u);
    plant.scan();
    EXPECT_EQ(plant.unit33(67), 0u);
}

TEST(GatewayNode, StandardBlocksSendTheirLayout) {
    Plant plant(kGateway, ";@system ToGateway_ErrorCode Send=\"I1.0\" Q=\"M1.0\"\n");
    plant.simulation.force(addressOf("SR1.11"), 42); // SR_ErrorCode
    plant.simulation.set(addressOf("I1.0"), 1);
    plant.scan(2);
    // IO-type 100: byte 3 the error code, the rest undefined (0).
    EXPECT_EQ(plant.unit33(69), 42u << 24);
}

TEST(GatewayNode, AUnitSendsAtMostFourTelegramsAScan) {
    std::string code;
    for (int no = 1; no <= 5; ++no)
        code += ";@system ToGateway_User_A No=\"" + std::to_string(no) +
                "\" Send=\"I1.0\" Reg_0=\"" + std::to_string(no) + "\" Reg_1=\"0\" Q=\"M1." +
                std::to_string(no) + "\"\n";
    Plant plant(kGateway, code);
    EXPECT_NE(
        diagnosticsText(plant.result.diagnostics).find("5 ToGateway blocks of unit 1 can send"),
        std::string::npos)
        << diagnosticsText(plant.result.diagnostics);
    plant.simulation.set(addressOf("I1.0"), 1);
    plant.scan();
    for (const char* q : {"M1.1", "M1.2", "M1.3", "M1.4"})
        EXPECT_EQ(plant.value(q), 1) << q;
    EXPECT_EQ(plant.value("M1.5"), 0);
    EXPECT_EQ(plant.simulation.unit(1)->telegrams().size(), 4u);
}

TEST(GatewayNode, DataToPlutoReachesTheExternalCommBlockThatReceivesIt) {
    Plant plant(kGateway,
                ";@system ExtVarBlock BlockNo=\"1\" Valid=\"M1.0\" Bit_0=\"Q1.10\" "
                "Bit_1=\"M1.1\" Bit_2=\"M1.2\" Bit_3=\"M1.3\" Bit_4=\"M1.4\" Bit_5=\"M1.5\" "
                "Bit_6=\"M1.6\" Bit_7=\"M1.7\" Bit_8=\"M1.8\" Bit_9=\"M1.9\" Bit_10=\"M1.10\" "
                "Bit_11=\"M1.11\" Bit_12=\"M1.12\" Bit_13=\"M1.13\" Bit_14=\"M1.14\" "
                "Bit_15=\"M1.15\" Reg_0=\"R1.0\" Reg_1=\"R1.1\"\n",
                ";@ext_comm 01 1 gateway=\"0\" packet=\"2\" timeout_ms=\"200\"\n");
    plant.scan(5);
    EXPECT_EQ(plant.value("M1.0"), 0); // nothing valid written yet
    // Area 2: valid bit 2, bits 0x8001, registers 100 and -200.
    ASSERT_EQ(plant.write(1, 1, {0x0004}).exception, gateway::ModbusException::None);
    ASSERT_EQ(plant.write(1, 8, {0x8001, 100, static_cast<std::uint16_t>(-200)}).exception,
              gateway::ModbusException::None);
    plant.scan(5); // within one 40 ms cycle
    EXPECT_EQ(plant.value("M1.0"), 1);
    EXPECT_EQ(plant.value("Q1.10"), 1);
    EXPECT_EQ(plant.value("M1.1"), 0);
    EXPECT_EQ(plant.value("M1.15"), 1);
    EXPECT_EQ(plant.value("R1.0"), 100);
    EXPECT_EQ(plant.value("R1.1"), -200);
    // The fieldbus marks the area invalid: the block is cleared at the next cycle.
    ASSERT_EQ(plant.write(1, 1, {0x0000}).exception, gateway::ModbusException::None);
    plant.scan(5);
    EXPECT_EQ(plant.value("M1.0"), 0);
    EXPECT_EQ(plant.value("R1.0"), 0);
}

TEST(GatewayNode, ABlockWithoutPacketsTimesOutAndAGatewayWithoutWritesClearsItsData) {
    Plant plant(";@gateway 0 type=\"GATE-E1\" to_pluto=\"0\" timeout_ms=\"1000\"\n",
                ";@system Ext_Val BlockNo=\"0\" Valid=\"M1.0\" Reg_0=\"R1.0\" Reg_1=\"R1.1\"\n",
                ";@ext_comm 01 0 gateway=\"0\" packet=\"0\" timeout_ms=\"250\"\n");
    ASSERT_EQ(plant.write(1, 1, {0x0001, 0, 7, 8}).exception, gateway::ModbusException::None);
    plant.scan(11);
    EXPECT_EQ(plant.value("M1.0"), 1);
    EXPECT_EQ(plant.value("R1.1"), 8);
    // The gateway's 1000 ms timeout without a write: it sends 0, not valid.
    plant.scan(100);
    EXPECT_EQ(plant.value("M1.0"), 0);
    EXPECT_EQ(plant.read(1, 1, 4).registers, (std::vector<std::uint16_t>{0, 0, 0, 0}));
    // Valid again, then the gateway stops sending packet 0 (unit 4): the
    // unit's own 250 ms timeout clears the block.
    ASSERT_EQ(plant.write(1, 1, {0x0001, 0, 7, 8}).exception, gateway::ModbusException::None);
    plant.scan(11);
    ASSERT_EQ(plant.value("M1.0"), 1);
    ASSERT_EQ(plant.write(4, 1, {0x0000}).exception, gateway::ModbusException::None);
    plant.scan(20);
    EXPECT_EQ(plant.value("M1.0"), 1); // the last packet is at most 200 ms old
    plant.scan(20);
    EXPECT_EQ(plant.value("M1.0"), 0);
    EXPECT_EQ(plant.value("R1.1"), 0);
}

TEST(GatewayNode, TheConfigurationUnitTakesOnlyTheManualsRanges) {
    Plant plant(kGateway, "");
    using gateway::ModbusException;
    EXPECT_EQ(plant.read(4, 0, 1).exception, ModbusException::IllegalFunction);
    EXPECT_EQ(plant.write(4, 0, {37}).exception, ModbusException::IllegalDataValue);
    EXPECT_EQ(plant.write(4, 1, {0x10}).exception, ModbusException::IllegalDataValue);
    EXPECT_EQ(plant.write(4, 2, {500}).exception, ModbusException::IllegalDataValue); // GATE-E
    EXPECT_EQ(plant.write(4, 37, {3}).exception, ModbusException::IllegalDataValue);
    EXPECT_EQ(plant.write(4, 41, {1}).exception, ModbusException::IllegalDataValue);
    EXPECT_EQ(plant.write(4, 40, {0, 0, 0}).exception, ModbusException::IllegalDataAddress);
    EXPECT_EQ(plant.node.settings().cycleMs, 40); // nothing changed
    // Length 41 (A1), enable packets 1 and 3, timeout 2000, expected 0-1, area 3 = Pluto 1 IO-type
    // 100.
    std::vector<std::uint16_t> all(42, 0);
    all[0] = 41;
    all[1] = 0b1010;
    all[2] = 2000;
    all[4] = 0b11;
    all[5 + 3] = 0x0164;
    all[37] = 48;
    ASSERT_EQ(plant.write(4, 0, all).exception, ModbusException::None);
    const project::Gateway& settings = plant.node.settings();
    EXPECT_EQ(settings.toPluto, (std::set<int>{1, 3}));
    EXPECT_EQ(settings.timeoutMs, 2000);
    EXPECT_EQ(settings.expectedNodes, (std::set<int>{0, 1}));
    EXPECT_EQ(settings.areas, (std::map<int, project::GatewayArea>{{3, {1, 100}}}));
    EXPECT_EQ(settings.cycleMs, 48);
}

TEST(GatewayNode, ALocalDataRequestIsAnsweredWithTheFlagSequence) {
    Plant plant(kGateway, "M1.5 = I1.0\n(R1.2 = 1234) = /M1.99\n");
    plant.simulation.set(addressOf("I1.0"), 1);
    plant.scan();
    // M5 of an A20 is local bit address 216 + 5.
    ASSERT_EQ(plant.write(2, 0, {3, 1, 1, 221}).exception, gateway::ModbusException::None);
    EXPECT_EQ(plant.read(2, 0, 1).registers[0], 3);
    plant.scan();
    EXPECT_EQ(plant.read(2, 0, 1).registers[0], 0);
    EXPECT_EQ(plant.read(34, 0, 7).registers,
              (std::vector<std::uint16_t>{6, 1, 1, 221, 0x0001, 0, 1}));
    ASSERT_EQ(plant.write(34, 0, {0}).exception, gateway::ModbusException::None);
    EXPECT_EQ(plant.read(34, 0, 1).registers[0], 0);
    // R2 is local register address 102.
    plant.write(2, 0, {3, 1, 2, 102});
    plant.scan();
    EXPECT_EQ(plant.read(34, 4, 3).registers, (std::vector<std::uint16_t>{0x0001, 0, 1234}));
    // No Pluto 7 answers; parameters are not simulated; address 2000 is no variable.
    plant.write(2, 0, {3, 7, 2, 102});
    plant.scan();
    EXPECT_EQ(plant.read(34, 4, 1).registers[0], 0x0002);
    plant.write(2, 0, {3, 1, 3, 0});
    plant.scan();
    EXPECT_EQ(plant.read(34, 4, 1).registers[0], 0x0008);
    plant.write(2, 0, {3, 1, 1, 2000});
    plant.scan();
    EXPECT_EQ(plant.read(34, 4, 1).registers[0], 0x0004);
}

TEST(GatewayNode, TheCompilerChecksWhatTheManualStates) {
    const auto result =
        compiled(kGateway + "! id_pluto:01=000000000001\n"
                            "! type_pluto:01=A20,is3\n"
                            "! pgm_pluto:01\n"
                            ";@ext_comm 01 0 gateway=\"3\" packet=\"0\"\n"
                            ";@ext_comm 01 1 gateway=\"0\" packet=\"1\"\n"
                            ";@ext_comm 01 2 gateway=\"0\" packet=\"0\" timeout_ms=\"40\"\n"
                            "S1.0_0\n"
                            ";@system ToGateway_User_A No=\"5\" Send=\"I1.0\" Reg_0=\"1\" "
                            "Reg_1=\"2\" Q=\"M1.1\"\n"
                            ";@system ToGateway_User_C No=\"5\" Send=\"I1.0\" Reg_0=\"1\" "
                            "Bit_0=\"I1.1\" Bit_1=\"I1.1\" Bit_2=\"I1.1\" Bit_3=\"I1.1\" "
                            "Bit_4=\"I1.1\" Bit_5=\"I1.1\" Bit_6=\"I1.1\" Bit_7=\"I1.1\" "
                            "Bit_8=\"I1.1\" Bit_9=\"I1.1\" Bit_10=\"I1.1\" Bit_11=\"I1.1\" "
                            "Bit_12=\"I1.1\" Bit_13=\"I1.1\" Bit_14=\"I1.1\" Bit_15=\"I1.1\" "
                            "Q=\"M1.2\"\n"
                            ";@system ToGateway_User_B No=\"100\" Send=\"I1.0\" Reg_0=\"1\" "
                            "Bit_0=\"I1.1\" Bit_1=\"I1.1\" Bit_2=\"I1.1\" Bit_3=\"I1.1\" "
                            "Bit_4=\"I1.1\" Bit_5=\"I1.1\" Bit_6=\"I1.1\" Bit_7=\"I1.1\" "
                            "Q=\"M1.3\"\n"
                            ";@system Ext_Val BlockNo=\"3\" Valid=\"M1.4\" Reg_0=\"R1.0\" "
                            "Reg_1=\"R1.1\"\n");
    const std::string text = diagnosticsText(result.diagnostics);
    EXPECT_EQ(result.errors(), 2) << text;
    for (const char* expected :
         {"user block number 5 is already used at line 12", "No must be a number 1-99",
          "receives from gateway 3, which the project does not have",
          "receives packet 1 of gateway 0, which does not send it",
          "its timeout (40 ms) must be greater than gateway 0's cycle time (40 ms",
          "External Comm Block 3 of unit 1 receives nothing"})
        EXPECT_NE(text.find(expected), std::string::npos) << expected << "\n" << text;
}

namespace {

// The telegram unit 0, of type `type`, sends in one scan with `inputs` set.
std::uint32_t telegramOf(const std::string& type, const std::string& block,
                         const std::vector<const char*>& inputs) {
    const std::string family = type == "B46" ? "_Double" : type == "ASi" ? "_ASi" : "";
    const auto result = compiled("! id_pluto" + family +
                                 ":00=000000000000\n"
                                 "! type_pluto:00=" +
                                 type +
                                 ",is3\n"
                                 "! pgm_pluto:00\n"
                                 "S0.0_0\n"
                                 ";@system " +
                                 block + " Send=\"M0.1\" Q=\"M0.2\"\nM0.1 = /M0.99\n");
    EXPECT_EQ(result.errors(), 0) << diagnosticsText(result.diagnostics);
    sim::Simulation simulation(result.images);
    for (const char* input : inputs)
        simulation.set(addressOf(input), 1);
    simulation.scan(); // M0.1 comes on
    simulation.scan();
    const auto& telegrams = simulation.unit(0)->telegrams();
    EXPECT_EQ(telegrams.size(), 1u);
    return telegrams.empty() ? 0 : telegrams.front().data;
}

} // namespace

// Gateway manual 4.3.3.2: byte 0 the least significant, bit 0 of a byte its lowest.
TEST(GatewayNode, StandardBlocksReadTheUnitInTheManualsLayouts) {
    // 101: I20-I27, I30-I37, I40-I47, then the error code.
    EXPECT_EQ(telegramOf("B46", "ToGateway_B46_I20_I47", {"I0.20", "I0.27", "I0.35", "I0.47"}),
              0x00802081u);
    // 104: slaves 4-7, each byte .1-.4 low, the B slave's .1-.4 high.
    EXPECT_EQ(telegramOf("ASi", "ToGateway_ASi_4_7_NonSafe_In", {"ASi0.4.1", "ASi0.5B.4"}),
              0x00008001u);
    // 103: byte 0 undefined, then slaves 1-3.
    EXPECT_EQ(telegramOf("ASi", "ToGateway_ASi_1_3_NonSafe_In", {"ASi0.1.2", "ASi0.3.1"}),
              0x01000200u);
    // 113: I10-I17, then the safety slaves 1-7 from bit 1 of byte 1, 8-15 in byte 2.
    EXPECT_EQ(telegramOf("ASi", "ToGateway_ASi_1_15_Safe", {"I0.10", "ASi0.1", "ASi0.15"}),
              0x00800201u);
    // 102: I1-I3 from bit 1, I10-I13 from bit 4; safety slaves 16-31 in bytes 1-2.
    EXPECT_EQ(
        telegramOf("ASi", "ToGateway_ASi_16_31_Safe", {"I0.1", "I0.13", "ASi0.16", "ASi0.31"}),
        0x00800182u);
}
