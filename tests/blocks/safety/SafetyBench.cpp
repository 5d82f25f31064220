// SPDX-License-Identifier: GPL-3.0-or-later
#include "SafetyBench.h"

#include "blocks/LibraryReader.h"
#include "blocks/ProjectInstances.h"
#include "compiler/Compiler.h"
#include "project/ProjectFile.h"
#include "sim/ScenarioRunner.h"

#include <fstream>
#include <sstream>

namespace rs::safetytest {

namespace {

const blocks::LibrarySet& safetyLibrary() {
    static const blocks::LibrarySet set = [] {
        std::ifstream file(RUNGSMITH_LIBRARIES "/Rungsmith_Safety.rslib", std::ios::binary);
        std::stringstream text;
        text << file.rdbuf();
        const blocks::LibraryReadResult read = blocks::readLibrary(text.str());
        blocks::LibrarySet libraries;
        if (read.ok())
            libraries.libraries.push_back({read.library, QStringLiteral("Rungsmith_Safety.rslib"),
                                           blocks::LibraryOrigin::Standard});
        return libraries;
    }();
    return set;
}

std::string listed(const lang::Diagnostics& diagnostics) {
    std::string text;
    for (const lang::Diagnostic& d : diagnostics)
        text += std::to_string(d.line) + ":" + std::to_string(d.column) + ": " + d.message + "\n";
    return text;
}

int expectLines(const std::string& scenario) {
    std::istringstream lines(scenario);
    int count = 0;
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("expect ", 0) == 0)
            ++count;
    return count;
}

} // namespace

std::string oneUnitProject(const std::string& names, const std::string& code, int instructionSet) {
    return "! id_pluto:00=000000000000\n! type_pluto:00=A20,is" + std::to_string(instructionSet) +
           "\n! pgm_pluto:00\n" + names + "S0.0_0\n" + code;
}

::testing::AssertionResult scenarioHolds(const std::string& project, const std::string& scenario) {
    if (safetyLibrary().libraries.empty())
        return ::testing::AssertionFailure() << "Rungsmith_Safety.rslib does not read";
    const blocks::ProjectWithInstances read =
        blocks::readProjectWithInstances(project, safetyLibrary());
    if (!read.read.ok() || lang::errorCount(read.read.diagnostics) > 0)
        return ::testing::AssertionFailure() << "reading:\n" << listed(read.read.diagnostics);
    const std::string expanded = project::writeProject(read.read.project);
    const compiler::CompileResult compiled = compiler::compileText(expanded);
    if (compiled.errors() > 0)
        return ::testing::AssertionFailure() << "compiling:\n"
                                             << listed(compiled.diagnostics) << "of\n"
                                             << expanded;
    sim::Simulation simulation(compiled.images);
    const sim::OperandNames names(read.read.project);
    const sim::ScenarioReport report =
        sim::runScenario("t.scn", sim::parseScenario(scenario, names), simulation);
    std::string failures;
    for (const std::string& d : report.diagnostics)
        failures += d + "\n";
    for (const std::string& f : report.failures)
        failures += f + "\n";
    const int expected = expectLines(scenario);
    if (report.failed > 0 || report.passed != expected)
        return ::testing::AssertionFailure()
               << report.passed << " of " << expected << " expectations passed, " << report.failed
               << " failed:\n"
               << failures;
    return ::testing::AssertionSuccess();
}

::testing::AssertionResult holdsOnBothInstructionSets(const std::string& names,
                                                      const std::string& code,
                                                      const std::string& scenario) {
    for (const int set : {2, 3}) {
        ::testing::AssertionResult holds =
            scenarioHolds(oneUnitProject(names, code, set), scenario);
        if (!holds)
            return holds << "(instruction set " << set << ")";
    }
    return ::testing::AssertionSuccess();
}

} // namespace rs::safetytest
