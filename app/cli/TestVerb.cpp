// SPDX-License-Identifier: GPL-3.0-or-later
#include "TestVerb.h"

#include "Pl110Verbs.h"
#include "Verbs.h"
#include "compiler/Compiler.h"
#include "project/ProjectFile.h"
#include "sim/ScenarioRunner.h"

#include <QFileInfo>

#include <cstdio>

namespace rs::cli {

QString tracePath(const QString& vcd, const QString& scenario, bool several) {
    if (!several)
        return vcd;
    const QFileInfo out(vcd);
    return out.path() + "/" + out.completeBaseName() + "." +
           QFileInfo(scenario).completeBaseName() + ".vcd";
}

void printReport(const sim::ScenarioReport& report) {
    for (const auto& line : report.diagnostics)
        std::fprintf(stderr, "%s\n", line.c_str());
    for (const auto& line : report.failures)
        std::fprintf(stdout, "%s\n", line.c_str());
}

int runTest(const QString& projectPath, const QStringList& scenarios, const QString& vcd,
            const QStringList& libraryFiles, const compiler::CheckOptions& options) {
    if (const auto text = pl110Text(projectPath))
        return testPl110(projectPath, *text, scenarios, vcd);
    const LoadedProject loaded = loadProject(projectPath, libraryFiles);
    if (loaded.status != Ok)
        return loaded.status;
    compiler::CompileResult compiled = rs::cli::compiled(loaded, options);
    if (compiled.errors()) {
        printDiagnostics(projectPath, compiled.diagnostics);
        std::fprintf(stdout, "%d Error(s) detected Result=FAILED\n", compiled.errors());
        return Failed;
    }
    const sim::OperandNames names(loaded.project);
    int passed = 0;
    int failed = 0;
    for (const QString& path : scenarios) {
        project::FileText text = project::readTextFile(path);
        if (!text.error.isEmpty()) {
            std::fprintf(stderr, "rungsmith-cli: %s\n", qPrintable(text.error));
            return UsageOrIo;
        }
        const sim::Scenario scenario = sim::parseScenario(text.text, names);
        sim::Simulation simulation(compiled.images);
        sim::VcdTrace trace(sim::traceSignals(compiled.images, sim::touchedBy(scenario)));
        const sim::ScenarioReport report = sim::runScenario(
            path.toStdString(), scenario, simulation, vcd.isEmpty() ? nullptr : &trace);
        printReport(report);
        passed += report.passed;
        failed += report.failed;
        if (!vcd.isEmpty() && report.diagnostics.empty()) {
            const QString out = tracePath(vcd, path, scenarios.size() > 1);
            const QString error = project::writeTextFile(
                out, trace.text("Rungsmith scenario " + QFileInfo(path).fileName().toStdString()));
            if (!error.isEmpty()) {
                std::fprintf(stderr, "rungsmith-cli: %s\n", qPrintable(error));
                return UsageOrIo;
            }
        }
    }
    std::fprintf(stdout, "%d passed, %d failed\n", passed, failed);
    return failed ? Failed : Ok;
}

} // namespace rs::cli
