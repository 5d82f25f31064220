// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "blocks/BlockLibrary.h"

#include <string>
#include <string_view>
#include <vector>

// The state machine of a block, read back from its body, for the block's
// documentation page. The page shows what the body does rather than what was
// written about it, so the two cannot drift apart. A body is read this way
// when it is built as docs/safety-blocks.md ("How a block is built") says:
// the state in a private register `state`, the next state in `next`, one
// line `({#next} = N) = CONDITION` per transition with each state's list
// written last-first, and bit outputs set from the state.
namespace rs::blockdoc {

struct Transition {
    std::vector<int> from; // the states it leaves, as 16-bit codes; empty: every state
    std::string condition; // in the language, pins and privates by name
    int to = 0;
};

// A line of the body that is not a transition: a private signal the
// conditions use (`resetEdge = P(Reset)`) or an output that does not follow
// from the state alone.
struct Definition {
    std::string name;
    std::string expression;
};

struct StateMachineTable {
    // The library's `state` records first, in their order, then any other
    // state the body names, in the order it names them.
    std::vector<int> states;
    // In the order they are tried: the first true one is taken.
    std::vector<Transition> transitions;
    // The bit outputs set from the state alone, and for each state (in the
    // order of `states`) which of them are on.
    std::vector<std::string> outputs;
    std::vector<std::vector<bool>> outputsOn;
    std::vector<Definition> definitions;
    bool diagCodeIsState = false; // a line ({DiagCode} = {#state})

    bool empty() const { return transitions.empty(); }
    // The transitions tried in a state, in order; those of every state first,
    // as the body tries them.
    std::vector<const Transition*> transitionsFrom(int state) const;
};

// Nothing (empty()) for a body that is not built that way, such as a system
// block's or one without a `state` and a `next` register.
StateMachineTable stateMachineOf(const blocks::BlockDefinition& block);

// "16#8001" for 0x8001 or for -32767, the same pattern in a signed register.
std::string stateCode(int code);

// A body's text as a reader writes it: `{Pin}` as `Pin`, `{#name}` as
// `name`, `({#state}=-32767)` as `(state=16#8001)`.
std::string readable(std::string_view bodyText);

} // namespace rs::blockdoc
