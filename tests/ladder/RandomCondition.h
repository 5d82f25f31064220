// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/Ast.h"

#include <random>

namespace rs::test {

// Random conditions in canonical shape over a small pool of operands, so that
// the same contact, comparison or name comes up more than once and a truth
// table over them says something. Every leaf kind of the language occurs:
// contacts, the four edges (also of a negated operand), the five timer
// spellings (negated too, constant or register preset) and comparisons.
class RandomCondition {
public:
    explicit RandomCondition(unsigned seed) : m_random(seed) {}

    lang::Expr expression(int depth);
    lang::Expr leaf();
    lang::Operand bit();

    int uniform(int low, int high) {
        return std::uniform_int_distribution<int>(low, high)(m_random);
    }
    bool chance(int percent) { return uniform(1, 100) <= percent; }

private:
    std::mt19937 m_random;
};

} // namespace rs::test
