// SPDX-License-Identifier: GPL-3.0-or-later
#include "lang/Parser.h"
#include "lang/Printer.h"

#include <gtest/gtest.h>

using namespace rs::lang;

namespace {

// "LINE:COLUMN: message" of every diagnostic, for one statement in unit 0's main code
// (the statement is on line 3).
std::vector<std::string> diagnose(const std::string& source) {
    std::vector<std::string> out;
    for (const auto& d : parse(source).diagnostics)
        out.push_back(std::to_string(d.line) + ":" + std::to_string(d.column) + ": " + d.message);
    return out;
}

std::string statementError(const std::string& statement) {
    auto all = diagnose("! pgm_pluto:00\nS0.0_0\n" + statement + "\n");
    return all.empty() ? "no error" : all.front();
}

} // namespace

TEST(Diagnostics, PointAtTheOffendingToken) {
    EXPECT_EQ(statementError("Q0.1 = I0.0 +"), "3:14: expected an operand after '+'");
    EXPECT_EQ(statementError("Q0.1 = I0.0 * "), "3:15: expected an operand after '*'");
    EXPECT_EQ(statementError("Q0.1 ="), "3:7: expected a condition after '='");
    EXPECT_EQ(statementError("Q0.1 = (I0.0 + I0.1"),
              "3:20: expected ')', found the end of the line");
    EXPECT_EQ(statementError("Q0.1 = I0.0 I0.1"), "3:13: unexpected 'I0.1' after the statement");
    EXPECT_EQ(statementError("Q0.1 = /(I0.0 + I0.1)"),
              "3:8: negation applies to one operand, not to a group in parentheses");
    EXPECT_EQ(statementError("Q0.1 = I0.0 * TON(5)"),
              "3:19: a time needs the decimal sign 's', as in 5s00");
    EXPECT_EQ(statementError("Q0.1 = I0.0 * TON(0.5)"),
              "3:19: a time is written with the decimal sign 's': 0s50, not 0.5");
    EXPECT_EQ(statementError("Q0.1 = TPS(12.345)"),
              "3:12: a time is written with the decimal sign 's': 12s34, not 12.345");
    EXPECT_EQ(statementError("Q0.1 = TON(R0.5)"), "no error");
    EXPECT_EQ(statementError("Q0.1 = TON(1s234)"),
              "3:12: a time has at most two decimals (hundredths of a second): '1s234'");
    EXPECT_EQ(
        statementError("Q0.1 = T(Q0.2)"),
        "3:10: T(Q0.2) toggles an output; it can only start a statement: T(Q0.2) = condition");
    EXPECT_EQ(
        statementError("Q0.1 = X(I0.0)"),
        "3:8: unknown function 'X('; conditions may use P(, N(, TON(, TPS(, TOF(, T( and IT(");
    EXPECT_EQ(statementError("Q0.1 = R0.1"),
              "3:8: R0.1 holds a number; compare it, as in (R0.1>0)");
    EXPECT_EQ(statementError("R0.1 = I0.0"),
              "3:1: R0.1 holds a number, not a bit; only Q, M, GM, IQ, SM or a register bit can be "
              "switched");
    EXPECT_EQ(statementError("Q0.1 = 5"),
              "3:8: a number cannot be a condition; compare a register with it, as in (R0.1>5)");
    EXPECT_EQ(statementError("Q0.1 = I0.1x"), "3:8: malformed address 'I0.1x'");
    EXPECT_EQ(statementError("(R0.1 ? 5)"), "3:7: expected ++, --, +=, -=, *=, /= or = after the "
                                            "register, found '?'");
    EXPECT_EQ(statementError("(R0.1 += Q0.1)"),
              "3:10: Q0.1 is not a register; expected a register or a number");
    EXPECT_EQ(
        statementError("P(I0.0) = I0.1"),
        "3:1: a statement cannot start with P(...); write the output first, as in Q0.1 = P(...)");
    EXPECT_EQ(statementError("Q0.1 = S(Q0.2)"),
              "3:8: S(...) is an instruction, not a condition: it can only start a statement");
    EXPECT_EQ(statementError("J(x)"), "3:3: expected a step number in J(...), found 'x'");
    EXPECT_EQ(statementError("Q0.1 = //I0.0"), "3:9: double negation '//' : remove both slashes");
    EXPECT_EQ(statementError("S0.1 = I0.0"),
              "3:1: a sequence cannot be a coil; reset it with R(S0.1)");
    EXPECT_EQ(statementError("Q0.1 = I0.0 # x"), "3:13: unexpected '#' after the statement");
}

TEST(Diagnostics, DeclarationErrors) {
    EXPECT_EQ(
        diagnose("! id_pluto:00=12345\n"),
        std::vector<std::string>{"1:15: the IDFIX number must be 12 hexadecimal digits "
                                 "(000000000000 when no identifier is connected), found '12345'"});
    EXPECT_EQ(diagnose("! type_pluto:00=B99\n"),
              std::vector<std::string>{"1:17: unknown unit type 'B99'; expected one of A16 A20 B16 "
                                       "B20 S20 B22 D20 O2 B46 S46 D45 ASi B42_ASi"});
    EXPECT_EQ(
        diagnose("! pgm_pluto:00\n! I0.1,a_pulse,inverted\n"),
        std::vector<std::string>{"2:16: unknown I/O option 'inverted'; expected a_pulse, "
                                 "b_pulse, c_pulse, static, non_inv, no_filt, x_talk, "
                                 "no_test_pulse, voltage, current, counter_up or counter_updown"});
    EXPECT_EQ(diagnose("! I0.1,a_pulse\n"),
              std::vector<std::string>{"1:1: I/O declarations belong to a unit's code: put them "
                                       "after '! pgm_pluto:NN'"});
    EXPECT_EQ(diagnose("! pgm_pluto\n"),
              std::vector<std::string>{"1:12: expected ':' and a station number, found the end of "
                                       "the line"});
    EXPECT_EQ(
        diagnose("! pgm_pluto:00\nS0.0_0\n! I0.0=Late\n"),
        std::vector<std::string>{"3:1: declarations come before the first step of a unit's code"});
}

TEST(Diagnostics, UnknownDirectivesAreWarningsAndKept) {
    ParseResult result = parse("$name x\n$author Someone\n");
    ASSERT_EQ(result.diagnostics.size(), 1u);
    EXPECT_EQ(result.diagnostics[0].severity, Severity::Warning);
    EXPECT_EQ(result.diagnostics[0].message, "unknown directive '$author'; kept as written");
    EXPECT_EQ(print(result.document), "$name x\n$author Someone\n");
    EXPECT_EQ(diagnose("! pgm_pluto:00\n$name late\n"),
              std::vector<std::string>{
                  "2:1: a '$' directive belongs at the top of the file, before '! pgm_pluto'"});
}

TEST(Diagnostics, StructureErrors) {
    EXPECT_EQ(
        diagnose("Q0.1 = I0.0\n"),
        std::vector<std::string>{"1:1: a statement before '! pgm_pluto' and a step header such "
                                 "as S0.0_0"});
    EXPECT_EQ(diagnose("! pgm_pluto:03\nQ3.1 = I3.0\n"),
              std::vector<std::string>{"2:1: a statement outside a step: add a step header such as "
                                       "S3.0_0"});
    EXPECT_EQ(diagnose("! pgm_pluto:03\nS0.0_0\n"),
              std::vector<std::string>{"2:1: step S0.0_0 is in the code of unit 3; write S3.0_0"});
    EXPECT_EQ(diagnose("S0.0_0\n"),
              std::vector<std::string>{"1:1: step S0.0_0 before '! pgm_pluto': declare which unit "
                                       "the code is for first"});
    EXPECT_EQ(diagnose("! pgm_pluto:00\nS0.0_0 Q0.1 = I0.0\n"),
              std::vector<std::string>{"2:8: unexpected 'Q0.1' after the step header"});
}

TEST(Diagnostics, EveryBadLineIsReportedAndGoodLinesAreKept) {
    ParseResult result = parse("! pgm_pluto:00\n"
                               "S0.0_0\n"
                               "Q0.1 = I0.0 +\n"
                               "Q0.2 = I0.1\n"
                               "Q0.3 = * I0.1\n"
                               "Q0.4 = I0.2 ; fine\n"
                               "(R0.1 += )\n");
    ASSERT_EQ(result.diagnostics.size(), 3u);
    EXPECT_EQ(result.diagnostics[0].line, 3);
    EXPECT_EQ(result.diagnostics[1].line, 5);
    EXPECT_EQ(result.diagnostics[1].column, 8);
    EXPECT_EQ(result.diagnostics[2].line, 7);
    EXPECT_EQ(print(result.document),
              "! pgm_pluto:00\nS0.0_0\nQ0.2 = I0.1\nQ0.4 = I0.2                    ; fine\n");
}

TEST(Diagnostics, FormatMatchesTheCommandLineContract) {
    Diagnostic d{Severity::Warning, 12, 4, "unconfigured I/O"};
    EXPECT_EQ(formatDiagnostic("a.sps", d), "a.sps:12:4: warning: unconfigured I/O");
    d.severity = Severity::Error;
    EXPECT_EQ(formatDiagnostic("a.sps", d), "a.sps:12:4: error: unconfigured I/O");
}
