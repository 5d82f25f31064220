// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QCommandLineParser>
#include <QStringList>

namespace rs::cli {

// One run of rungsmith-cli as a verb sees it: its positional arguments (after
// the verb) and the parsed options.
struct Invocation {
    QStringList arguments;
    const QCommandLineParser& options;
};

// A verb of the command line: its name, its synopsis for --help, and what it does.
// Which targets' files a verb reads (docs/pl110.md lists the PL110's verbs).
enum class Targets { PlutoOnly, PlutoAndPl110 };

struct Verb {
    const char* name;
    const char* synopsis;
    int (*run)(const Invocation&);
    Targets targets = Targets::PlutoOnly;
};

} // namespace rs::cli
