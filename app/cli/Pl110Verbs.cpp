// SPDX-License-Identifier: GPL-3.0-or-later
#include "Pl110Verbs.h"

#include "Drawing.h"
#include "MarksSnapshot.h"
#include "ProjectLoading.h"
#include "TestVerb.h"
#include "Verbs.h"
#include "pl110/NameCsv.h"
#include "pl110/ProgramCheck.h"
#include "pl110/ProgramFile.h"
#include "pl110/ProgramText.h"
#include "pl110/RungLayout.h"
#include "pl110/Rungs.h"
#include "pl110/Scenario.h"
#include "project/ProjectFile.h"
#include "sim/VcdWriter.h"

#include <QFileInfo>

#include <QStringList>

#include <optional>
#include <utility>

namespace rs::cli {

std::optional<std::string> pl110Text(const QString& path) {
    // A Pluto project (the usual case, up to megabytes) is not read twice:
    // the first 64 KB tell.
    if (!pl110::isPl110File(path))
        return std::nullopt;
    project::FileText file = project::readTextFile(path);
    if (!file.error.isEmpty() || !pl110::isPl110Text(file.text))
        return std::nullopt;
    return std::move(file.text);
}

int checkPl110(const QString& path, const std::string& text) {
    const pl110::ProgramReading reading = pl110::readProgram(text);
    lang::Diagnostics diagnostics = reading.diagnostics;
    const lang::Diagnostics checked = pl110::checkProgram(reading.program);
    diagnostics.insert(diagnostics.end(), checked.begin(), checked.end());
    lang::sortByPlace(diagnostics);
    printDiagnostics(path, diagnostics);
    const int errors = lang::errorCount(diagnostics);
    std::fprintf(stdout, "%d Error(s) detected Result=%s\n", errors, errors ? "FAILED" : "OK");
    return errors ? Failed : Ok;
}

std::optional<pl110::Program> checkedPl110(const QString& path, const std::string& text) {
    pl110::ProgramReading reading = pl110::readProgram(text);
    lang::Diagnostics diagnostics = reading.diagnostics;
    if (diagnostics.empty())
        diagnostics = pl110::checkProgram(reading.program);
    if (diagnostics.empty())
        return std::move(reading.program);
    printDiagnostics(path, diagnostics);
    std::fprintf(stdout, "%d Error(s) detected Result=FAILED\n", lang::errorCount(diagnostics));
    return std::nullopt;
}

int formatPl110(const QString& path, const std::string& text) {
    const pl110::ProgramReading reading = pl110::readProgram(text);
    if (!reading.diagnostics.empty()) {
        // Printing would drop the bad lines: refused, as for a Pluto project.
        printDiagnostics(path, reading.diagnostics);
        return Failed;
    }
    const std::string printed = pl110::printProgram(reading.program);
    std::fwrite(printed.data(), 1, printed.size(), stdout);
    return Ok;
}

namespace {

// Runs the scenario to its end; its status, and false when it could not run.
std::pair<int, bool> runToEnd(const QString& path, const pl110::Program& program,
                              pl110::ScanEngine& engine) {
    const project::FileText file = project::readTextFile(path);
    if (!file.error.isEmpty()) {
        std::fprintf(stderr, "rungsmith-cli: %s\n", qPrintable(file.error));
        return {UsageOrIo, false};
    }
    const pl110::Scenario scenario = pl110::parseScenario(file.text, pl110::ScenarioNames(program));
    const sim::ScenarioReport report = pl110::runScenario(path.toStdString(), scenario, engine);
    printReport(report);
    if (!report.diagnostics.empty())
        return {Failed, false};
    return {report.failed ? Failed : Ok, true};
}

} // namespace

int ladderPl110(const QString& path, const std::string& text, int network, const QString& output,
                const QString& scenario) {
    const pl110::ProgramReading reading = pl110::readProgram(text);
    lang::Diagnostics diagnostics = reading.diagnostics;
    if (diagnostics.empty() && !scenario.isEmpty())
        diagnostics = pl110::checkProgram(reading.program); // only a checked program runs
    if (!diagnostics.empty()) {
        printDiagnostics(path, diagnostics);
        return Failed;
    }
    const std::vector<pl110::NumberedRung> rungs = pl110::numberedRungs(reading.program);
    if (network >= 1 && network <= static_cast<int>(rungs.size())) {
        const pl110::NumberedRung& rung = rungs[static_cast<std::size_t>(network - 1)];
        pl110::RungLayoutContext context;
        context.title = QStringLiteral("Rung %1").arg(network);
        context.comment = QString::fromStdString(rung.comment);
        context.statement = static_cast<std::uint32_t>(network);
        int status = Ok;
        std::optional<render::PowerSnapshot> power;
        if (!scenario.isEmpty()) {
            pl110::ScanEngine engine(reading.program);
            const auto [ran, drawable] = runToEnd(scenario, reading.program, engine);
            if (!drawable)
                return ran;
            status = ran;
            power = render::snapshotOfMarks(engine.marks());
        }
        const QString error = drawing().writeNetworkPicture(
            output, pl110::layoutRung(*rung.rung, context), power ? &*power : nullptr,
            QStringLiteral("%1 rung %2").arg(path).arg(network));
        if (!error.isEmpty()) {
            std::fprintf(stderr, "rungsmith-cli: %s\n", qPrintable(error));
            return UsageOrIo;
        }
        return status;
    }
    std::fprintf(stderr, "rungsmith-cli: %s: the program has %d rung(s), not %d\n",
                 qPrintable(path), static_cast<int>(rungs.size()), network);
    return Failed;
}

namespace {

// The program, its reading errors printed; nothing when it has some.
std::optional<pl110::Program> readOrReport(const std::string& text, const QString& path) {
    pl110::ProgramReading reading = pl110::readProgram(text);
    if (reading.diagnostics.empty())
        return std::move(reading.program);
    printDiagnostics(path, reading.diagnostics);
    return std::nullopt;
}

int written(const QString& out, std::string_view text) {
    const QString error = project::writeTextFile(out, text);
    if (error.isEmpty())
        return Ok;
    std::fprintf(stderr, "rungsmith-cli: %s\n", qPrintable(error));
    return UsageOrIo;
}

} // namespace

int exportPl110Names(const std::string& text, const QString& path, const QString& out) {
    const auto program = readOrReport(text, path);
    return program ? written(out, pl110::exportNamesCsv(*program)) : Failed;
}

int importPl110Names(const std::string& text, const QString& path, const QString& csvPath,
                     const QString& out) {
    const auto program = readOrReport(text, path);
    if (!program)
        return Failed;
    const project::FileText csv = project::readTextFile(csvPath);
    if (!csv.error.isEmpty()) {
        std::fprintf(stderr, "rungsmith-cli: %s\n", qPrintable(csv.error));
        return UsageOrIo;
    }
    const pl110::NameCsvImport imported = pl110::importNamesCsv(*program, csv.text);
    for (const auto& problem : imported.problems)
        std::fprintf(stderr, "%s:%d:%d: error: %s\n", qPrintable(csvPath), problem.line,
                     problem.column, lang::visibleText(problem.message).c_str());
    if (!imported.problems.empty())
        return Failed;
    return written(out, pl110::printProgram(imported.program));
}

int testPl110(const QString& path, const std::string& text, const QStringList& scenarios,
              const QString& vcd) {
    const auto program = checkedPl110(path, text);
    if (!program)
        return Failed;
    const pl110::ScenarioNames names(*program);
    pl110::ScanEngine engine(*program);
    int passed = 0;
    int failed = 0;
    for (const QString& scenarioPath : scenarios) {
        const project::FileText file = project::readTextFile(scenarioPath);
        if (!file.error.isEmpty()) {
            std::fprintf(stderr, "rungsmith-cli: %s\n", qPrintable(file.error));
            return UsageOrIo;
        }
        const pl110::Scenario scenario = pl110::parseScenario(file.text, names);
        const std::vector<pl110::Address> traced =
            pl110::traceSignals(*program, pl110::touchedBy(scenario));
        sim::VcdWriter trace(pl110::vcdSignals(traced));
        const sim::ScenarioReport report = pl110::runScenario(
            scenarioPath.toStdString(), scenario, engine, [&](const pl110::ScanEngine& now) {
                if (vcd.isEmpty())
                    return;
                std::vector<std::int64_t> values;
                values.reserve(traced.size());
                for (const pl110::Address& address : traced)
                    values.push_back(now.value(address));
                trace.sample(now.timeMs(), values);
            });
        printReport(report);
        passed += report.passed;
        failed += report.failed;
        if (!vcd.isEmpty() && report.diagnostics.empty()) {
            const QString out = tracePath(vcd, scenarioPath, scenarios.size() > 1);
            if (const int status =
                    written(out, trace.text("Rungsmith scenario " +
                                            QFileInfo(scenarioPath).fileName().toStdString()));
                status != Ok)
                return status;
        }
    }
    std::fprintf(stdout, "%d passed, %d failed\n", passed, failed);
    return failed ? Failed : Ok;
}

} // namespace rs::cli
