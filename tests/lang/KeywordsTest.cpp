// SPDX-License-Identifier: GPL-3.0-or-later
#include "lang/Keywords.h"
#include "lang/Parser.h"
#include "lang/Printer.h"
#include "lang/TextCase.h"

#include <gtest/gtest.h>

#include <string>

// Every word of the keyword table is read by the parser where the language
// allows it and printed back as the table spells it, whatever its case in the
// source: a word added to the table without the parser knowing it fails here.

using namespace rs::lang;

namespace {

constexpr const char* kKeywordsHeader = "! pgm_pluto:00\nS0.0_0\n";

std::string canonicalKeywordStatement(const std::string& statement) {
    ParseResult result = parse(std::string(kKeywordsHeader) + statement + "\n");
    if (!result.diagnostics.empty())
        return "error: " + result.diagnostics.front().message;
    const auto& lines = result.document.units.at(0).steps.at(0).lines;
    if (lines.size() != 1)
        return "lines: " + std::to_string(lines.size());
    return printStatement(std::get<Statement>(lines[0].body));
}

std::string canonicalDocument(const std::string& source) {
    ParseResult result = parse(source);
    if (!result.diagnostics.empty())
        return "error: " + result.diagnostics.front().message;
    return print(result.document);
}

std::string spelled(std::string_view word) {
    return std::string(word);
}

} // namespace

TEST(Keywords, EveryInstructionWordIsParsedAndPrintedBack) {
    for (std::string_view word : instructionWords()) {
        const std::string w = spelled(word);
        const std::string lower = toLower(word);
        bool read = false;
        if (word == kRisingEdgeWord || word == kFallingEdgeWord) {
            EXPECT_EQ(canonicalKeywordStatement("Q0.1 = " + lower + "(I0.0)"),
                      "Q0.1 = " + w + "(I0.0)");
            read = true;
        }
        if (timerSpellingOf(word)) {
            EXPECT_EQ(canonicalKeywordStatement("Q0.1 = I0.5 * " + lower + "(1s00)"),
                      "Q0.1 = I0.5 * " + w + "(1s00)");
            read = true;
        }
        if (word == statementWord(StatementKind::Set) ||
            word == statementWord(StatementKind::Reset) ||
            word == statementWord(StatementKind::Toggle)) {
            EXPECT_EQ(canonicalKeywordStatement(lower + "(q0.1) = i0.0"), w + "(Q0.1) = I0.0");
            read = true;
        }
        if (word == statementWord(StatementKind::SequenceReset)) {
            EXPECT_EQ(canonicalKeywordStatement(lower + "(s0.2) = i0.7"), w + "(S0.2) = I0.7");
        }
        if (word == statementWord(StatementKind::Jump)) {
            EXPECT_EQ(canonicalKeywordStatement(lower + "(+1) = I0.0"), w + "(+1) = I0.0");
            read = true;
        }
        EXPECT_TRUE(read) << w << " is in the table but no form of the language uses it here";
    }
}

TEST(Keywords, EveryDeclarationWordIsParsedAndPrintedBack) {
    for (auto family :
         {UnitFamily::Pluto, UnitFamily::Double, UnitFamily::ASi, UnitFamily::B42ASi}) {
        const std::string line = "! " + spelled(idKeyword(family)) + ":01=000000000000\n";
        EXPECT_EQ(canonicalDocument(toUpper(line)), line);
    }
    for (std::string_view type : kUnitTypeWords) {
        const std::string line = "! " + spelled(kTypeKeyword) + ":01=" + spelled(type) + "\n";
        EXPECT_EQ(canonicalDocument(toLower(line)), line);
        for (int set : {2, 3}) {
            const std::string withSet = "! " + spelled(kTypeKeyword) + ":01=" + spelled(type) +
                                        "," + spelled(instructionSetWord(set)) + "\n";
            EXPECT_EQ(canonicalDocument(toUpper(withSet)), withSet);
        }
    }
    const std::string program = "! " + spelled(kProgramKeyword) + ":01\n";
    EXPECT_EQ(canonicalDocument(toUpper(program)), program);
}

TEST(Keywords, EveryIoOptionIsParsedAndPrintedBack) {
    for (std::string_view option : kIoOptionWords) {
        const std::string source = "! pgm_pluto:00\n! I0.5," + spelled(option) + "\n";
        EXPECT_EQ(canonicalDocument(toUpper(source)), source);
    }
}

TEST(Keywords, EveryOperatorIsParsedAndPrintedBack) {
    for (auto op : {CompareOp::Equal, CompareOp::Greater, CompareOp::Less, CompareOp::GreaterEqual,
                    CompareOp::LessEqual}) {
        const std::string w = spelled(compareWord(op));
        EXPECT_EQ(canonicalKeywordStatement("Q0.1 = (R0.1 " + w + " 4)"),
                  "Q0.1 = (R0.1" + w + "4)");
        EXPECT_EQ(compareOpOf(w), op);
    }
    for (auto op : {AssignOp::Increment, AssignOp::Decrement}) {
        const std::string w = spelled(assignWord(op));
        EXPECT_EQ(canonicalKeywordStatement("(R0.100 " + w + ")"), "(R0.100" + w + ")");
    }
    for (auto op : {AssignOp::AddAssign, AssignOp::SubAssign, AssignOp::MulAssign,
                    AssignOp::DivAssign, AssignOp::Copy}) {
        const std::string w = spelled(assignWord(op));
        EXPECT_EQ(canonicalKeywordStatement("(R0.100" + w + "7)"), "(R0.100 " + w + " 7)");
    }
    for (auto op : {BinaryOp::Add, BinaryOp::Sub, BinaryOp::Mul, BinaryOp::Div}) {
        const std::string w = spelled(binaryWord(op));
        EXPECT_EQ(canonicalKeywordStatement("(R0.100=R0.1" + w + "R0.2)"),
                  "(R0.100 = R0.1 " + w + " R0.2)");
    }
}
