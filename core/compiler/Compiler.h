// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Image.h"
#include "ProgramCheck.h"
#include "Signature.h"
#include "project/Project.h"

#include <string_view>

namespace rs::compiler {

struct CompileResult {
    lang::Diagnostics diagnostics; // sorted by line and column
    std::vector<UnitImage> images; // by station; empty when there are errors
    // Every unit's, by station, those without code too, and the project's
    // (Signature.h); none when there are errors.
    std::vector<UnitSignature> signatures;
    std::uint32_t projectSignature = 0;

    int errors() const { return lang::errorCount(diagnostics); }
};

// What a compile makes besides its diagnostics: the images and signatures,
// or nothing (a check: the same diagnostics, found without the work of the
// images' places, signatures and source text).
enum class Output { Images, DiagnosticsOnly };

// Checks the project against everything the manuals state and, when nothing
// is an error, generates every unit's image. The same project always gives the
// same images. `readFrom`: the text the project was read from, when the
// caller has it; when that is already the canonical text, the project's
// places are the canonical ones and it is not read again.
CompileResult compile(const project::Project& project, const CheckOptions& options = {},
                      std::string_view readFrom = {}, Output output = Output::Images);

// What a check of one unit's code alone needs to know of the others
// (CheckOptions::onlyUnit), from the whole project.
UnitScope unitScope(const project::Project& project, int station, const CheckOptions& options);

// Reads, resolves and compiles project text; syntax errors and check results together.
CompileResult compileText(std::string_view text, const CheckOptions& options = {});

} // namespace rs::compiler
