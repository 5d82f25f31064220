// SPDX-License-Identifier: GPL-3.0-or-later
#include "TimingExample.h"

#include "blocks/BlockInstance.h"
#include "blocks/ProjectInstances.h"
#include "blocks/UnitVariables.h"
#include "sim/ScenarioRunner.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

namespace rs::blockdoc {

namespace {

// An example is a page of text; anything larger is not one.
constexpr qint64 kMaxExampleBytes = 1 << 20;

bool readText(const QString& path, std::string& text, std::string& problem) {
    QFile file(path);
    if (!file.exists()) {
        problem = QDir::toNativeSeparators(path).toStdString() + ": no such file";
        return false;
    }
    if (file.size() > kMaxExampleBytes || !file.open(QIODevice::ReadOnly)) {
        problem = QDir::toNativeSeparators(path).toStdString() + ": cannot be read";
        return false;
    }
    const QByteArray bytes = file.readAll();
    text.assign(bytes.constData(), static_cast<std::size_t>(bytes.size()));
    return true;
}

std::string placed(const QString& path, const lang::Diagnostic& diagnostic) {
    return QDir::toNativeSeparators(path).toStdString() + ":" + std::to_string(diagnostic.line) +
           ":" + std::to_string(diagnostic.column) + ": " + diagnostic.message;
}

const lang::Diagnostic* firstError(const lang::Diagnostics& diagnostics) {
    for (const lang::Diagnostic& d : diagnostics)
        if (d.severity == lang::Severity::Error)
            return &d;
    return nullptr;
}

// The bound pins of the first instance of the block: address and pin name.
std::vector<std::pair<lang::Address, std::string>>
instancePins(const project::Project& project, const blocks::BlockDefinition& block) {
    std::vector<std::pair<lang::Address, std::string>> pins;
    for (const lang::UnitProgram& unit : project.program.units)
        for (const lang::Step& step : unit.steps)
            for (const blocks::BlockInstance& instance : blocks::findInstances(step).instances) {
                if (!blocks::sameName(instance.type, block.name))
                    continue;
                const auto names = blocks::unitNames(project.program, unit.station());
                for (const blocks::Pin& pin : block.pins)
                    if (const blocks::Binding* bound = instance.findPin(pin.name))
                        if (const auto address = blocks::operandAddress(names, bound->operand))
                            pins.emplace_back(*address, pin.name);
                return pins;
            }
    return pins;
}

} // namespace

TimingExampleFiles timingExampleFiles(const blocks::LoadedLibrary& library,
                                      const blocks::BlockDefinition& block) {
    const QDir folder(QFileInfo(library.path)
                          .absoluteDir()
                          .filePath(QString::fromStdString(library.library.name)));
    const QString name = QString::fromStdString(block.name);
    return {folder.filePath(name + QStringLiteral(".sps")),
            folder.filePath(name + QStringLiteral(".scn"))};
}

TimingExample runTimingExample(const blocks::LoadedLibrary& library,
                               const blocks::BlockDefinition& block) {
    TimingExample example;
    const TimingExampleFiles files = timingExampleFiles(library, block);
    std::string projectText;
    std::string scenarioText;
    if (!readText(files.project, projectText, example.problem) ||
        !readText(files.scenario, scenarioText, example.problem))
        return example;

    blocks::LibrarySet libraries;
    libraries.libraries.push_back(library);
    const blocks::ProjectWithInstances read =
        blocks::readProjectWithInstances(projectText, libraries);
    if (const lang::Diagnostic* error = firstError(read.read.diagnostics)) {
        example.problem = placed(files.project, *error);
        return example;
    }
    const compiler::CompileResult compiled =
        blocks::compileProject(read.read.project, read.read.diagnostics);
    if (const lang::Diagnostic* error = firstError(compiled.diagnostics)) {
        example.problem = placed(files.project, *error);
        return example;
    }
    const auto pins = instancePins(read.read.project, block);
    if (pins.empty()) {
        example.problem = QDir::toNativeSeparators(files.project).toStdString() +
                          ": no instance of " + block.name + " with a pin bound to a variable";
        return example;
    }

    const sim::OperandNames names(read.read.project);
    const sim::Scenario scenario = sim::parseScenario(scenarioText, names);
    if (!scenario.diagnostics.empty()) {
        example.problem = placed(files.scenario, scenario.diagnostics.front());
        return example;
    }
    for (const auto& [address, pin] : pins)
        if (example.recording.add(address))
            example.labels.push_back(pin);
    sim::Simulation simulation(compiled.images);
    const sim::ScenarioReport report =
        sim::runScenario(files.scenario.toStdString(), scenario, simulation, nullptr,
                         [&example](const sim::Simulation& s) { example.recording.sample(s); });
    example.passed = report.passed;
    example.failed = report.failed;
    return example;
}

} // namespace rs::blockdoc
