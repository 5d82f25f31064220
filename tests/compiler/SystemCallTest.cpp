// SPDX-License-Identifier: GPL-3.0-or-later
// ;@system records (docs/file-format.md): what the compiler makes of them and
// every error it gives at a call, at its line and column.
#include "DiagnosticsText.h"
#include "compiler/Compiler.h"
#include "compiler/ImageCodec.h"
#include "compiler/SystemInstruction.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

using namespace rs;
using compiler::Op;
using rs::test::problemsText;

namespace {

// Unit 1 reads the register and double register unit 0 exports.
std::string twoUnitsExporting(const std::string& unitOneCode,
                              const std::string& unitOneNames = "") {
    return "! id_pluto:00=000000000000\n"
           ";@var R0.5 export=\"yes\"\n"
           ";@var DR0.10 export=\"yes\"\n"
           "! type_pluto:00=A20,is3\n"
           "! id_pluto:01=000000000001\n"
           "! type_pluto:01=A20,is3\n"
           "! pgm_pluto:00\n"
           "S0.0_0\n"
           "(R0.5 = 42)\n"
           "! pgm_pluto:01\n" +
           unitOneNames + "S1.0_0\n" + unitOneCode;
}

const compiler::UnitImage& unitOne(const compiler::CompileResult& result) {
    return result.images.back();
}

} // namespace

TEST(SystemCall, ACallIsASystemInstructionAndItsOperandsInTheParametersOrder) {
    // Operands in another order than the instruction's, a name, lower case.
    const auto result = compiler::compileText(
        twoUnitsExporting("M1.0 = I1.0\n"
                          ";@system registervalid value=\"Speed\" Valid=\"m1.1\" Input=\"R0.5\"\n"
                          "Q1.10 = M1.1\n",
                          "! R1.7=Speed\n"),
        {.warnUnconfiguredIo = false, .onlyUnit = {}});
    ASSERT_EQ(problemsText(result), "");
    const auto& code = unitOne(result).code;
    // M1.0 = I1.0: Rung, Contact, Coil; then the call; then Q1.10 = M1.1.
    ASSERT_EQ(code.size(), 3u + 4u + 3u);
    const compiler::Instruction& call = code[3];
    EXPECT_EQ(call.op, Op::System);
    EXPECT_EQ(call.aux, std::uint8_t(compiler::SystemInstructionId::RegisterValid));
    EXPECT_EQ(call.slot, 3);
    EXPECT_EQ(call.line, 14u);
    EXPECT_EQ(call.column, 1);
    EXPECT_EQ(call.statement, compiler::kNoStatement);
    const std::vector<std::string> operands = {"R0.5", "M1.1", "R1.7"};
    const std::vector<std::uint8_t> roles = {compiler::ArgumentWord, compiler::ArgumentWritten,
                                             compiler::ArgumentWritten | compiler::ArgumentWord};
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(code[4 + i].op, Op::Argument);
        EXPECT_EQ(lang::toString(code[4 + i].operand), operands[i]);
        EXPECT_EQ(code[4 + i].aux, roles[i]);
        EXPECT_EQ(code[4 + i].statement, compiler::kNoStatement);
    }
    // The statements around the call keep their numbers: the call takes none.
    EXPECT_EQ(code[0].statement, 0u);
    EXPECT_EQ(code[7].statement, 1u);

    const auto decoded = compiler::readHps(compiler::writeHps(result.images));
    ASSERT_TRUE(std::holds_alternative<std::vector<compiler::UnitImage>>(decoded));
    EXPECT_EQ(std::get<std::vector<compiler::UnitImage>>(decoded), result.images);
}

TEST(SystemCall, WrongCallsAreErrorsAtTheRecord) {
    struct Case {
        std::string call;
        std::string expected;
    };
    const std::vector<Case> cases = {
        {";@system ReadTemperature Input=\"R0.5\"",
         "12:1: error: unknown system instruction 'ReadTemperature'; did you mean ReadVoltage, "
         "ReadCurrent, ReadVoltage_32, ReadCurrent_32?\n"},
        {";@system Temperature Input=\"R0.5\"",
         "12:1: error: unknown system instruction 'Temperature'; Rungsmith's image has 27, "
         "listed in docs/image-format.md, \"System instructions\"\n"},
        {";@system", "12:1: error: @system needs one system instruction's name, as in "
                     ";@system RegisterValid Input=\"R1.5\" Valid=\"M0.1\" Value=\"R0.7\"\n"},
        {";@system RegisterValid Input=\"R0.5\" Valid=\"M1.1\" Value=\"R1.6\" Colour=\"red\"",
         "12:63: error: RegisterValid has no operand 'Colour'; its operands are Input, Valid, "
         "Value\n"},
        {";@system RegisterValid Input=\"R0.5\" Valid=\"M1.1\"",
         "12:1: error: RegisterValid: operand Value is not given\n"},
        {";@system RegisterValid Input=\"R0.5\" Valid=\"M1.1\" Value=\"R1.6\" input=\"R0.5\"",
         "12:63: error: RegisterValid: operand Input is given twice\n"},
        {";@system RegisterValid Input=\"M0.1\" Valid=\"M1.1\" Value=\"R1.6\"",
         "12:24: error: RegisterValid: operand Input takes a register (R, a half of a DR, SR), "
         "not M0.1\n"},
        {";@system DRegisterValid Input=\"R0.5\" Valid=\"M1.1\" Value=\"DR1.6\"",
         "12:25: error: DRegisterValid: operand Input takes a double register (DR), not R0.5\n"},
        {";@system RegisterValid Input=\"7\" Valid=\"M1.1\" Value=\"R1.6\"",
         "12:24: error: RegisterValid: operand Input takes a register (R, a half of a DR, SR), "
         "not '7'\n"},
        {";@system RegisterValid Input=\"R0.5\" Valid=\"S1.0_0\" Value=\"R1.6\"",
         "12:37: error: RegisterValid: operand Valid takes a bit, not 'S1.0_0'\n"},
        {";@system RegisterValid Input=\"Nowhere\" Valid=\"M1.1\" Value=\"R1.6\"",
         "12:24: error: unknown name 'Nowhere': declare it with '! <address>=Nowhere'\n"},
        // What any statement's operands are checked for.
        {";@system RegisterValid Input=\"R0.6\" Valid=\"M1.1\" Value=\"R1.6\"",
         "12:24: error: R0.6 is local to unit 0 and not exported; other units cannot read it\n"},
        {";@system RegisterValid Input=\"R0.5\" Valid=\"I1.1\" Value=\"R1.6\"",
         "12:37: error: I1.1 is an input; the program cannot write it\n"},
        {";@system RegisterValid Input=\"R0.5\" Valid=\"M1.1\" Value=\"R0.6\"",
         "12:50: error: R0.6 belongs to unit 0; a unit writes only its own variables\n"},
    };
    for (const auto& c : cases) {
        const auto result = compiler::compileText(twoUnitsExporting(c.call + "\n"),
                                                  {.warnUnconfiguredIo = false, .onlyUnit = {}});
        EXPECT_EQ(problemsText(result), c.expected) << c.call;
        EXPECT_TRUE(result.images.empty()) << c.call;
    }
}

TEST(SystemCall, AnOutputWrittenElsewhereTooIsWarnedAboutAsACoilIs) {
    const auto result = compiler::compileText(
        twoUnitsExporting(";@system RegisterValid Input=\"R0.5\" Valid=\"M1.1\" Value=\"R1.6\"\n"
                          "M1.1 = I1.0\n"),
        {.warnUnconfiguredIo = false, .onlyUnit = {}});
    EXPECT_EQ(problemsText(result),
              "13:1: warning: M1.1 is also written at line 12; the write that runs last in each "
              "scan wins\n");
}

// The engine runs a System on the Arguments after it as its table says: an
// image that says otherwise is refused when read.
TEST(SystemCall, ADamagedCallIsRefusedWhenTheImageIsRead) {
    const auto result = compiler::compileText(
        twoUnitsExporting(";@system RegisterValid Input=\"R0.5\" Valid=\"M1.1\" Value=\"R1.6\"\n"),
        {.warnUnconfiguredIo = false, .onlyUnit = {}});
    ASSERT_EQ(result.errors(), 0);
    const compiler::UnitImage& image = unitOne(result);
    std::size_t call = 0;
    while (image.code[call].op != Op::System)
        ++call;
    auto refused = [&](const std::function<void(compiler::UnitImage&)>& damage) {
        compiler::UnitImage damaged = image;
        damage(damaged);
        const auto read = compiler::decodeImage(compiler::encodeImage(damaged));
        return std::holds_alternative<compiler::ImageError>(read)
                   ? std::get<compiler::ImageError>(read).message
                   : std::string("read");
    };
    EXPECT_EQ(refused([&](auto& i) { i.code[call].aux = 200; }), "unknown system instruction 200");
    EXPECT_EQ(refused([&](auto& i) { i.code[call].slot = 2; }),
              "system instruction RegisterValid takes 3 operands, not 2");
    EXPECT_EQ(refused([&](auto& i) { i.code[call + 2].aux = compiler::ArgumentWord; }),
              "operand 2 of system instruction RegisterValid is not what it takes");
    EXPECT_EQ(refused([&](auto& i) { i.code.erase(i.code.begin() + std::ptrdiff_t(call)); }),
              "an operand of a system instruction without the instruction");
    EXPECT_EQ(refused([&](auto& i) { i.code.resize(call + 3); }),
              "the code ends within the operands of system instruction RegisterValid");
    EXPECT_EQ(refused([](auto&) {}), "read");
}
