// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "PropertyFile.h"
#include "compiler/Image.h"

#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

// Proves each property of a property file over the compiled project, or finds
// the shortest input sequence that breaks it: bounded model checking for
// counterexamples, k-induction strengthened with invariants for proofs, on
// CaDiCaL (docs/prove.md).
namespace rs::prove {

struct Verdict;

struct ProofOptions {
    int maxDepth = 200;                          // scans
    std::chrono::milliseconds timeLimit{60'000}; // per property
    std::function<bool()> cancelled;             // asked while solving
    // Told each verdict as soon as it is known, in file order, on the
    // prover's thread: for a window that shows results as they come.
    std::function<void(const Verdict&)> verdictFound;
};

// The inputs of one scan: every input the model has, with its value.
using ScanInputs = std::vector<std::pair<lang::Address, std::int64_t>>;

struct Verdict {
    enum class Status : std::uint8_t {
        Proved,      // for every input sequence
        Failed,      // a counterexample of `depth` scans
        Unknown,     // neither, up to `depth` scans
        Covered,     // a cover reached in `depth` scans
        Unreachable, // a cover proved never to hold
    } status = Status::Unknown;
    const Property* property = nullptr;
    int depth = 0;
    // Why unknown: the kind, for a window to word in its language, and in English.
    enum class Why : std::uint8_t { None, DepthReached, TimeLimit, Cancelled, NotRepeated };
    Why why = Why::None;
    std::string reason;
    std::vector<ScanInputs> inputs; // Failed and Covered: the scans' inputs
    int invariants = 0;             // proved: the invariants the proof kept
    std::int64_t clauses = 0;       // of the last query
    int variables = 0;
};

// Every property but the assumptions, in file order.
std::vector<Verdict> proveProperties(const std::vector<compiler::UnitImage>& images,
                                     const PropertyFile& file, const ProofOptions& options = {});

} // namespace rs::prove
