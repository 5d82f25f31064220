// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Prover.h"

#include <string>
#include <vector>

namespace rs::sim {
class OperandNames;
}

// A counterexample (or a cover's witness) as a scenario file that
// `rungsmith-cli test` runs: the inputs scan by scan from power on, then one
// `expect` on the last line, which fails for a counterexample and holds for a
// witness. Before it is reported, the simulator runs it and must reproduce
// what the prover found.
namespace rs::prove {

struct CounterexampleScenario {
    std::string text;
    bool reproduced = false;
    std::string problem; // why not, when not
};

// Empty when the simulator, given the verdict's inputs from power on, breaks
// the property (reaches the cover) in the last scan and in no scan before,
// with every assumption kept; else what it does instead.
std::string replayProblem(const std::vector<compiler::UnitImage>& images, const PropertyFile& file,
                          const Verdict& verdict);

CounterexampleScenario writeCounterexample(const std::vector<compiler::UnitImage>& images,
                                           const PropertyFile& file, const Verdict& verdict,
                                           const sim::OperandNames& names,
                                           const std::string& propertyFileName);

} // namespace rs::prove
