// SPDX-License-Identifier: GPL-3.0-or-later
#include "LadderVerbs.h"

#include "Drawing.h"
#include "LivePower.h"
#include "PictureFileName.h"
#include "Pl110Verbs.h"
#include "Verbs.h"
#include "compiler/Compiler.h"
#include "ladder/LadderToText.h"
#include "ladder/Layout.h"
#include "ladder/ProjectLadder.h"
#include "ladder/TextToLadder.h"
#include "project/ProjectFile.h"
#include "sim/ScenarioRunner.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <optional>
#include <set>

namespace rs::cli {

namespace {

int failure(const QString& path, const QString& message) {
    std::fprintf(stderr, "rungsmith-cli: %s: %s\n", qPrintable(path), qPrintable(message));
    return Failed;
}

// A whole number option, or nothing when it is absent or not a number in range.
std::optional<int> number(const Invocation& invocation, const char* name, int low, int high) {
    bool ok = false;
    const int value = invocation.options.value(QLatin1String(name)).toInt(&ok);
    if (!ok || value < low || value > high)
        return std::nullopt;
    return value;
}

// The project with its diagnostics printed; a status other than Ok when it
// cannot be read or has errors.
int read(const QString& path, const Invocation& invocation, LoadedProject& loaded) {
    loaded = loadProject(path, libraryFiles(invocation));
    if (loaded.status != Ok)
        return loaded.status;
    printDiagnostics(path, loaded.diagnostics);
    return loaded.ok() ? Ok : Failed;
}

struct ScenarioPower {
    render::PowerSnapshot power;
    int status = Ok;       // UsageOrIo when unreadable, Failed on errors or failed expectations
    bool drawable = false; // the scenario ran to its end
};

// Compiles the project, runs the scenario from power on and takes the power
// picture of unit `station` as the scenario leaves it. Failed expectations
// are printed as `test` prints them; the state they end in is still drawn.
ScenarioPower runToEnd(const QString& projectPath, const LoadedProject& loaded,
                       const QString& scenarioPath, int station,
                       const std::set<lang::Address>& watched) {
    const project::FileText text = project::readTextFile(scenarioPath);
    if (!text.error.isEmpty()) {
        std::fprintf(stderr, "rungsmith-cli: %s\n", qPrintable(text.error));
        return {{}, UsageOrIo, false};
    }
    const compiler::CompileResult compiled = rs::cli::compiled(loaded, {});
    if (compiled.errors()) {
        for (const auto& diagnostic : compiled.diagnostics)
            if (diagnostic.severity == lang::Severity::Error)
                std::fprintf(stderr, "%s\n",
                             lang::formatDiagnostic(projectPath.toStdString(), diagnostic).c_str());
        return {{}, Failed, false};
    }
    const sim::Scenario scenario = sim::parseScenario(text.text, sim::OperandNames(loaded.project));
    sim::Simulation simulation(compiled.images);
    const sim::ScenarioReport report =
        sim::runScenario(scenarioPath.toStdString(), scenario, simulation);
    for (const auto& line : report.diagnostics)
        std::fprintf(stderr, "%s\n", line.c_str());
    if (!report.diagnostics.empty())
        return {{}, Failed, false};
    for (const auto& line : report.failures)
        std::fprintf(stdout, "%s\n", line.c_str());
    const sim::UnitEngine& engine = *simulation.unit(station);
    render::PowerSnapshot power = render::powerSnapshot(engine);
    for (const lang::Address& address : watched)
        power.values.emplace(address, engine.read(address));
    return {std::move(power), report.failed ? Failed : Ok, true};
}

QString stepName(const lang::StepAddress& step) {
    return QString::fromStdString(lang::toString(step));
}

int firstDifferingLine(const std::string& a, const std::string& b) {
    const auto mismatch = std::mismatch(a.begin(), a.end(), b.begin(), b.end()).first;
    return 1 + static_cast<int>(std::count(a.begin(), mismatch, '\n'));
}

} // namespace

int runLadder(const Invocation& invocation) {
    if (invocation.arguments.size() != 1)
        return usage(QStringLiteral("ladder takes exactly one FILE.sps"));
    if (const auto text = pl110Text(invocation.arguments[0])) {
        const auto rung = number(invocation, "network", 1, 1 << 30);
        if (!rung)
            return usage(QStringLiteral("ladder needs --network K, a rung number from 1"));
        if (!render::isPictureFileName(invocation.options.value(QStringLiteral("output"))))
            return usage(QStringLiteral("ladder needs -o OUT.svg or -o OUT.png"));
        return ladderPl110(invocation.arguments[0], *text, *rung,
                           invocation.options.value(QStringLiteral("output")),
                           invocation.options.value(QStringLiteral("scenario")));
    }
    const auto unit = number(invocation, "unit", 0, 31);
    if (!unit)
        return usage(QStringLiteral("ladder needs --unit U, a station number 0-31"));
    const auto networkNumber = number(invocation, "network", 1, 1 << 30);
    if (!networkNumber)
        return usage(QStringLiteral("ladder needs --network K, a network number from 1"));
    const bool inSequence = invocation.options.isSet(QStringLiteral("sequence")) ||
                            invocation.options.isSet(QStringLiteral("step"));
    const auto sequence = inSequence ? number(invocation, "sequence", 0, 9) : 0;
    const auto stepNumber = inSequence ? number(invocation, "step", 0, 254) : 0;
    if (!sequence || !stepNumber)
        return usage(QStringLiteral("--sequence S (0-9) and --step N (0-254) go together"));
    const QString output = invocation.options.value(QStringLiteral("output"));
    if (!render::isPictureFileName(output))
        return usage(QStringLiteral("ladder needs -o OUT.svg or -o OUT.png"));

    const QString& path = invocation.arguments[0];
    LoadedProject loaded;
    if (const int status = read(path, invocation, loaded); status != Ok)
        return status;
    const lang::StepAddress wanted{*unit, *sequence, *stepNumber};
    // Instances are boxes as the IDE draws them: while they are what their block makes.
    const ladder::ProjectLadder drawn(loaded.project, loaded.places);
    if (!drawn.hasCode(*unit))
        return failure(path, QStringLiteral("unit %1 has no code").arg(*unit));
    const int networks = drawn.networkCount(wanted);
    if (networks < 0)
        return failure(path,
                       QStringLiteral("unit %1 has no step %2").arg(*unit).arg(stepName(wanted)));
    if (*networkNumber > networks)
        return failure(path, QStringLiteral("step %1 has %2 network(s), not %3")
                                 .arg(stepName(wanted))
                                 .arg(networks)
                                 .arg(*networkNumber));
    const ladder::NetworkLayout layout = *drawn.layout(wanted, *networkNumber);
    std::set<lang::Address> pinVariables;
    if (layout.block)
        for (const auto& pin : layout.block->pins)
            if (pin.address)
                pinVariables.insert(*pin.address);
    const QString title = QStringLiteral("%1 network %2").arg(stepName(wanted)).arg(*networkNumber);
    const bool simulated = invocation.options.isSet(QStringLiteral("scenario"));
    ScenarioPower live;
    if (simulated) {
        live = runToEnd(path, loaded, invocation.options.value(QStringLiteral("scenario")), *unit,
                        pinVariables);
        if (!live.drawable)
            return live.status;
    }
    const QString error =
        drawing().writeNetworkPicture(output, layout, simulated ? &live.power : nullptr, title);
    if (!error.isEmpty()) {
        std::fprintf(stderr, "rungsmith-cli: %s\n", qPrintable(error));
        return UsageOrIo;
    }
    return live.status;
}

int runRoundtrip(const Invocation& invocation) {
    if (invocation.arguments.size() != 1)
        return usage(QStringLiteral("roundtrip takes exactly one FILE.sps"));
    const QString& path = invocation.arguments[0];
    LoadedProject loaded;
    if (const int status = read(path, invocation, loaded); status != Ok)
        return status;
    const std::string canonical = project::writeProject(loaded.project);
    for (auto& unit : loaded.project.program.units)
        for (auto& step : unit.steps)
            step.lines = ladder::toLines(ladder::toLadder(step));
    const std::string text = project::writeProject(loaded.project);
    std::fwrite(text.data(), 1, text.size(), stdout);
    if (text != canonical)
        return failure(path, QStringLiteral("line %1 changed on the way through the ladder model")
                                 .arg(firstDifferingLine(canonical, text)));
    return Ok;
}

} // namespace rs::cli
