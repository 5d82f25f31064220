// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>

namespace rs::ladder {

// Every kind of element and output a rung is drawn with. The vocabulary
// (ElementVocabulary.h) says what each makes in the language; the order is
// the order the editor lists them in.
enum class ElementKind : std::uint8_t {
    NormallyOpen,    // x
    NormallyClosed,  // /x
    PositiveEdge,    // P(x)
    NegativeEdge,    // N(x)
    NotPositiveEdge, // /P(x), instruction set 3
    NotNegativeEdge, // /N(x), instruction set 3
    OnDelayTimer,    // TON(t), T(t)
    PulseTimer,      // TPS(t), IT(t)
    OffDelayTimer,   // TOF(t)
    Comparison,      // (R0.1>=5)
    Coil,            // Q0.2
    Set,             // S(Q0.2)
    Reset,           // R(Q0.2)
    Toggle,          // T(Q0.2)
    Jump,            // J(+1)
    SequenceReset,   // R(S0.1)
    Arithmetic,      // (R0.1 += 2)
};

// How an element is drawn, whatever the target.
enum class Shape : std::uint8_t { Contact, Box, Coil };

} // namespace rs::ladder
