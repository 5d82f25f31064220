// SPDX-License-Identifier: GPL-3.0-or-later
// Program text at and past the reader's limits: deep nesting, long chains,
// other line ends and control characters.

#include "lang/NameResolver.h"
#include "lang/Parser.h"
#include "lang/Printer.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace rs::lang;

namespace {

constexpr const char* kExtremeHeader = "! pgm_pluto:00\nS0.0_0\n";

// "I0.1 + I0.2 * (I0.3 + I0.4 * (...))": each level of parentheses adds an OR
// and an AND to the tree, the deepest tree a given nesting can make.
std::string alternating(int levels) {
    std::string text = "I0.0";
    for (int level = levels; level > 0; --level)
        text = "I0.1 + I0.2 * (" + text + ")";
    return text;
}

int depthOf(const Expr& expr) {
    int deepest = 0;
    for (const auto& child : expr.children)
        deepest = std::max(deepest, depthOf(child));
    return deepest + 1;
}

const Statement& onlyStatement(const ParseResult& result) {
    return std::get<Statement>(result.document.units.at(0).steps.at(0).lines.at(0).body);
}

} // namespace

TEST(ExtremeInput, ParenthesesNestUpToTheLimit) {
    const ParseResult result =
        parse(std::string(kExtremeHeader) + "Q0.0 = " + alternating(kMaxExpressionDepth) + "\n");
    ASSERT_TRUE(result.diagnostics.empty()) << result.diagnostics.front().message;
    EXPECT_EQ(depthOf(*onlyStatement(result).condition), 2 * kMaxExpressionDepth + 1);
    // The canonical text keeps the nesting, so it reads back.
    const std::string printed = print(result.document);
    EXPECT_EQ(parse(printed).document, result.document);
}

TEST(ExtremeInput, OneLevelMoreIsAnErrorAtTheParenthesisThatGoesTooDeep) {
    const std::string statement =
        "Q0.0 = " + std::string(101, '(') + "I0.0" + std::string(101, ')') + "\nQ0.1 = I0.1\n";
    const ParseResult result = parse(std::string(kExtremeHeader) + statement);
    ASSERT_EQ(result.diagnostics.size(), 1u);
    EXPECT_EQ(result.diagnostics[0].line, 3);
    EXPECT_EQ(result.diagnostics[0].column, 8 + 100);
    EXPECT_EQ(result.diagnostics[0].message, "expression nested deeper than 100 levels");
    // The next line is read as usual.
    EXPECT_EQ(result.document.units.at(0).steps.at(0).lines.size(), 1u);
}

TEST(ExtremeInput, TenThousandParenthesesAreOneErrorNotAStackOverflow) {
    const ParseResult result =
        parse(std::string(kExtremeHeader) + "Q0.0 = " + std::string(10000, '(') + "I0.0" +
              std::string(10000, ')') + "\n");
    ASSERT_EQ(result.diagnostics.size(), 1u);
    EXPECT_EQ(result.diagnostics[0].column, 108);
}

TEST(ExtremeInput, ALongChainIsOneFlatNode) {
    std::string chain = "I0.0";
    for (int i = 1; i < 100000; ++i)
        chain += " + I0." + std::to_string(i % 8);
    ParseResult result = parse(std::string(kExtremeHeader) + "Q0.0 = " + chain + "\n");
    ASSERT_TRUE(result.diagnostics.empty());
    const Expr& condition = *onlyStatement(result).condition;
    EXPECT_EQ(condition.kind, ExprKind::Or);
    EXPECT_EQ(condition.children.size(), 100000u);
    EXPECT_EQ(depthOf(condition), 2);
    EXPECT_TRUE(resolveNames(result.document).empty());
    EXPECT_EQ(printStatement(onlyStatement(result)), "Q0.0 = " + chain);
}

TEST(ExtremeInput, ACarriageReturnAloneEndsALineAsLfAndCrLfDo) {
    const std::string lf = "$name Ends\n! pgm_pluto:00\nS0.0_0\n; a comment\nQ0.0 = I0.0 ; on\n\n"
                           "Q0.1 = I0.1 +\n";
    std::string cr = lf;
    std::replace(cr.begin(), cr.end(), '\n', '\r');
    std::string crlf;
    for (char c : lf)
        crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    const ParseResult fromLf = parse(lf);
    for (const std::string& text : {cr, crlf}) {
        const ParseResult other = parse(text);
        EXPECT_EQ(other.document, fromLf.document);
        EXPECT_EQ(print(other.document), print(fromLf.document));
        ASSERT_EQ(other.diagnostics.size(), 1u);
        EXPECT_EQ(other.diagnostics[0].line, 7);
        EXPECT_EQ(other.diagnostics[0].column, 14);
    }
    EXPECT_EQ(std::get<Directive>(fromLf.document.preamble.at(0).body).text, "Ends");
}

TEST(ExtremeInput, ControlCharactersInAMessageAreShownVisibly) {
    const ParseResult result =
        parse(std::string(kExtremeHeader) + "Q0.0 = I0.0 " + std::string("\0\x01\x7F", 3) + "\n");
    ASSERT_EQ(result.diagnostics.size(), 1u);
    EXPECT_EQ(result.diagnostics[0].message, "unexpected '\\0' after the statement");
    EXPECT_EQ(visibleText(std::string("a\0b\tc\x01\x7F\r\n", 9)), "a\\0b\\tc\\x01\\x7F\\r\\n");
    EXPECT_EQ(formatDiagnostic("f.sps", {Severity::Error, 1, 2, std::string("x\0y", 3)}),
              "f.sps:1:2: error: x\\0y");
}
