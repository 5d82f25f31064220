// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/Ast.h"

#include <random>

namespace rs::test {

// Random syntax trees in canonical shape (flattened AND/OR, statements in
// steps, no two blank lines in a row): what printing and parsing must carry
// through unchanged.
class RandomProgram {
public:
    explicit RandomProgram(unsigned seed) : m_random(seed) {}

    lang::Document document();
    lang::Expr expression(int depth);
    lang::Statement statement();

private:
    int uniform(int low, int high) {
        return std::uniform_int_distribution<int>(low, high)(m_random);
    }
    bool chance(int percent) { return uniform(1, 100) <= percent; }

    lang::Operand bitOperand();
    lang::Operand wordOperand();
    lang::Operand name();
    lang::Value value();
    lang::Expr leaf();
    std::string text(int maxLength);
    std::optional<std::string> maybeComment();
    std::vector<lang::Line> lines(int count, bool statements, bool unitSection);
    lang::Line line(bool statements, bool unitSection);

    std::mt19937 m_random;
    int m_unit = 0;
};

} // namespace rs::test
