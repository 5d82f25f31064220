// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "InstructionMeaning.h"
#include "UnitState.h"

#include <cstdint>
#include <cstring>

// The fast interpreter's rows: consecutive statements of two common shapes,
// each row run by one loop without a branch that depends on the program or
// the data (docs/simulator.md, "Speed").
namespace rs::sim::engine {

// A statement of at most two contacts and one edge in series, on bytes or
// register bits, and one output (=, S, R, T on a byte or register bit, or a
// jump). A bit is (*read & mask) != 0; unused contacts read a 1, an unused
// edge is a negated one that never fires. The output is its OutputForm on
// the bits targetMask of *target.
struct BitStatement {
    const std::uint8_t* read[3]; // two contacts, the edge's operand
    EdgeState* edge;
    std::uint8_t* target;
    std::uint8_t mask[3];
    std::uint8_t negated[3]; // the contacts; the edge's operand (P(/x))
    std::uint8_t edgeRising;
    std::uint8_t edgeNegated;
    std::uint8_t targetMask; // the bits of *target that are the output
    std::uint8_t targetOne;  // the output's 1 (1 for a byte, the bit for a register bit)
    std::uint8_t keepOn;     // with power: output = (output & keepOn) ^ flipOn
    std::uint8_t flipOn;
    std::uint8_t keepOff; // without: *target &= keepOff
    std::uint8_t jump;    // 1: a jump to jumpStep with power, no output
    std::uint8_t jumpStep;
};

// A statement of at most one contact and one edge in series, a load of a and
// of b, and arithmetic on a register other than a division. A load reads 4
// bytes (a 32-bit value, a double register or a constant) and keeps the low
// 32 - narrow bits.
struct WordStatement {
    const std::uint8_t* read[2]; // the contact, the edge's operand
    EdgeState* edge;
    const std::uint8_t* load[2];
    std::int16_t* target;
    std::uint8_t mask[2];
    std::uint8_t negated[2];
    std::uint8_t edgeRising;
    std::uint8_t edgeNegated;
    std::uint8_t loads[2]; // whether it loads a, b
    std::uint8_t narrow[2];
    ArithmeticForm form;
};

template <typename Statement> struct Row {
    const Statement* first;
    const Statement* end;
};

template <bool withEdges>
inline void runBitStatements(const Row<BitStatement>& row, std::uint8_t& ditto, int& pendingJump) {
    int jump = pendingJump;
    for (const BitStatement* st = row.first; st != row.end; ++st) {
        const auto bit = [st](int i) {
            return static_cast<unsigned>((*st->read[i] & st->mask[i]) != 0) ^ st->negated[i];
        };
        unsigned on = bit(0) & bit(1);
        if constexpr (withEdges) {
            const unsigned value = bit(2);
            const unsigned seen =
                edgeSeen(st->edge->seen, st->edge->last, value, st->edgeRising != 0);
            st->edge->seen = true;
            st->edge->last = value != 0;
            on &= seen ^ st->edgeNegated;
        }
        const unsigned old = *st->target;
        const unsigned output =
            (static_cast<unsigned>((old & st->targetMask) != 0) & st->keepOn) ^ st->flipOn;
        const unsigned withPower = (old & ~st->targetMask) | (st->targetOne & (0u - output));
        const unsigned without = old & st->keepOff;
        const unsigned select = 0u - on;
        *st->target = static_cast<std::uint8_t>((withPower & select) | (without & ~select));
        jump = (on & st->jump) ? st->jumpStep : jump;
        const unsigned keep = 0u - static_cast<unsigned>(st->jump); // a jump leaves SM_Ditto
        // Stored each time: the next statement may read it.
        ditto = static_cast<std::uint8_t>((ditto & keep) | (on & ~keep));
    }
    pendingJump = jump;
}

inline void runWordStatements(const Row<WordStatement>& row, std::uint8_t& overflow,
                              std::int64_t& a, std::int64_t& b) {
    for (const WordStatement* st = row.first; st != row.end; ++st) {
        const unsigned value =
            static_cast<unsigned>((*st->read[1] & st->mask[1]) != 0) ^ st->negated[1];
        const unsigned seen = edgeSeen(st->edge->seen, st->edge->last, value, st->edgeRising != 0);
        st->edge->seen = true;
        st->edge->last = value != 0;
        const unsigned on =
            ((static_cast<unsigned>((*st->read[0] & st->mask[0]) != 0) ^ st->negated[0]) &
             (seen ^ st->edgeNegated));
        const auto load = [st](int i) {
            std::uint32_t raw = 0;
            std::memcpy(&raw, st->load[i], sizeof raw);
            return static_cast<std::int64_t>(static_cast<std::int32_t>(raw << st->narrow[i]) >>
                                             st->narrow[i]);
        };
        const std::int64_t loadedA = load(0);
        const std::int64_t loadedB = load(1);
        a = st->loads[0] ? loadedA : a;
        b = st->loads[1] ? loadedB : b;
        const std::int64_t current = *st->target;
        const std::int64_t result = st->form.undivided(current, a, b);
        const auto bounded = static_cast<std::int16_t>(saturated(result, kRegisterBounds));
        *st->target = on ? bounded : static_cast<std::int16_t>(current);
        overflow = on ? outside(result, kRegisterBounds) : overflow;
    }
}

} // namespace rs::sim::engine
