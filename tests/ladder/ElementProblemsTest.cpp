// SPDX-License-Identifier: GPL-3.0-or-later
#include "ladder/ElementProblems.h"
#include "RandomCondition.h"
#include "StepText.h"
#include "ladder/TextToLadder.h"
#include "project/UnitText.h"

#include <gtest/gtest.h>

#include <sstream>

namespace {

using rs::lang::ElementNumber;

// The line (from 1) of the unit's text that holds `text`, and its column.
std::pair<int, int> placeOf(const std::string& unitText, const std::string& text) {
    std::istringstream lines(unitText);
    std::string line;
    for (int number = 1; std::getline(lines, line); ++number)
        if (const auto column = line.find(text); column != std::string::npos)
            return {number, static_cast<int>(column) + 1};
    return {0, 0};
}

TEST(ElementProblems, MessagesAreDrawnOnTheElementsTheyConcern) {
    const auto project = rs::test::projectWithCode("Lamp = EStop * I0.1\n"
                                                   "Q0.16 = I0.2 + I0.3\n");
    const std::string text = rs::project::unitText(project, 0);
    const auto [line1, estop] = placeOf(text, "EStop * I0.1");
    const auto [line2, i03] = placeOf(text, "I0.3");
    ASSERT_GT(line1, 0);
    ASSERT_GT(line2, 0);
    const rs::lang::Diagnostics diagnostics{
        {rs::lang::Severity::Error, line1, estop, "first"},
        {rs::lang::Severity::Warning, line1, estop + 1, "second"},
        {rs::lang::Severity::Error, line2, i03, "third"},
        {rs::lang::Severity::Error, line2, 1, "on the output"},
        {rs::lang::Severity::Error, 1, 1, "on no statement"},
    };
    const auto problems = rs::ladder::problemsByElement(project, 0, diagnostics);
    const std::map<ElementNumber, std::string> expected{
        {{0, 2}, "first\nsecond"}, // 1 is the series, 2 EStop
        {{1, 3}, "third"},         // 1 the parallel, 2 I0.2, 3 I0.3
        {{1, 0}, "on the output"},
    };
    EXPECT_EQ(problems, expected);
    EXPECT_TRUE(rs::ladder::problemsByElement(project, 0, {}).empty());
}

// The ladder's circuits number a condition's nodes exactly as the syntax tree
// does: the same count, and leaf i of the one is leaf i of the other.
TEST(ElementProblems, TheLadderNumbersEveryRandomConditionAsTheLanguageDoes) {
    for (unsigned seed = 1; seed <= 2000; ++seed) {
        rs::test::RandomCondition random(seed);
        const rs::lang::Expr expr = random.expression(random.uniform(0, 4));
        const rs::ladder::Circuit circuit = rs::ladder::toCircuit(expr);
        const rs::lang::PreOrderNumbering<rs::lang::Expr> text(expr, rs::lang::partsOf);
        const rs::lang::PreOrderNumbering<rs::ladder::Circuit> ladder(
            circuit, [](const rs::ladder::Circuit& c) -> const auto& { return c.parts; });
        ASSERT_EQ(text.nodes().size(), ladder.nodes().size()) << seed;
        for (std::size_t i = 0; i < text.nodes().size(); ++i) {
            const bool group = text.nodes()[i]->kind == rs::lang::ExprKind::And ||
                               text.nodes()[i]->kind == rs::lang::ExprKind::Or;
            ASSERT_EQ(group, !ladder.nodes()[i]->isElement()) << seed << " node " << i + 1;
            if (!group) {
                ASSERT_EQ(rs::ladder::toCircuit(*text.nodes()[i]), *ladder.nodes()[i]) << seed;
            }
        }
    }
}

} // namespace
