// SPDX-License-Identifier: GPL-3.0-or-later
#include "lang/Ast.h"
#include "lang/Parser.h"

#include <gtest/gtest.h>

namespace {

using namespace rs::lang;

// A comparison with a constant and a timer with a constant preset hold no
// operand apart; with registers they do, and read as before.
TEST(OptionalApart, OnlyARegisterOperandIsHeld) {
    const ParseResult parsed = parse("! pgm_pluto:00\nS0.0_0\nQ0.1 = (R0.1>5) * TON(1s00)\n"
                                     "Q0.2 = (R0.1>R0.2) * TON(R0.3)\n");
    ASSERT_TRUE(parsed.diagnostics.empty());
    const auto& lines = parsed.document.units.front().steps.front().lines;
    const auto& constants = std::get<Statement>(lines[0].body).condition->children;
    const auto& registers = std::get<Statement>(lines[1].body).condition->children;
    EXPECT_FALSE(constants[0].right.operand);
    EXPECT_EQ(constants[0].right.constant, 5);
    EXPECT_FALSE(constants[1].preset.registerOperand.has_value());
    ASSERT_TRUE(registers[0].right.operand);
    EXPECT_EQ(registers[0].right.operand->address,
              (Address{AddressKind::Register, 0, 2, -1, false}));
    ASSERT_TRUE(registers[1].preset.registerOperand.has_value());
    EXPECT_EQ(registers[1].preset.registerOperand->address,
              (Address{AddressKind::Register, 0, 3, -1, false}));
    // What makes a condition's node and a line small (issue 23).
    EXPECT_LE(sizeof(Expr), 160U);
    EXPECT_LE(sizeof(Line), 288U);
}

TEST(OptionalApart, CopiesAreDeepAndCompareByValue) {
    OptionalApart<Operand> a;
    EXPECT_EQ(a, std::nullopt);
    EXPECT_THROW((void)a.value(), std::bad_optional_access);
    a = Operand{"Speed", {}, {}};
    OptionalApart<Operand> b = a;
    ASSERT_TRUE(b.has_value());
    b->name = "Other";
    EXPECT_EQ(a->name, "Speed");
    EXPECT_NE(a, b);
    b = a;
    EXPECT_EQ(a, b);
    b = std::nullopt;
    EXPECT_FALSE(b);
    EXPECT_NE(a, b);
    OptionalApart<Operand> moved = std::move(a);
    EXPECT_EQ(moved->name, "Speed");
}

} // namespace
