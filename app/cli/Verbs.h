// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ProjectLoading.h"
#include "compiler/Compiler.h"
#include "compiler/ProgramCheck.h"

#include <QString>
#include <QStringList>

#include <cstdio>

namespace rs::cli {

// Exit statuses of the command-line contract.
enum ExitStatus { Ok = 0, Failed = 1, UsageOrIo = 2 };

// Says what is wrong with the command and where help is; returns UsageOrIo.
int usage(const QString& message);

struct Streams {
    std::FILE* out = stdout;
    std::FILE* err = stderr;
};

int runCheck(const QString& path, const QStringList& libraryFiles,
             const compiler::CheckOptions& options, Streams streams);
int runCompile(const QString& path, const QString& output, const QStringList& libraryFiles,
               const compiler::CheckOptions& options, Streams streams);
int runFormat(const QString& path, const QStringList& libraryFiles, Streams streams);

// The project compiled, with the diagnostics of reading it first; no images
// when reading it failed.
compiler::CompileResult compiled(const LoadedProject& loaded,
                                 const compiler::CheckOptions& options);

} // namespace rs::cli
