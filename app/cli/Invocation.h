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
struct Verb {
    const char* name;
    const char* synopsis;
    int (*run)(const Invocation&);
};

} // namespace rs::cli
