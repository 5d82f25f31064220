// SPDX-License-Identifier: GPL-3.0-or-later
// Opening a project whose 1,000 block instances are written without their
// statements (they are expanded on reading) against opening the same project
// with the statements written out (issue 15: within twice the time).
#include "blocks/InstanceStanding.h"
#include "blocks/LibraryReader.h"
#include "blocks/ProjectInstances.h"
#include "ladder/Layout.h"
#include "ladder/UnitLadder.h"
#include "project/ProjectFile.h"

#include <benchmark/benchmark.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace {

using namespace rs;

constexpr int kUnits = 8;
constexpr int kInstancesPerUnit = 125;

// 8 A20 units with 125 EquivalentInputs instances each, Out and Fault bound
// to memories, so each instance takes one private memory.
std::string handWritten() {
    std::string text;
    for (int unit = 0; unit < kUnits; ++unit)
        text += "! id_pluto:0" + std::to_string(unit) + "=000000000000\n";
    for (int unit = 0; unit < kUnits; ++unit) {
        const std::string u = std::to_string(unit);
        text += "! pgm_pluto:0" + u + "\nS" + u + ".0_0\n";
        for (int i = 0; i < kInstancesPerUnit; ++i)
            text += ";@block EquivalentInputs Channel1=\"I" + u + "." + std::to_string(i % 8) +
                    "\" Channel2=\"I" + u + "." + std::to_string((i + 1) % 8) + "\" Out=\"M" + u +
                    "." + std::to_string(i) + "\" Fault=\"M" + u + "." + std::to_string(200 + i) +
                    "\"\n;@end\n";
    }
    return text;
}

blocks::LibrarySet standardLibrary() {
    std::ifstream file(RUNGSMITH_LIBRARIES "/Rungsmith_Basics.rslib", std::ios::binary);
    std::stringstream text;
    text << file.rdbuf();
    blocks::LibraryReadResult read = blocks::readLibrary(text.str());
    if (!read.ok())
        throw std::runtime_error("the standard library does not read");
    blocks::LibrarySet set;
    set.libraries.push_back({std::move(read.library), QStringLiteral("Rungsmith_Basics.rslib"),
                             blocks::LibraryOrigin::Standard});
    return set;
}

const std::string& handText() {
    static const std::string text = handWritten();
    return text;
}

const blocks::LibrarySet& libraries() {
    static const blocks::LibrarySet set = standardLibrary();
    return set;
}

const std::string& writtenOut() {
    static const std::string text = [] {
        const blocks::ProjectWithInstances read =
            blocks::readProjectWithInstances(handText(), libraries());
        if (!read.read.ok() || !read.expanded)
            throw std::runtime_error("the instances do not expand");
        return project::writeProject(read.read.project);
    }();
    return text;
}

void BM_OpenExpandingInstances(benchmark::State& state) {
    for (auto _ : state) {
        blocks::ProjectWithInstances read =
            blocks::readProjectWithInstances(handText(), libraries());
        benchmark::DoNotOptimize(read);
    }
    state.counters["instances"] = kUnits * kInstancesPerUnit;
}
BENCHMARK(BM_OpenExpandingInstances)->Unit(benchmark::kMillisecond);

// The written-out file still holds its records: they are checked against
// their blocks, as opening does.
void BM_OpenWrittenOut(benchmark::State& state) {
    for (auto _ : state) {
        blocks::ProjectWithInstances read =
            blocks::readProjectWithInstances(writtenOut(), libraries());
        benchmark::DoNotOptimize(read);
    }
    state.counters["bytes"] = static_cast<double>(writtenOut().size());
}
BENCHMARK(BM_OpenWrittenOut)->Unit(benchmark::kMillisecond);

const std::string& statementsAlone() {
    static const std::string text = [] {
        std::string plain;
        std::istringstream lines(writtenOut());
        for (std::string line; std::getline(lines, line);)
            if (line.rfind(";@block", 0) != 0 && line.rfind(";@end", 0) != 0)
                plain += line + "\n";
        return plain;
    }();
    return text;
}

// The same statements with no records at all: what the program costs to read.
void BM_OpenStatementsAlone(benchmark::State& state) {
    for (auto _ : state) {
        project::ProjectReadResult read = project::readProject(statementsAlone());
        benchmark::DoNotOptimize(read);
    }
}
BENCHMARK(BM_OpenStatementsAlone)->Unit(benchmark::kMillisecond);

// What a ladder page does with every unit when it opens and after each edit:
// how each instance stands, the ladder with boxes, and every network laid out.
std::size_t layOutUnits(const project::Project& project, bool boxes) {
    std::size_t elements = 0;
    for (const auto& unit : project.program.units) {
        std::vector<blocks::InstanceStatus> statuses;
        if (boxes)
            statuses = blocks::instanceStatuses(project.program, unit.station(), libraries());
        const auto shown = [&](const lang::Step&, const blocks::BlockInstance& instance) {
            for (const auto& status : statuses)
                if (status.instance.record == instance.record)
                    return status.standing == blocks::Standing::AsMade;
            return false;
        };
        const auto symbols = ladder::SymbolTable::of(project.program, unit.station());
        for (const auto& page : ladder::unitLadder(unit, shown)) {
            for (std::size_t n = 0; n < page.ladder.networks.size(); ++n) {
                const ladder::Network& network = page.ladder.networks[n];
                ladder::LayoutContext context;
                context.number = static_cast<int>(n) + 1;
                context.firstStatement = page.firstStatements[n];
                context.symbols = &symbols;
                if (network.block)
                    context.block = libraries().libraries[0].library.findBlock("EquivalentInputs");
                const ladder::NetworkLayout layout = ladder::layoutNetwork(network, context);
                elements += layout.elements.size() + (layout.block ? layout.block->pins.size() : 0);
            }
        }
    }
    return elements;
}

void BM_LadderOfInstances(benchmark::State& state) {
    const project::Project project =
        blocks::readProjectWithInstances(writtenOut(), libraries()).read.project;
    for (auto _ : state)
        benchmark::DoNotOptimize(layOutUnits(project, true));
}
BENCHMARK(BM_LadderOfInstances)->Unit(benchmark::kMillisecond);

void BM_LadderOfStatementsAlone(benchmark::State& state) {
    const project::Project project = project::readProject(statementsAlone()).project;
    for (auto _ : state)
        benchmark::DoNotOptimize(layOutUnits(project, false));
}
BENCHMARK(BM_LadderOfStatementsAlone)->Unit(benchmark::kMillisecond);

} // namespace
