// SPDX-License-Identifier: GPL-3.0-or-later
#include "TestVerb.h"

#include "Verbs.h"
#include "compiler/Compiler.h"
#include "project/ProjectFile.h"
#include "sim/ScenarioRunner.h"

#include <QFileInfo>

#include <cstdio>

namespace rs::cli {

namespace {

QString tracePath(const QString& vcd, const QString& scenario, bool several) {
    if (!several)
        return vcd;
    const QFileInfo out(vcd);
    return out.path() + "/" + out.completeBaseName() + "." +
           QFileInfo(scenario).completeBaseName() + ".vcd";
}

} // namespace

int runTest(const QString& projectPath, const QStringList& scenarios, const QString& vcd,
            const compiler::CheckOptions& options) {
    project::FileText file = project::readTextFile(projectPath);
    if (!file.error.isEmpty()) {
        std::fprintf(stderr, "rungsmith-cli: %s\n", qPrintable(file.error));
        return UsageOrIo;
    }
    project::ProjectReadResult read = project::readProject(file.text);
    compiler::CompileResult compiled = compiler::compileText(file.text, options);
    if (compiled.errors()) {
        for (const auto& diagnostic : compiled.diagnostics)
            std::fprintf(stderr, "%s\n",
                         lang::formatDiagnostic(projectPath.toStdString(), diagnostic).c_str());
        std::fprintf(stdout, "%d Error(s) detected Result=FAILED\n", compiled.errors());
        return Failed;
    }
    const sim::OperandNames names(read.project);
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
        for (const auto& line : report.diagnostics)
            std::fprintf(stderr, "%s\n", line.c_str());
        for (const auto& line : report.failures)
            std::fprintf(stdout, "%s\n", line.c_str());
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
