// SPDX-License-Identifier: GPL-3.0-or-later
// The counter input instructions (HS_SpeedCount_Up, HS_SpeedCount_Dir,
// docs/image-format.md): what the compiler makes of a call and what it
// refuses, each at its line and column.
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

// A D45 whose IA0.0 counts up, IA0.2 and IA0.3 up and down, IA0.1 reads
// 4-20 mA and IA0.4 is an ordinary input.
std::string counterD45(const std::string& code) {
    return "! id_pluto_Double:00=000000000000\n"
           "! type_pluto:00=D45,is3\n"
           "! pgm_pluto:00\n"
           "! IA0.0,counter_up\n"
           "! IA0.1,current\n"
           "! IA0.2,counter_updown\n"
           "! IA0.3,counter_updown\n"
           "! IA0.4,static\n"
           "S0.0_0\n" +
           code;
}

} // namespace

TEST(CounterInputCall, TheUpDownPairIsReadAsValuesAndTheSpeedsWritten) {
    const auto result = compiler::compileText(
        counterD45(";@system HS_SpeedCount_Dir Input_A=\"IA0.2\" Input_B=\"IA0.3\" Valid=\"M0.1\" "
                   "EdgePer10ms=\"R0.4\" PulsePerSec=\"R0.5\"\n"));
    ASSERT_EQ(problemsText(result), "");
    const auto& code = result.images.front().code;
    ASSERT_EQ(code.size(), 6u);
    EXPECT_EQ(code[0].op, Op::System);
    EXPECT_EQ(code[0].aux, std::uint8_t(compiler::SystemInstructionId::HSSpeedCountDir));
    const std::vector<std::string> operands = {"IA0.2", "IA0.3", "M0.1", "R0.4", "R0.5"};
    const std::uint8_t word = compiler::ArgumentWord;
    const std::uint8_t written = compiler::ArgumentWritten;
    const std::vector<std::uint8_t> roles = {word, word, written, written | word, written | word};
    for (std::size_t i = 0; i < operands.size(); ++i) {
        const compiler::Instruction& argument = code[1 + i];
        EXPECT_EQ(argument.op, Op::Argument);
        EXPECT_EQ(argument.aux, roles[i]) << i;
        EXPECT_EQ(lang::toString(argument.operand), operands[i]);
    }
}

TEST(CounterInputCall, TheUpCounterIsInstructionSeven) {
    const auto result = compiler::compileText(
        counterD45(";@system HS_SpeedCount_Up Input=\"IA0.0\" Valid=\"M0.1\" EdgePer10ms=\"R0.4\" "
                   "PulsePerSec=\"R0.5\"\n"));
    ASSERT_EQ(problemsText(result), "");
    const auto& code = result.images.front().code;
    ASSERT_EQ(code.size(), 5u);
    EXPECT_EQ(code[0].aux, 7);
    EXPECT_EQ(lang::toString(code[1].operand), "IA0.0");
}

TEST(CounterInputCall, WrongCallsAreErrorsAtTheOperand) {
    struct Case {
        std::string call;
        std::string expected;
    };
    const std::string outputs = " Valid=\"M0.1\" EdgePer10ms=\"R0.4\" PulsePerSec=\"R0.5\"";
    const std::vector<Case> cases = {
        {";@system HS_SpeedCount_Up Input=\"IA0.2\"" + outputs,
         "10:27: error: HS_SpeedCount_Up reads IA0.2 as a counter_up input, but line 6 "
         "declares it a counter_updown input\n"},
        {";@system HS_SpeedCount_Up Input=\"IA0.1\"" + outputs,
         "10:27: error: HS_SpeedCount_Up reads IA0.1 as a counter_up input, but line 5 "
         "declares it a current input\n"},
        {";@system HS_SpeedCount_Dir Input_A=\"IA0.2\" Input_B=\"IA0.0\"" + outputs,
         "10:44: error: HS_SpeedCount_Dir reads IA0.0 as a counter_updown input, but line 4 "
         "declares it a counter_up input\n"},
        {";@system HS_SpeedCount_Dir Input_A=\"IA0.4\" Input_B=\"IA0.3\"" + outputs,
         "10:28: error: HS_SpeedCount_Dir reads IA0.4 as a counter_updown input, but line 8 "
         "declares it an ordinary input\n"},
        {";@system HS_SpeedCount_Up Input=\"I0.0\"" + outputs,
         "10:27: error: HS_SpeedCount_Up: operand Input takes an analogue input (IA), not I0.0\n"},
        {";@system HS_SpeedCount_Up Input=\"IA0.0\" Valid=\"M0.1\" EdgePer10ms=\"DR0.4\" "
         "PulsePerSec=\"R0.5\"",
         "10:54: error: HS_SpeedCount_Up: operand EdgePer10ms takes a register (R, a half of a "
         "DR, SR), not DR0.4\n"},
        {";@system HS_SpeedCount_Up Input=\"IA0.0\" Valid=\"M0.1\" EdgePer10ms=\"R0.4\"",
         "10:1: error: HS_SpeedCount_Up: operand PulsePerSec is not given\n"},
    };
    for (const auto& c : cases)
        EXPECT_EQ(problemsText(compiler::compileText(counterD45(c.call + "\n"))), c.expected)
            << c.call;
}
