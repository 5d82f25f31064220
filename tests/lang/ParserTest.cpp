// SPDX-License-Identifier: GPL-3.0-or-later
#include "lang/Parser.h"
#include "lang/Printer.h"

#include <gtest/gtest.h>

using namespace rs::lang;

namespace {

constexpr const char* kParserHeader = "! pgm_pluto:00\nS0.0_0\n";

// The canonical text of one statement written in the main code of unit 0.
std::string canonicalStatement(const std::string& statement) {
    ParseResult result = parse(std::string(kParserHeader) + statement + "\n");
    if (!result.diagnostics.empty())
        return "error: " + result.diagnostics.front().message;
    const auto& lines = result.document.units.at(0).steps.at(0).lines;
    if (lines.size() != 1)
        return "lines: " + std::to_string(lines.size());
    return printStatement(std::get<Statement>(lines[0].body));
}

} // namespace

TEST(Parser, CanonicalSpellingIsUpperCaseWithSpacesAroundOperators) {
    EXPECT_EQ(canonicalStatement("q0.1=i0.0+i0.2*i1.0"), "Q0.1 = I0.0 + I0.2 * I1.0");
    EXPECT_EQ(canonicalStatement("Q0.1 = /I0.0 + I0.2 * I1.0"), "Q0.1 = /I0.0 + I0.2 * I1.0");
    EXPECT_EQ(canonicalStatement("Q10.3 = p(i10.2) * P(/I10.3)"), "Q10.3 = P(I10.2) * P(/I10.3)");
    EXPECT_EQ(canonicalStatement("M0.0 = /p(I0.0) * /n(I0.2)"), "M0.0 = /P(I0.0) * /N(I0.2)");
}

TEST(Parser, PrecedenceAndParenthesesMakeTheSameTreeAsTheLadder) {
    EXPECT_EQ(canonicalStatement("Q0.1 = (I0.0 + I0.2 * I1.0) * I0.1"),
              "Q0.1 = (I0.0 + I0.2 * I1.0) * I0.1");
    // Redundant parentheses do not change the series/parallel circuit.
    EXPECT_EQ(canonicalStatement("q0.2 = i0.12 * (i0.13 + m0.0) * ( (p(i0.14) * i0.02) + q0.2)"),
              "Q0.2 = I0.12 * (I0.13 + M0.0) * (P(I0.14) * I0.2 + Q0.2)");
    EXPECT_EQ(canonicalStatement("Q0.1 = ((I0.0))"), "Q0.1 = I0.0");
    EXPECT_EQ(canonicalStatement("Q0.1 = I0.0 * (I0.1 * I0.2)"), "Q0.1 = I0.0 * I0.1 * I0.2");
    EXPECT_EQ(canonicalStatement("Q0.1 = I0.0 + (I0.1 + I0.2)"), "Q0.1 = I0.0 + I0.1 + I0.2");
}

TEST(Parser, TimersKeepTheirSpellingAndNormaliseTheTime) {
    EXPECT_EQ(canonicalStatement("Q0.10 = I0.2 * T(5s10)"), "Q0.10 = I0.2 * T(5s10)");
    EXPECT_EQ(canonicalStatement("Q0.12 = I0.4 * /t(2s5)"), "Q0.12 = I0.4 * /T(2s50)");
    EXPECT_EQ(canonicalStatement("Q0.12 = I0.4 * tps(3S5)"), "Q0.12 = I0.4 * TPS(3s50)");
    EXPECT_EQ(canonicalStatement("Q0.13 = I0.5 * TOF(1s00)"), "Q0.13 = I0.5 * TOF(1s00)");
    EXPECT_EQ(canonicalStatement("Q0.1 = I0.5 * it(0s01)"), "Q0.1 = I0.5 * IT(0s01)");
    EXPECT_EQ(canonicalStatement("Q0.1 = I0.5 * TON(R0.5)"), "Q0.1 = I0.5 * TON(R0.5)");
}

TEST(Parser, ComparisonsAreOperands) {
    EXPECT_EQ(canonicalStatement("Q0.10 = (R0.98 >= 4)"), "Q0.10 = (R0.98>=4)");
    EXPECT_EQ(canonicalStatement("M0.10 = (R0.22 = R0.35) * I0.4"), "M0.10 = (R0.22=R0.35) * I0.4");
    EXPECT_EQ(canonicalStatement("Q0.12 = (SR0.40 < 180) * SM0.5"), "Q0.12 = (SR0.40<180) * SM0.5");
    EXPECT_EQ(canonicalStatement("M0.1 = (DR0.4 <= -5)"), "M0.1 = (DR0.4<=-5)");
    EXPECT_EQ(canonicalStatement("M0.1 = /(R0.1 = 5)"), "M0.1 = /(R0.1=5)");
}

TEST(Parser, EveryStatementForm) {
    EXPECT_EQ(canonicalStatement("m0.0"), "M0.0");
    EXPECT_EQ(canonicalStatement("s(q5.17) = i5.2"), "S(Q5.17) = I5.2");
    EXPECT_EQ(canonicalStatement("R(Q5.17)=I5.3"), "R(Q5.17) = I5.3");
    EXPECT_EQ(canonicalStatement("T(Q4.2) = P(I4.1)"), "T(Q4.2) = P(I4.1)");
    EXPECT_EQ(canonicalStatement("j(+1)=/i0.00*/i0.01"), "J(+1) = /I0.0 * /I0.1");
    EXPECT_EQ(canonicalStatement("J(-2)"), "J(-2)");
    EXPECT_EQ(canonicalStatement("J(01) = M0.1"), "J(1) = M0.1");
    EXPECT_EQ(canonicalStatement("R(S0.2) = I0.7"), "R(S0.2) = I0.7");
    EXPECT_EQ(canonicalStatement("S(R0.100.1) = I0.0"), "S(R0.100.1) = I0.0");
}

TEST(Parser, EveryAssignmentForm) {
    EXPECT_EQ(canonicalStatement("(R0.100++)"), "(R0.100++)");
    EXPECT_EQ(canonicalStatement("(R0.100 - -)"), "(R0.100--)");
    EXPECT_EQ(canonicalStatement("(R0.100+=77)"), "(R0.100 += 77)");
    EXPECT_EQ(canonicalStatement("(R0.100 - = 77)"), "(R0.100 -= 77)");
    EXPECT_EQ(canonicalStatement("(R0.100 \xE2\x80\x93= 77)"), "(R0.100 -= 77)");
    EXPECT_EQ(canonicalStatement("(R0.100 *= 2)"), "(R0.100 *= 2)");
    EXPECT_EQ(canonicalStatement("(R0.100 /= R0.102)"), "(R0.100 /= R0.102)");
    EXPECT_EQ(canonicalStatement("(R0.100 = 1)"), "(R0.100 = 1)");
    EXPECT_EQ(canonicalStatement("(R0.100 = -32768)"), "(R0.100 = -32768)");
    EXPECT_EQ(canonicalStatement("(R0.100=R0.102/R0.104)"), "(R0.100 = R0.102 / R0.104)");
    EXPECT_EQ(canonicalStatement("(R0.100=DR0.102/R0.104)"), "(R0.100 = DR0.102 / R0.104)");
    EXPECT_EQ(canonicalStatement("(DR0.4.Lo += DR0.4.Hi)"), "(DR0.4.Lo += DR0.4.Hi)");
    EXPECT_EQ(canonicalStatement("(R1.34+=R1.35) = P(I1.3)"), "(R1.34 += R1.35) = P(I1.3)");
    EXPECT_EQ(canonicalStatement("(R0.9++) = (R0.12 > R0.14)"), "(R0.9++) = (R0.12>R0.14)");
    EXPECT_EQ(canonicalStatement("(SR0.10 = 201)"), "(SR0.10 = 201)");
}

TEST(Parser, DocumentStructure) {
    ParseResult result = parse("$name Example, manual\n"
                               "! id_pluto:00=ffff00007FA3\n"
                               "! I0.0=MuteSensor1 ; global\n"
                               "! pgm_pluto:00\n"
                               "! i0.5,c_pulse,non_inv,no_filt\n"
                               "s0.0_0 ; main\n"
                               "Q0.1 = MuteSensor1\n"
                               "S0.1_0\n"
                               "J(+1) = I0.1\n");
    ASSERT_TRUE(result.diagnostics.empty()) << result.diagnostics.front().message;
    const Document& doc = result.document;
    ASSERT_EQ(doc.preamble.size(), 3u);
    EXPECT_EQ(std::get<Directive>(doc.preamble[0].body).text, "Example, manual");
    const auto& id = std::get<IdDeclaration>(std::get<Declaration>(doc.preamble[1].body).body);
    EXPECT_EQ(id.idfix, "FFFF00007FA3");
    EXPECT_EQ(doc.preamble[2].comment, std::optional<std::string>(" global"));
    ASSERT_EQ(doc.units.size(), 1u);
    EXPECT_EQ(doc.units[0].station(), 0);
    ASSERT_EQ(doc.units[0].steps.size(), 2u);
    EXPECT_EQ(doc.units[0].steps[0].comment, std::optional<std::string>(" main"));
    EXPECT_EQ(doc.units[0].steps[1].address, (StepAddress{0, 1, 0}));
    EXPECT_EQ(print(doc), "$name Example, manual\n"
                          "! id_pluto:00=FFFF00007FA3\n"
                          "! I0.0=MuteSensor1             ; global\n"
                          "! pgm_pluto:00\n"
                          "! I0.5,c_pulse,non_inv,no_filt\n"
                          "S0.0_0                         ; main\n"
                          "Q0.1 = MuteSensor1\n"
                          "S0.1_0\n"
                          "J(+1) = I0.1\n");
}

TEST(Parser, DeclarationsOfEveryKind) {
    ParseResult result = parse("! id_pluto_Double:01=000000000000\n"
                               "! ID_PLUTO_ASI:02=000000000000\n"
                               "! id_pluto_b42_asi:03=000000000000\n"
                               "! type_pluto:01=b46,IS3\n"
                               "! type_pluto:02=asi\n"
                               "! pgm_pluto:01\n"
                               "! ia1.0,counter_updown\n"
                               "! Q1.2,NO_TEST_PULSE\n"
                               "! iq1.14,a_pulse\n");
    ASSERT_TRUE(result.diagnostics.empty()) << result.diagnostics.front().message;
    EXPECT_EQ(print(result.document), "! id_pluto_Double:01=000000000000\n"
                                      "! id_pluto_ASi:02=000000000000\n"
                                      "! id_pluto_B42_ASi:03=000000000000\n"
                                      "! type_pluto:01=B46,is3\n"
                                      "! type_pluto:02=ASi\n"
                                      "! pgm_pluto:01\n"
                                      "! IA1.0,counter_updown\n"
                                      "! Q1.2,no_test_pulse\n"
                                      "! IQ1.14,a_pulse\n");
}

TEST(Parser, CommentsAndBlankLinesAreKept) {
    const std::string source = ";*****\n"
                               ";\n"
                               "\n"
                               "\n"
                               "! pgm_pluto:00 ;   unit zero  \n"
                               "S0.0_0\n"
                               "Q0.3 = Q0.2\n"
                               "        ; explains the line above\n"
                               "; at the margin\n";
    ParseResult result = parse(source);
    ASSERT_TRUE(result.diagnostics.empty());
    EXPECT_EQ(print(result.document), ";*****\n"
                                      ";\n"
                                      "\n"
                                      "! pgm_pluto:00                 ;   unit zero\n"
                                      "S0.0_0\n"
                                      "Q0.3 = Q0.2\n"
                                      "                               ; explains the line above\n"
                                      "; at the margin\n");
}

TEST(Parser, LongCodeGetsOneSpaceBeforeItsComment) {
    ParseResult result =
        parse(std::string(kParserHeader) + "J(+1) = /I0.0 * /I0.1 * (SR0.43<100) ; both sensors\n");
    ASSERT_TRUE(result.diagnostics.empty());
    EXPECT_NE(print(result.document).find("(SR0.43<100) ; both sensors\n"), std::string::npos);
}

TEST(Parser, CarriageReturnsAreTolerated) {
    ParseResult result = parse("! pgm_pluto:00\r\nS0.0_0\r\nQ0.1 = I0.0 ; c\r\n");
    ASSERT_TRUE(result.diagnostics.empty());
    EXPECT_EQ(print(result.document),
              "! pgm_pluto:00\nS0.0_0\nQ0.1 = I0.0                    ; c\n");
}
