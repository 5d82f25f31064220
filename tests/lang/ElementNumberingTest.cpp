// SPDX-License-Identifier: GPL-3.0-or-later
#include "lang/ElementNumbering.h"
#include "lang/Parser.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using rs::lang::ElementNumber;

const char* kProgram = "! pgm_pluto:00\n"               // line 1
                       "S0.0_0\n"                       // 2
                       "Q0.0 = I0.0 * (I0.1 + /I0.2)\n" // 3
                       "; a note\n"                     // 4
                       "Q0.1 = I0.3\n"                  // 5
                       "S0.1_0\n"                       // 6
                       "Q0.2 = I0.4\n";                 // 7

rs::lang::UnitProgram unit() {
    const auto parsed = rs::lang::parse(kProgram);
    EXPECT_TRUE(parsed.diagnostics.empty()) << parsed.diagnostics.front().message;
    return parsed.document.units.at(0);
}

TEST(ElementNumbering, StatementsAreNumberedInFileOrderAcrossSteps) {
    std::vector<std::pair<std::uint32_t, int>> seen; // number, line
    rs::lang::forEachStatement(
        unit(), [&](const rs::lang::Step&, const rs::lang::Statement& s, std::uint32_t number) {
            seen.emplace_back(number, s.location.line);
        });
    const std::vector<std::pair<std::uint32_t, int>> expected{{0, 3}, {1, 5}, {2, 7}};
    EXPECT_EQ(seen, expected);
}

// Q0.0 = I0.0 * (I0.1 + /I0.2): 1 the series, 2 I0.0, 3 the parallel, 4 I0.1, 5 /I0.2.
TEST(ElementNumbering, AMessageIsPlacedOnTheLastElementStartingAtOrBeforeItsColumn) {
    const auto program = unit();
    const std::string line = "Q0.0 = I0.0 * (I0.1 + /I0.2)";
    auto at = [&](const std::string& text) {
        return rs::lang::elementAt(program, 3, static_cast<int>(line.find(text)) + 1);
    };
    EXPECT_EQ(at("Q0.0"), (ElementNumber{0, 0})); // before the condition: the output
    EXPECT_EQ(at("I0.0"), (ElementNumber{0, 2}));
    EXPECT_EQ(at("("), (ElementNumber{0, 2}));
    EXPECT_EQ(at("I0.1"), (ElementNumber{0, 4}));
    EXPECT_EQ(at("/I0.2"), (ElementNumber{0, 5}));
    EXPECT_EQ(rs::lang::elementAt(program, 7, 8), (ElementNumber{2, 1}));
    EXPECT_EQ(rs::lang::elementAt(program, 4, 1), std::nullopt); // a comment line
    EXPECT_EQ(rs::lang::elementAt(program, 99, 1), std::nullopt);
}

TEST(ElementNumbering, AWalkOutOfPreOrderIsCaught) {
    const auto program = unit();
    const auto& statement = std::get<rs::lang::Statement>(program.steps[0].lines[0].body);
    rs::lang::PreOrderNumbering<rs::lang::Expr> numbering(*statement.condition, rs::lang::partsOf);
    const rs::lang::Expr& series = *statement.condition;
    EXPECT_EQ(numbering.number(series), 1);
    EXPECT_THROW(numbering.number(series.children[1]), std::logic_error); // skips I0.0
}

} // namespace
