// SPDX-License-Identifier: GPL-3.0-or-later
#include "FuzzFailure.h"

#include "compiler/Compiler.h"
#include "project/ProjectFile.h"
#include "prove/Counterexample.h"
#include "prove/Prover.h"
#include "sim/Scenario.h"

#include <cstdint>
#include <string_view>

namespace {

using rs::fuzz::fail;

// A small program with every kind of state the prover models: a latch, an
// edge, a timer, a sequence, saturating arithmetic.
const char* kProgram = "! id_pluto:00=000000000000\n"
                       "! type_pluto:00=A20,is3\n"
                       "! I0.12=EStop\n"
                       "! M0.5=Running\n"
                       "! pgm_pluto:00\n"
                       "S0.0_0\n"
                       "Q0.2 = EStop * (P(I0.13) + Q0.2)\n"
                       "Running = Q0.2 * TON(0s05)\n"
                       "(R0.5 += 9000) = P(I0.1)\n"
                       "S0.1_0\n"
                       "J(1) = I0.2 * Running\n"
                       "S0.1_1\n"
                       "Q0.3 = I0.3\n"
                       "J(0) = /EStop\n";

} // namespace

// Any input: reading never crashes and its diagnostics point into the text;
// a file that reads is proved to a small depth, and every counterexample or
// witness the prover reports is one the simulator repeats.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const rs::project::ProjectReadResult read = rs::project::readProject(kProgram);
    static const rs::compiler::CompileResult compiled = rs::compiler::compileText(kProgram);
    static const rs::sim::OperandNames names(read.project);
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const rs::prove::PropertyFile file = rs::prove::parseProperties(text, names);
    rs::fuzz::requireInside(text, file.diagnostics,
                            "a diagnostic points outside the property file");
    if (rs::lang::errorCount(file.diagnostics))
        return 0;
    rs::prove::ProofOptions options;
    options.maxDepth = 6;
    options.timeLimit = std::chrono::milliseconds(2000);
    for (const rs::prove::Verdict& verdict :
         rs::prove::proveProperties(compiled.images, file, options)) {
        if (verdict.status != rs::prove::Verdict::Status::Failed &&
            verdict.status != rs::prove::Verdict::Status::Covered)
            continue;
        if (!rs::prove::writeCounterexample(compiled.images, file, verdict, names, "f.prop")
                 .reproduced)
            fail("a counterexample the simulator does not repeat");
    }
    return 0;
}
