// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Rung.h"

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace rs::ladder {

// A rung, or a comment or blank line standing among the rungs.
using NetworkItem = std::variant<Rung, lang::Line>;

// A network: rungs shown together under one comment. In a file written by
// hand every statement is its own network; a ";@network" record groups the
// statements after it (docs/file-format.md).
struct Network {
    std::string comment;
    // The ";@network" comment line the network was read with, so it is written
    // back as it was; none for a network without a record.
    std::optional<lang::CommentLine> record;
    std::vector<NetworkItem> items;

    friend bool operator==(const Network&, const Network&) = default;
};

// Statements the network stands for: one per output.
int statementCount(const Network& network);

// The ladder form of one step.
struct StepLadder {
    std::vector<lang::Line> leading; // comments and blank lines before the first network
    std::vector<Network> networks;

    friend bool operator==(const StepLadder&, const StepLadder&) = default;
};

} // namespace rs::ladder
