// SPDX-License-Identifier: GPL-3.0-or-later
#include "FuzzFailure.h"

#include "compiler/Compiler.h"
#include "project/ProjectFile.h"
#include "sim/ScenarioRunner.h"

#include <cstdint>
#include <string_view>

namespace {

using rs::fuzz::fail;

const char* kProgram = "! id_pluto:00=000000000000\n"
                       "! type_pluto:00=A20,is3\n"
                       "! I0.12=EStop\n"
                       "! M0.5=Running\n"
                       "! pgm_pluto:00\n"
                       "S0.0_0\n"
                       "Q0.2 = EStop * I0.13\n"
                       "Running = Q0.2 * TON(0s50)\n"
                       "(R0.5 += 1) = P(I0.13)\n";

// Scenarios longer than this are read, not run: the fuzzer looks for faults,
// and 30 days of scans (the bound) take minutes.
constexpr std::int64_t kRunAtMostMs = 10'000;

} // namespace

// Any input: reading never crashes; diagnostics point into the text; a
// scenario that reads stays within the bounds it promises, and a short one runs.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const rs::project::ProjectReadResult read = rs::project::readProject(kProgram);
    static const rs::compiler::CompileResult compiled = rs::compiler::compileText(kProgram);
    static const rs::sim::OperandNames names(read.project);
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const rs::sim::Scenario scenario = rs::sim::parseScenario(text, names);
    rs::fuzz::requireInside(text, scenario.diagnostics, "a diagnostic points outside the scenario");
    if (!scenario.diagnostics.empty())
        return 0;
    std::int64_t cycleMs = 10;
    std::int64_t totalMs = 0;
    bool expects = false;
    for (const auto& step : scenario.steps) {
        using Kind = rs::sim::ScenarioStep::Kind;
        if (step.kind == Kind::Cycle) {
            if (step.durationMs < rs::sim::kMinCycleMs || step.durationMs > rs::sim::kMaxCycleMs)
                fail("a cycle out of range was read");
            cycleMs = step.durationMs;
        }
        if (step.kind == Kind::Scans && step.count > rs::sim::kMaxVirtualMs / cycleMs)
            fail("a scan count past the bound was read");
        totalMs += step.kind == Kind::Scans   ? step.count * cycleMs
                   : step.kind == Kind::Cycle ? 0
                                              : step.durationMs;
        if (totalMs > rs::sim::kMaxVirtualMs)
            fail("virtual time past the bound was read");
        expects = expects || step.kind == Kind::Expect;
    }
    if (!expects)
        fail("a scenario without expectation was read");
    if (totalMs > kRunAtMostMs)
        return 0;
    rs::sim::Simulation simulation(compiled.images);
    const rs::sim::ScenarioReport report = rs::sim::runScenario("fuzz.scn", scenario, simulation);
    if (report.passed + report.failed < 1)
        fail("a scenario that ran counted nothing");
    return 0;
}
