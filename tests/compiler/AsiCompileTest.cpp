// SPDX-License-Identifier: GPL-3.0-or-later
#include "compiler/Compiler.h"
#include "compiler/ImageCodec.h"

#include <gtest/gtest.h>

using namespace rs;

namespace {

std::string asiProject(const std::string& records, const std::string& code) {
    // Lines 1-3, the records, then the program from line 4 + records + 2.
    return "$name Asi\n"
           "! id_pluto_ASi:00=000000000000\n"
           "! type_pluto:00=ASi,is2\n" +
           records + "! pgm_pluto:00\nS0.0_0\n" + code;
}

std::vector<std::string> warnings(const compiler::CompileResult& result) {
    std::vector<std::string> lines;
    for (const auto& d : result.diagnostics)
        lines.push_back(std::to_string(d.line) + ":" + std::to_string(d.column) + ": " +
                        (d.severity == lang::Severity::Error ? "error: " : "warning: ") +
                        d.message);
    return lines;
}

} // namespace

TEST(AsiCompile, ASlaveUsedButNotDefinedIsAWarningOnce) {
    const auto result =
        compiler::compileText(asiProject(";@asi_slave ASi0.3 type=\"safe_input\"\n",
                                         "Q0.0 = ASi0.3 * ASi0.4\nQ0.1 = ASi0.4 * ASi0.3\n"));
    EXPECT_EQ(warnings(result),
              (std::vector<std::string>{"7:17: warning: ASi0.4: AS-i slave ASi0.4 is not defined "
                                        "on the AS-i Options page"}));
    EXPECT_EQ(result.images.size(), 1u); // a warning compiles
}

TEST(AsiCompile, AVariableTheSlaveTypeLacksIsAWarning) {
    const auto result = compiler::compileText(
        asiProject(";@asi_slave ASi0.3 type=\"safe_input\"\n"
                   ";@asi_slave ASi0.5 type=\"nonsafe_ab\"\n",
                   "Q0.0 = ASi0.3.1 * ASi0.5.4\nASq0.5.4 = Q0.0\nASq0.3.2 = Q0.0\n"));
    EXPECT_EQ(warnings(result),
              (std::vector<std::string>{
                  "8:8: warning: ASi0.3.1: AS-i slave ASi0.3 is a Safe Input slave, which has "
                  "no such variable",
                  "9:1: warning: ASq0.5.4: AS-i slave ASi0.5 is a Nonsafe A/B slave, which has "
                  "no such variable"}));
}

TEST(AsiCompile, ABusNotUsedAndAMonitoringUnitAreWarnings) {
    auto result =
        compiler::compileText(asiProject(";@asi 00 mode=\"unused\"\n", "Q0.0 = ASi0.3\n"));
    EXPECT_EQ(warnings(result),
              (std::vector<std::string>{"7:8: warning: ASi0.3: the AS-i bus of unit 0 is set as "
                                        "not used (AS-i Options)"}));
    result = compiler::compileText(
        asiProject(";@asi 00 mode=\"monitor\"\n;@asi_slave ASi0.7 type=\"nonsafe_std\"\n",
                   "ASq0.7.1 = ASi0.7.2\n"));
    EXPECT_EQ(warnings(result),
              (std::vector<std::string>{
                  "8:1: warning: ASq0.7.1: this unit only monitors the AS-i bus; the external "
                  "master sets the slaves' outputs, not this program"}));
}

TEST(AsiCompile, TheImageCarriesTheSlaveTableAndReadsBackTheSame) {
    const auto result = compiler::compileText(
        asiProject(";@asi 00 mode=\"monitor_slave\" address=\"9\" optimize=\"immunity\"\n"
                   ";@asi_slave ASi0.3 type=\"safe_input\" model=\"URAX-C1\" "
                   "monitoring=\"simultaneous\" time_limit_ms=\"250\"\n"
                   ";@asi_slave ASi0.5 type=\"nonsafe_ab\" profile=\"S-7.A.E\" id1=\"6\"\n"
                   ";@asi_slave ASi0.5B type=\"combined_ab\"\n",
                   "Q0.0 = ASi0.3\n"));
    ASSERT_EQ(result.errors(), 0);
    ASSERT_EQ(result.images.size(), 1u);
    const compiler::AsiSetup& asi = result.images[0].asi;
    EXPECT_EQ(asi.slaveAddress, 9);
    ASSERT_EQ(asi.slaves.size(), 3u);
    EXPECT_EQ(asi.slaves[0].number, 3);
    EXPECT_EQ(asi.slaves[0].model, 2); // URAX-C1
    EXPECT_EQ(asi.slaves[0].timeLimitMs, 250u);
    EXPECT_EQ(asi.slaves[1].profile[1], 0xA);
    EXPECT_EQ(asi.slaves[1].profile[2], 0xE);
    EXPECT_EQ(asi.slaves[1].profile[3], 0x6);
    EXPECT_TRUE(asi.slaves[2].b);
    const auto read = compiler::decodeImage(compiler::encodeImage(result.images[0]));
    ASSERT_TRUE(std::holds_alternative<compiler::UnitImage>(read));
    EXPECT_EQ(std::get<compiler::UnitImage>(read), result.images[0]);
}

TEST(AsiCompile, TheSignatureChangesWithTheSlaveTableOnly) {
    const std::string code = "Q0.0 = ASi0.3\n";
    const auto plain = compiler::compileText(asiProject("", code));
    const auto same = compiler::compileText(asiProject(";@asi 00 mode=\"master\"\n", code));
    const auto defined =
        compiler::compileText(asiProject(";@asi_slave ASi0.3 type=\"safe_input\"\n", code));
    const auto simultaneous = compiler::compileText(
        asiProject(";@asi_slave ASi0.3 type=\"safe_input\" monitoring=\"simultaneous\"\n", code));
    ASSERT_EQ(plain.signatures.size(), 1u);
    ASSERT_EQ(defined.signatures.size(), 1u);
    EXPECT_EQ(plain.signatures[0], same.signatures[0]); // the defaults are no AS-i options
    EXPECT_NE(plain.signatures[0], defined.signatures[0]);
    EXPECT_NE(defined.signatures[0], simultaneous.signatures[0]);
}

TEST(AsiCompile, AReaderRefusesSlavesOutOfOrder) {
    compiler::UnitImage image;
    image.asi.slaves.resize(2);
    image.asi.slaves[0].number = 5;
    image.asi.slaves[0].type = 1;
    image.asi.slaves[1].number = 4;
    image.asi.slaves[1].type = 1;
    const auto read = compiler::decodeImage(compiler::encodeImage(image));
    ASSERT_TRUE(std::holds_alternative<compiler::ImageError>(read));
    EXPECT_EQ(std::get<compiler::ImageError>(read).message,
              "the AS-i slaves of the image are out of order");
}
