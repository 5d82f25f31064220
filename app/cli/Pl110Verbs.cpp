// SPDX-License-Identifier: GPL-3.0-or-later
#include "Pl110Verbs.h"

#include "ProjectLoading.h"
#include "Verbs.h"
#include "pl110/ProgramCheck.h"
#include "pl110/ProgramText.h"
#include "project/ProjectFile.h"

namespace rs::cli {

std::optional<std::string> pl110Text(const QString& path) {
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

} // namespace rs::cli
