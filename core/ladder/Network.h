// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Rung.h"

#include "blocks/BlockInstance.h"

#include <cstddef>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace rs::ladder {

// A rung, or a comment or blank line standing among the rungs.
using NetworkItem = std::variant<Rung, lang::Line>;

// A block instance shown as one box (blocks.md): its ";@block" record, the
// statements it stands for and its ";@end", kept as they were read so that
// writing the network back gives the same lines.
struct BlockCall {
    blocks::BlockInstance instance; // read from lines.front()
    std::vector<lang::Line> lines;

    friend bool operator==(const BlockCall& a, const BlockCall& b) { return a.lines == b.lines; }
};

// A network: rungs shown together under one comment, or one block instance. In a file written by
// hand every statement is its own network; a ";@network" record groups the
// statements after it (docs/file-format.md).
struct Network {
    std::string comment;
    // The ";@network" comment line the network was read with, so it is written
    // back as it was; none for a network without a record.
    std::optional<lang::CommentLine> record;
    std::vector<NetworkItem> items;
    // A block network: the items are only the comment and blank lines that
    // follow the instance's ";@end", never rungs.
    std::optional<BlockCall> block;

    friend bool operator==(const Network&, const Network&) = default;
};

// A call of a block written without its statements, which reading the
// project expands (blocks.md): its record and ";@end".
BlockCall unexpandedCall(blocks::BlockInstance instance);

// Statements the network stands for: one per output, or the statements of
// its block instance.
int statementCount(const Network& network);
// The lines of the step the network was read from (toLadder): its record,
// block, statements and comment lines.
std::size_t lineCount(const Network& network);

// The ladder form of one step.
struct StepLadder {
    std::vector<lang::Line> leading; // comments and blank lines before the first network
    std::vector<Network> networks;

    friend bool operator==(const StepLadder&, const StepLadder&) = default;
};

} // namespace rs::ladder
