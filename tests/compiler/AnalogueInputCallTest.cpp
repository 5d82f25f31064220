// SPDX-License-Identifier: GPL-3.0-or-later
// The analogue input instructions (ReadVoltage, ReadCurrent and their _32
// forms, docs/image-format.md): what the compiler makes of a call and what
// it refuses, each at its line and column.
#include "DiagnosticsText.h"
#include "compiler/Compiler.h"
#include "compiler/SystemInstruction.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace rs;
using compiler::Op;
using rs::test::problemsText;

namespace {

// A D45 whose IA0.0 is configured 0-10 V, IA0.1 4-20 mA, IA0.2 as an
// ordinary input and IA0.3 not at all.
std::string analogueD45(const std::string& code) {
    return "! id_pluto_Double:00=000000000000\n"
           "! type_pluto:00=D45,is3\n"
           "! pgm_pluto:00\n"
           "! IA0.0,voltage\n"
           "! IA0.1,current\n"
           "! IA0.2,static\n"
           "S0.0_0\n" +
           code;
}

} // namespace

TEST(AnalogueInputCall, TheInputIsReadAsAValueAndTheScaleMayBeNumbers) {
    const auto result = compiler::compileText(analogueD45(
        ";@system ReadCurrent_32 Input=\"IA0.1\" Value_4mA=\"-100000\" Value_20mA=\"DR0.2\" "
        "Q=\"M0.1\" Current=\"DR0.4\" Scaled_Value=\"DR0.6\"\n"));
    ASSERT_EQ(problemsText(result), "");
    const auto& code = result.images.front().code;
    ASSERT_EQ(code.size(), 7u);
    EXPECT_EQ(code[0].op, Op::System);
    EXPECT_EQ(code[0].aux, std::uint8_t(compiler::SystemInstructionId::ReadCurrent32));
    const std::vector<std::string> operands = {"IA0.1", "", "DR0.2", "M0.1", "DR0.4", "DR0.6"};
    const std::uint8_t word = compiler::ArgumentWord;
    const std::uint8_t written = compiler::ArgumentWritten;
    const std::vector<std::uint8_t> roles = {word,    word,           word,
                                             written, written | word, written | word};
    for (std::size_t i = 0; i < operands.size(); ++i) {
        const compiler::Instruction& argument = code[1 + i];
        EXPECT_EQ(argument.op, Op::Argument);
        EXPECT_EQ(argument.aux, roles[i]) << i;
        if (operands[i].empty()) {
            EXPECT_EQ(argument.flags, compiler::ConstantOperand);
            EXPECT_EQ(argument.constant, -100000);
        } else {
            EXPECT_EQ(lang::toString(argument.operand), operands[i]);
        }
    }
}

TEST(AnalogueInputCall, WrongCallsAreErrorsAtTheOperand) {
    struct Case {
        std::string call;
        std::string expected;
    };
    const std::string outputs = " Q=\"M0.1\" Voltage=\"R0.1\" Scaled_Value=\"R0.2\"";
    const std::string outputs32 = " Q=\"M0.1\" Voltage=\"DR0.4\" Scaled_Value=\"DR0.6\"";
    const std::vector<Case> cases = {
        {";@system ReadVoltage Input=\"IA0.1\" Value_0V=\"0\" Value_10V=\"100\"" + outputs,
         "8:22: error: ReadVoltage reads IA0.1 as a voltage input, but line 5 declares it a "
         "current input\n"},
        {";@system ReadCurrent Input=\"IA0.0\" Value_4mA=\"0\" Value_20mA=\"100\"" +
             std::string(" Q=\"M0.1\" Current=\"R0.1\" Scaled_Value=\"R0.2\""),
         "8:22: error: ReadCurrent reads IA0.0 as a current input, but line 4 declares it a "
         "voltage input\n"},
        {";@system ReadVoltage Input=\"IA0.2\" Value_0V=\"0\" Value_10V=\"100\"" + outputs,
         "8:22: error: ReadVoltage reads IA0.2 as a voltage input, but line 6 declares it an "
         "ordinary input\n"},
        {";@system ReadVoltage Input=\"IA0.3\" Value_0V=\"0\" Value_10V=\"100\"" + outputs,
         "8:22: warning: unconfigured I/O: IA0.3 has no I/O declaration in the code of unit 0\n"},
        {";@system ReadVoltage Input=\"I0.0\" Value_0V=\"0\" Value_10V=\"100\"" + outputs,
         "8:22: error: ReadVoltage: operand Input takes an analogue input (IA), not I0.0\n"},
        {";@system ReadVoltage Input=\"IA0.0\" Value_0V=\"0\" Value_10V=\"40000\"" + outputs,
         "8:49: error: 40000 does not fit a register (-32768..32767)\n"},
        {";@system ReadVoltage Input=\"IA0.0\" Value_0V=\"DR0.8\" Value_10V=\"100\"" + outputs,
         "8:36: error: ReadVoltage: operand Value_0V takes a register (R, a half of a DR, SR) "
         "or a number, not DR0.8\n"},
        {";@system ReadVoltage_32 Input=\"IA0.0\" Value_0V=\"0\" Value_10V=\"100000\"" + outputs,
         "8:80: error: ReadVoltage_32: operand Voltage takes a double register (DR), not R0.1\n"
         "8:95: error: ReadVoltage_32: operand Scaled_Value takes a double register (DR), not "
         "R0.2\n"},
        {";@system ReadVoltage_32 Input=\"IA0.0\" Value_0V=\"0\" Value_10V=\"100000\"" + outputs32,
         ""},
        {";@system ReadVoltage Input=\"IA0.0\" Value_0V=\"0\" Value_10V=\"100\" Q=\"M0.1\" "
         "Voltage=\"R0.1\"",
         "8:1: error: ReadVoltage: operand Scaled_Value is not given\n"},
    };
    for (const auto& c : cases)
        EXPECT_EQ(problemsText(compiler::compileText(analogueD45(c.call + "\n"))), c.expected)
            << c.call;
}

TEST(AnalogueInputCall, AUnitWithoutAnalogueInputsCannotReadOne) {
    const auto result = compiler::compileText(
        "! id_pluto:00=000000000000\n! type_pluto:00=A20,is3\n! pgm_pluto:00\nS0.0_0\n"
        ";@system ReadVoltage Input=\"IA0.0\" Value_0V=\"0\" Value_10V=\"100\" Q=\"M0.1\" "
        "Voltage=\"R0.1\" Scaled_Value=\"R0.2\"\n");
    EXPECT_EQ(problemsText(result), "5:22: error: IA0.0 does not exist on unit 0, an A20\n");
}
