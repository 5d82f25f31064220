// SPDX-License-Identifier: GPL-3.0-or-later
#include "RandomCondition.h"
#include "RandomNetworks.h"
#include "RandomProgram.h"
#include "Sanitized.h"
#include "StepText.h"
#include "TruthTable.h"
#include "ladder/LadderToText.h"
#include "ladder/TextToLadder.h"
#include "lang/Printer.h"
#include "project/Annotation.h"
#include "project/Project.h"

#include <gtest/gtest.h>

namespace {

using namespace rs::ladder;
using rs::lang::Expr;
using rs::lang::ExprKind;

bool holdsTimer(const Expr& e) {
    if (e.kind == ExprKind::Timer)
        return true;
    for (const auto& child : e.children)
        if (holdsTimer(child))
            return true;
    return false;
}

// Random conditions with timers, edges and comparisons go to the ladder and
// back unchanged, and the ladder conducts exactly when the expression does.
TEST(RoundTripProperty, ConditionToLadderAndBackIsTheIdentityWithEqualTruthTables) {
    int tabulated = 0;
    int withTimers = 0;
    const unsigned cases = rs::test::randomCases(3000);
    for (unsigned seed = 1; seed <= cases; ++seed) {
        rs::test::RandomCondition random(seed);
        const Expr expr = random.expression(random.uniform(0, 4));
        const Circuit circuit = toCircuit(expr);
        const Expr back = toExpr(circuit);
        ASSERT_EQ(rs::lang::printExpression(back), rs::lang::printExpression(expr)) << seed;
        ASSERT_EQ(back, expr) << seed;
        const rs::test::TruthTable expected = rs::test::truthTable(expr);
        if (expected.rows.empty())
            continue; // too many inputs to tabulate
        ASSERT_EQ(rs::test::truthTable(circuit), expected) << rs::lang::printExpression(expr);
        if (holdsTimer(expr))
            ++withTimers;
        else
            ASSERT_EQ(rs::test::truthTable(circuit).rows, rs::test::algebraTable(expr).rows)
                << rs::lang::printExpression(expr);
        ++tabulated;
    }
    // The generator must keep most conditions small enough to tabulate.
    EXPECT_GT(tabulated, static_cast<int>(cases * 5 / 6));
    EXPECT_GT(withTimers, static_cast<int>(cases / 6));
}

// Whole programs (statements, comment lines, blank lines, trailing comments,
// records) go through the ladder model and come back line for line.
TEST(RoundTripProperty, StepsToLadderAndBackGiveTheSameLines) {
    int shared = 0;
    int compared = 0;
    for (unsigned seed = 1; seed <= 400; ++seed) {
        rs::test::RandomProgram program(seed);
        rs::test::RandomCondition random(seed);
        rs::lang::Document document = program.document();
        for (auto& unit : document.units)
            for (auto& step : unit.steps) {
                rs::test::addNetworkStructure(step, random);
                const StepLadder ladder = toLadder(step);
                ASSERT_EQ(toLines(ladder), step.lines) << "seed " << seed;
                ASSERT_EQ(rs::test::printLines(toLines(ladder)), rs::test::printLines(step.lines));
                for (const auto& network : ladder.networks)
                    for (const auto& item : network.items)
                        if (const auto* rung = std::get_if<Rung>(&item);
                            rung && rung->outputs.size() > 1)
                            ++shared;
                // The grouping is the project's: same networks, comments and statements.
                std::vector<rs::project::Network> networks;
                try {
                    networks = rs::project::networksOf(step);
                } catch (const rs::project::AnnotationError&) {
                    continue; // a comment that reads as a malformed record (see the report)
                }
                ASSERT_EQ(ladder.networks.size(), networks.size()) << "seed " << seed;
                for (std::size_t i = 0; i < networks.size(); ++i) {
                    EXPECT_EQ(ladder.networks[i].comment, networks[i].comment);
                    std::size_t statements = 0;
                    for (const auto* line : networks[i].lines)
                        statements += std::holds_alternative<rs::lang::Statement>(line->body);
                    EXPECT_EQ(static_cast<std::size_t>(statementCount(ladder.networks[i])),
                              statements);
                }
                ++compared;
            }
    }
    EXPECT_GT(shared, 50);
    EXPECT_GT(compared, 500);
}

} // namespace

namespace {

// Networks of random steps replaced by networks of other steps: the lines
// the run says change are the lines toLines writes for the whole new step,
// and the run is refused only where records of other networks change.
TEST(RoundTripProperty, ANetworkRunsLinesAreTheWholeStepsLinesWhereTheyChange) {
    int written = 0;
    int refused = 0;
    for (unsigned seed = 1; seed <= 300; ++seed) {
        rs::test::RandomProgram program(seed);
        rs::test::RandomCondition random(seed);
        rs::lang::Document document = program.document();
        std::vector<Network> donors;
        std::vector<StepLadder> ladders;
        for (auto& unit : document.units)
            for (auto& step : unit.steps) {
                rs::test::addNetworkStructure(step, random);
                ladders.push_back(toLadder(step));
                donors.insert(donors.end(), ladders.back().networks.begin(),
                              ladders.back().networks.end());
            }
        for (const auto& ladder : ladders) {
            const std::vector<rs::lang::Line> lines = toLines(ladder);
            const auto size = static_cast<int>(ladder.networks.size());
            const auto first = static_cast<std::size_t>(random.uniform(0, size));
            const auto removed = static_cast<std::size_t>(
                random.uniform(0, std::min(3, size - static_cast<int>(first))));
            std::vector<Network> added;
            for (int i = random.uniform(0, 3); i > 0 && !donors.empty(); --i)
                added.push_back(donors[static_cast<std::size_t>(
                    random.uniform(0, static_cast<int>(donors.size()) - 1))]);
            StepLadder changed = ladder;
            const auto at = changed.networks.begin() + static_cast<std::ptrdiff_t>(first);
            changed.networks.insert(
                changed.networks.erase(at, at + static_cast<std::ptrdiff_t>(removed)),
                added.begin(), added.end());

            const auto run = networkRunLines(ladder, first, removed, added);
            if (!run) {
                ++refused;
                continue;
            }
            std::vector<rs::lang::Line> spliced = lines;
            ASSERT_LE(run->first + run->removed, spliced.size());
            const auto from = spliced.begin() + static_cast<std::ptrdiff_t>(run->first);
            spliced.insert(spliced.erase(from, from + static_cast<std::ptrdiff_t>(run->removed)),
                           run->lines.begin(), run->lines.end());
            ASSERT_EQ(rs::test::printLines(spliced), rs::test::printLines(toLines(changed)))
                << "seed " << seed;
            ++written;
        }
    }
    EXPECT_GT(written, 300);
    EXPECT_GT(refused, 0);
    EXPECT_LT(refused * 4, written);
}

} // namespace
