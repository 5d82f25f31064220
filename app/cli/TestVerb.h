// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "compiler/ProgramCheck.h"
#include "sim/ScenarioRunner.h"

#include <QString>
#include <QStringList>

namespace rs::cli {

// A scenario run's syntax errors to stderr, its failed expectations to stdout.
void printReport(const sim::ScenarioReport& report);

// Where --vcd OUT writes the trace of one scenario: OUT itself, or with
// several scenarios OUT's base name, the scenario's and ".vcd".
QString tracePath(const QString& vcd, const QString& scenario, bool several);

// `test FILE.sps SCENARIO... [--vcd OUT.vcd]`: runs each scenario from power
// on against the compiled project, prints one line per failure and the
// closing "N passed, M failed". With several scenarios and --vcd, each trace
// goes to OUT.<scenario name>.vcd.
int runTest(const QString& project, const QStringList& scenarios, const QString& vcd,
            const QStringList& libraryFiles, const compiler::CheckOptions& options);

} // namespace rs::cli
