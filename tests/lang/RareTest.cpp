// SPDX-License-Identifier: GPL-3.0-or-later
#include "lang/Ast.h"
#include "lang/Parser.h"

#include <gtest/gtest.h>

namespace {

using namespace rs::lang;

// A statement that is no assignment holds none (issue 23: it is what makes
// a line of a large project small), and reads as the default one.
TEST(Rare, OnlyAnAssignmentHoldsOne) {
    const ParseResult parsed = parse("! pgm_pluto:00\nS0.0_0\nQ0.1 = I0.0\n(R0.1 += 2) = I0.1\n");
    ASSERT_TRUE(parsed.diagnostics.empty());
    const auto& lines = parsed.document.units.front().steps.front().lines;
    const auto& coil = std::get<Statement>(lines[0].body);
    const auto& assign = std::get<Statement>(lines[1].body);
    EXPECT_FALSE(coil.assignment.held());
    EXPECT_EQ(*coil.assignment, Assignment{});
    EXPECT_TRUE(assign.assignment.held());
    EXPECT_EQ(assign.assignment->op, AssignOp::AddAssign);
    EXPECT_LT(sizeof(Line), 500U);
}

TEST(Rare, CopiesAreDeepAndTheDefaultIsHeldAsNone) {
    Rare<Assignment> a;
    a->op = AssignOp::Increment; // written: held
    ASSERT_TRUE(a.held());
    Rare<Assignment> b = a;
    b->op = AssignOp::Decrement;
    EXPECT_EQ(a->op, AssignOp::Increment);
    EXPECT_FALSE(a == b);
    b = Assignment{};
    EXPECT_FALSE(b.held());
    EXPECT_TRUE(b == Rare<Assignment>{});
    Statement statement;
    statement.assignment = a;
    const Statement copy = statement;
    EXPECT_TRUE(copy == statement);
}

} // namespace
