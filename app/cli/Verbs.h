// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "compiler/ProgramCheck.h"

#include <QString>

#include <cstdio>

namespace rs::cli {

// Exit statuses of the command-line contract.
enum ExitStatus { Ok = 0, Failed = 1, UsageOrIo = 2 };

struct Streams {
    std::FILE* out = stdout;
    std::FILE* err = stderr;
};

int runCheck(const QString& path, const compiler::CheckOptions& options, Streams streams);
int runCompile(const QString& path, const QString& output, const compiler::CheckOptions& options,
               Streams streams);
int runFormat(const QString& path, Streams streams);

} // namespace rs::cli
