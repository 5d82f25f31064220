// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "compiler/Compiler.h"
#include "compiler/ProgramCheck.h"

#include <QString>

#include <string>

namespace rs::ui {

// What Build > Compile and the text page's check both do, on any thread: the
// project's canonical text read again with its block instances (so that an
// instance's problems are found), then compiled. Diagnostics are lines of
// that text.
compiler::CompileResult compileProjectText(const std::string& canonicalText,
                                           const QString& executableDir, const QString& projectPath,
                                           const compiler::CheckOptions& options,
                                           compiler::Output output = compiler::Output::Images);

// The diagnostics that concern the code of one unit, with lines of its code.
lang::Diagnostics unitCodeDiagnostics(const std::string& canonicalText,
                                      const lang::Diagnostics& diagnostics, int station);

} // namespace rs::ui
