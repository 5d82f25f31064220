// SPDX-License-Identifier: GPL-3.0-or-later
#include "ManualNetworks.h"

#include "ladder/UnitLadder.h"
#include "project/ProjectFile.h"

#include <algorithm>
#include <stdexcept>

namespace rs::test {

namespace fs = std::filesystem;

std::vector<fs::path> manualExamples() {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(fs::path(RUNGSMITH_TEST_DATA) / "manual"))
        if (entry.path().extension() == ".sps")
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

project::Project readExample(const fs::path& path) {
    auto file = project::readTextFile(QString::fromStdString(path.string()));
    auto result = project::readProject(file.text);
    if (!file.error.isEmpty() || !result.ok())
        throw std::runtime_error("cannot read " + path.string());
    return std::move(result.project);
}

std::string LaidOutNetwork::describe() const {
    return lang::toString(step) + " network " + std::to_string(number);
}

std::vector<LaidOutNetwork> layOutEveryNetwork(const project::Project& project) {
    std::vector<LaidOutNetwork> all;
    for (const auto& unit : project.program.units) {
        const auto symbols = ladder::SymbolTable::of(project.program, unit.station());
        for (const auto& page : ladder::unitLadder(unit))
            for (std::size_t i = 0; i < page.ladder.networks.size(); ++i) {
                ladder::LayoutContext context;
                context.number = static_cast<int>(i) + 1;
                context.firstStatement = page.firstStatements[i];
                context.symbols = &symbols;
                all.push_back({unit.station(), page.address, context.number,
                               ladder::layoutNetwork(page.ladder.networks[i], context)});
            }
    }
    return all;
}

} // namespace rs::test
