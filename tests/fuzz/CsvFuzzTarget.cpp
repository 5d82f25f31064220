// SPDX-License-Identifier: GPL-3.0-or-later
#include "FuzzFailure.h"

#include "project/ProjectFile.h"
#include "project/Utf8Text.h"
#include "project/VariableCsv.h"

#include <cstdint>
#include <string_view>

namespace {

using rs::fuzz::fail;

const char* kProject = "$name Csv\n"
                       "! id_pluto:00=000000000000\n"
                       "! type_pluto:00=A20,is3\n"
                       "! id_pluto:01=000000000000\n"
                       "! type_pluto:01=B20,is2\n"
                       "! I0.0=Start\n"
                       "! pgm_pluto:00\n"
                       "! M0.0=Alpha\n"
                       "S0.0_0\n"
                       "Q0.2 = Start * Alpha\n"
                       "! pgm_pluto:01\n"
                       "S1.0_0\n";

} // namespace

// Any input: importing never crashes. What it imports is a project whose text
// is UTF-8, reads back without errors, and exports to a CSV that imports
// into it again changing nothing and exports the same again.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const rs::project::ProjectReadResult read = rs::project::readProject(kProject);
    const std::string_view csv(reinterpret_cast<const char*>(data), size);
    const rs::project::CsvImport imported = rs::project::importVariablesCsv(read.project, csv, {});
    for (const auto& problem : imported.problems)
        if (problem.line < 1 || problem.column < 1)
            fail("a problem without its place");
    const std::string text = rs::project::writeProject(imported.project);
    if (rs::project::findTextFault(text))
        fail("the imported project is not UTF-8 text");
    const rs::project::ProjectReadResult again = rs::project::readProject(text);
    if (!again.ok())
        fail("the imported project does not read back");
    const std::string exported = rs::project::exportVariablesCsv(again.project, {});
    const rs::project::CsvImport reimported =
        rs::project::importVariablesCsv(again.project, exported, {});
    if (!reimported.problems.empty() || !reimported.changes.empty())
        fail("the exported CSV does not import unchanged");
    const rs::project::ProjectReadResult third =
        rs::project::readProject(rs::project::writeProject(reimported.project));
    if (rs::project::exportVariablesCsv(third.project, {}) != exported)
        fail("export, import, export differ");
    return 0;
}
