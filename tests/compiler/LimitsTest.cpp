// SPDX-License-Identifier: GPL-3.0-or-later
// What the compiler refuses or allows at the edges: a program too large for
// its unit, units of another project on the bus, and the same bytes every run.

#include "compiler/Compiler.h"
#include "compiler/ImageCodec.h"

#include <gtest/gtest.h>

#include <string>

using namespace rs;

namespace {

std::vector<std::string> lines(const lang::Diagnostics& diagnostics) {
    std::vector<std::string> out;
    for (const auto& d : diagnostics)
        out.push_back(std::to_string(d.line) + ":" + std::to_string(d.column) + ": " +
                      (d.severity == lang::Severity::Error ? "error: " : "warning: ") + d.message);
    return out;
}

compiler::CheckOptions quiet() {
    compiler::CheckOptions options;
    options.warnUnconfiguredIo = false;
    return options;
}

// Unit 0 with `statements` lines of code, each a series of 40 contacts (1,176
// bytes of image), then unit 1 with one line.
std::string twoUnitsOfSize(int statements) {
    std::string series = "I0.0";
    for (int i = 1; i < 40; ++i)
        series += " * I0." + std::to_string(i % 8);
    std::string text = "! id_pluto:00=000000000000\n! id_pluto:01=000000000000\n"
                       "! pgm_pluto:00\nS0.0_0\n";
    for (int i = 0; i < statements; ++i)
        text += "M0." + std::to_string(i % 16) + " = " + series + "\n";
    return text + "! pgm_pluto:01\nS1.0_0\nQ1.0 = I1.0\n";
}

} // namespace

TEST(ProgramSize, AProgramThatFitsItsUnitCompiles) {
    const compiler::CompileResult result = compiler::compileText(twoUnitsOfSize(14000), quiet());
    EXPECT_EQ(result.errors(), 0);
    ASSERT_EQ(result.images.size(), 2u);
    EXPECT_LE(compiler::encodeImage(result.images[0]).size(), compiler::kMaxUnitImageBytes);
    EXPECT_NO_THROW(compiler::writeHps(result.images));
}

TEST(ProgramSize, AProgramTooLargeForItsUnitIsAnErrorAtItsPgmPlutoLine) {
    // 15,000 lines take 17,640,000 bytes and more.
    const compiler::CompileResult result = compiler::compileText(twoUnitsOfSize(15000), quiet());
    ASSERT_EQ(result.errors(), 1) << lines(result.diagnostics).front();
    const auto& error = result.diagnostics.front();
    EXPECT_EQ(error.line, 3);
    EXPECT_EQ(error.column, 1);
    EXPECT_TRUE(error.message.starts_with("program of unit 0 is ")) << error.message;
    EXPECT_TRUE(error.message.ends_with(" bytes; a Pluto A20 holds at most 16777216 bytes"))
        << error.message;
    EXPECT_TRUE(result.images.empty());
}

TEST(OtherProjectUnit, ReadingItsGlobalsIsAWarningOncePerUnit) {
    const compiler::CompileResult result =
        compiler::compileText("! id_pluto:00=000000000000\n! pgm_pluto:00\nS0.0_0\n"
                              "Q0.0 = I1.0 * GM1.2 * I2.3\nQ0.1 = Q1.0\n",
                              quiet());
    EXPECT_EQ(lines(result.diagnostics),
              (std::vector<std::string>{"4:8: warning: unit 1 is not in this project; its globals "
                                        "come from another project on the bus",
                                        "4:23: warning: unit 2 is not in this project; its globals "
                                        "come from another project on the bus"}));
    ASSERT_EQ(result.images.size(), 1u);
    EXPECT_EQ(result.images[0].code[1].operand.unit, 1);
}

TEST(OtherProjectUnit, ItsLocalsAndWritingItAreErrors) {
    const compiler::CompileResult result =
        compiler::compileText("! id_pluto:00=000000000000\n! pgm_pluto:00\nS0.0_0\n"
                              "Q0.0 = M1.0\n(R0.1 = R1.2)\nS(GM1.0) = I0.0\n",
                              quiet());
    EXPECT_EQ(lines(result.diagnostics),
              (std::vector<std::string>{
                  "4:8: error: M1.0 belongs to unit 1, which the project does not have (no '! "
                  "id_pluto:01=...'); only its globals can be read",
                  "5:9: error: R1.2 belongs to unit 1, which the project does not have (no '! "
                  "id_pluto:01=...'); only its globals can be read",
                  "6:3: error: GM1.0 belongs to unit 1, which the project does not have (no '! "
                  "id_pluto:01=...')"}));
    EXPECT_TRUE(result.images.empty());
}

TEST(Determinism, TheSameProjectCompilesToTheSameBytesEveryTime) {
    const std::string text = "$name Twice\n! id_pluto:00=000000000000\n! type_pluto:00=A20,is3\n"
                             "! id_pluto:01=000000000000\n! pgm_pluto:00\n! I0.0=Start\n"
                             "S0.1_0\nJ(+1) = Start\nS0.1_1\nJ(0) = TON(2s00)\nS0.0_0\n"
                             "Q0.1 = Start * (I0.1 + /I0.2) * TON(1s00) + P(GM1.0)\n"
                             "(R0.1 = R0.2 + 5) = N(I0.5)\n! pgm_pluto:01\nS1.0_0\n"
                             "GM1.0 = I1.0 * I0.0\n";
    const compiler::CompileResult first = compiler::compileText(text, quiet());
    ASSERT_EQ(first.errors(), 0) << lines(first.diagnostics).front();
    const compiler::CompileResult second = compiler::compileText(text, quiet());
    EXPECT_EQ(compiler::writeHps(second.images), compiler::writeHps(first.images));
}
