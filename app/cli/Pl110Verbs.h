// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>
#include <QStringList>

#include "pl110/Program.h"

#include <optional>
#include <string>

// check and format for a PL110 program (docs/pl110.md): the same verbs, the
// same output contract as for a Pluto project.
namespace rs::cli {

// The file's text when it is a PL110 program ($target PL110); nothing for a
// Pluto project or a file that cannot be read (the Pluto path reports that).
std::optional<std::string> pl110Text(const QString& path);

int checkPl110(const QString& path, const std::string& text);
// The program when it reads and checks without errors; else nothing, with
// the diagnostics and the closing "N Error(s) detected Result=FAILED" printed.
std::optional<pl110::Program> checkedPl110(const QString& path, const std::string& text);
int formatPl110(const QString& path, const std::string& text);
// ladder --network K -o OUT.svg|png [--scenario SCN]: rung K (INIT's rungs,
// then MAIN's) drawn as the IDE draws a network; with a scenario, live as
// the scenario leaves it (its failures printed as `test` prints them).
int ladderPl110(const QString& path, const std::string& text, int network, const QString& output,
                const QString& scenario);
// vars export / import: the names and descriptions as CSV (pl110/NameCsv.h).
int exportPl110Names(const std::string& text, const QString& path, const QString& out);
int importPl110Names(const std::string& text, const QString& path, const QString& csvPath,
                     const QString& out);
// test: each scenario from power on, the failures and the count as for Pluto.
int testPl110(const QString& path, const std::string& text, const QStringList& scenarios,
              const QString& vcd);

} // namespace rs::cli
