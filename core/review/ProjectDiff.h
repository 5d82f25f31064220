// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "NetworkDiff.h"
#include "UnitDiff.h"
#include "compiler/Compiler.h"

#include <string>
#include <vector>

// What a reviewer needs to know about a new version of a project: what
// changed, unit by unit and network by network, and whether what the units do
// changed at all (their signatures, compiler/Signature.h).
namespace rs::review {

struct ProjectDiff {
    std::vector<UnitDifference> units;
    std::vector<NetworkDifference> networks;
    std::vector<int> changedStations; // whose signature differs, or that one side lacks
    std::uint32_t oldSignature = 0;
    std::uint32_t newSignature = 0;
    bool textChanged = false; // the canonical texts differ

    bool behaviourChanged() const { return oldSignature != newSignature; }
    // The lines of `rungsmith-cli diff`: each unit's differences, then its
    // networks', by station; then the verdict.
    std::vector<std::string> lines() const;
    // "no change in behaviour", "no change in behaviour; only the text
    // changed", or "behaviour changed in Pluto 00, Pluto 02 (project
    // signature 1A2B3C4D, was 5E6F7A8B)".
    std::string verdict() const;
};

// Both projects compiled without errors: `compiled` holds their signatures.
ProjectDiff diffProjects(const project::Project& before, const compiler::CompileResult& oldCompiled,
                         const project::Project& after, const compiler::CompileResult& newCompiled);

} // namespace rs::review
