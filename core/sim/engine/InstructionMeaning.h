// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "compiler/Image.h"
#include "lang/Ast.h"

#include <algorithm>
#include <array>
#include <cstdint>

// What each instruction means, said once: the marking interpreter, the fast
// interpreter (its handlers and its rows) and the machine-code lowering all
// read these, so a change of meaning is a change here (docs/simulator.md,
// "Instructions").
namespace rs::sim::engine {

// The system memories and registers that instructions write.
constexpr int kDitto = 1;
constexpr int kTimerFreeze = 10;
constexpr int kOverflow = 11;
constexpr int kDivByZero = 12;
constexpr int kRemain = 2;

// Where arithmetic saturates. The manual: a register at 32767 / -32768, a
// double register at ±2147483647.
struct Bounds {
    std::int64_t low;
    std::int64_t high;
};
constexpr Bounds kRegisterBounds{-32768, 32767};
constexpr Bounds kDoubleRegisterBounds{-2147483647, 2147483647};

constexpr bool outside(std::int64_t value, Bounds bounds) {
    return value < bounds.low || value > bounds.high;
}

constexpr std::int64_t saturated(std::int64_t value, Bounds bounds) {
    return std::clamp(value, bounds.low, bounds.high);
}

// An arithmetic output computes x <operation> y from the target's value
// (current) and a and b, with x = current * fromCurrent + a * fromA and
// y = constant + a * yA + b * yB; a subtraction adds a negated y.
struct ArithmeticForm {
    enum class Operation : std::uint8_t { Add, Multiply, Divide };
    std::int8_t fromCurrent = 0;
    std::int8_t fromA = 0;
    std::int8_t constant = 0;
    std::int8_t yA = 0;
    std::int8_t yB = 0;
    Operation operation = Operation::Add;

    constexpr std::int64_t x(std::int64_t current, std::int64_t a) const {
        return current * fromCurrent + a * fromA;
    }
    constexpr std::int64_t y(std::int64_t a, std::int64_t b) const {
        return constant + a * yA + b * yB;
    }
    // The result before saturation of anything but a division (division by
    // zero and the remainder are the caller's).
    constexpr std::int64_t undivided(std::int64_t current, std::int64_t a, std::int64_t b) const {
        const std::int64_t left = x(current, a);
        const std::int64_t right = y(a, b);
        return operation == Operation::Multiply ? left * right : left + right;
    }
};

constexpr ArithmeticForm arithmeticForm(compiler::ArithOp op) {
    using Operation = ArithmeticForm::Operation;
    switch (op) {
    case compiler::ArithOp::Increment:
        return {.fromCurrent = 1, .constant = 1};
    case compiler::ArithOp::Decrement:
        return {.fromCurrent = 1, .constant = -1};
    case compiler::ArithOp::Add:
        return {.fromCurrent = 1, .yA = 1};
    case compiler::ArithOp::Sub:
        return {.fromCurrent = 1, .yA = -1};
    case compiler::ArithOp::Mul:
        return {.fromCurrent = 1, .yA = 1, .operation = Operation::Multiply};
    case compiler::ArithOp::Div:
        return {.fromCurrent = 1, .yA = 1, .operation = Operation::Divide};
    case compiler::ArithOp::Copy:
        return {.fromA = 1};
    case compiler::ArithOp::AddAB:
        return {.fromA = 1, .yB = 1};
    case compiler::ArithOp::SubAB:
        return {.fromA = 1, .yB = -1};
    case compiler::ArithOp::MulAB:
        return {.fromA = 1, .yB = 1, .operation = Operation::Multiply};
    case compiler::ArithOp::DivAB:
        return {.fromA = 1, .yB = 1, .operation = Operation::Divide};
    }
    return {};
}

// Where decoding puts an aux byte that is no ArithOp (an image read from a
// file may hold one): its form computes 0.
constexpr std::uint8_t kUnknownArithmetic = static_cast<std::uint8_t>(compiler::ArithOp::DivAB) + 1;

// arithmeticForm() by the image's aux byte, for the handlers that look it up
// while scanning.
inline constexpr auto kArithmeticForms = [] {
    std::array<ArithmeticForm, kUnknownArithmetic + 1> forms{};
    for (std::size_t op = 0; op < kUnknownArithmetic; ++op)
        forms[op] = arithmeticForm(static_cast<compiler::ArithOp>(op));
    return forms;
}();

constexpr bool isDivision(compiler::ArithOp op) {
    return arithmeticForm(op).operation == ArithmeticForm::Operation::Divide;
}

// A comparison of a and b, the image's aux byte of a Compare.
constexpr bool compares(lang::CompareOp op, std::int64_t a, std::int64_t b) {
    switch (op) {
    case lang::CompareOp::Equal:
        return a == b;
    case lang::CompareOp::Greater:
        return a > b;
    case lang::CompareOp::Less:
        return a < b;
    case lang::CompareOp::GreaterEqual:
        return a >= b;
    case lang::CompareOp::LessEqual:
        return a <= b;
    }
    return false;
}

// What an output (=, S, R, T) does to its bit: with power it becomes
// (bit & keepOn) ^ flipOn, without power bit & keepOff.
struct OutputForm {
    std::uint8_t keepOn;
    std::uint8_t flipOn;
    std::uint8_t keepOff;
};

constexpr OutputForm outputForm(compiler::Op op) {
    switch (op) {
    case compiler::Op::Coil:
        return {0, 1, 0};
    case compiler::Op::Set:
        return {0, 1, 1};
    case compiler::Op::Reset:
        return {0, 0, 1};
    case compiler::Op::Toggle:
        return {1, 1, 1};
    default:
        return {1, 0, 1}; // not an output: the bit stays
    }
}

// The bit (0 or 1) after output `op` ran with `power` (0 or 1); without a
// branch on either.
template <compiler::Op op> constexpr unsigned outputBit(unsigned power, unsigned bit) {
    constexpr OutputForm form = outputForm(op);
    const unsigned select = 0u - power;
    return (((bit & form.keepOn) ^ form.flipOn) & select) | (bit & form.keepOff & ~select);
}

// Whether an edge occurrence sees its edge now, from its operand's value and
// what it saw the last time it ran (0 or 1 each). The first time it runs
// (seen 0) it sees none.
constexpr unsigned edgeSeen(unsigned seen, unsigned last, unsigned value, bool rising) {
    // Rising: the value is 1 and was 0; falling: it was 1 and is 0.
    return seen & (value ^ last) & (rising ? value : last);
}

} // namespace rs::sim::engine
