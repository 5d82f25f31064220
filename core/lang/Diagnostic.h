// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "SourceLocation.h"

#include <string>
#include <string_view>
#include <vector>

namespace rs::lang {

enum class Severity { Error, Warning };

struct Diagnostic {
    Severity severity = Severity::Error;
    int line = 0;
    int column = 0;
    std::string message;
};

using Diagnostics = std::vector<Diagnostic>;

int errorCount(const Diagnostics& diagnostics);

// In the order of their places in the file; of one place, in the order given.
void sortByPlace(Diagnostics& diagnostics);

// The text with every control character written visibly (\0, \t, \x01), so
// a message quoting source text is never cut at a NUL or broken across lines.
std::string visibleText(std::string_view text);

// "FILE:LINE:COLUMN: error: MESSAGE", the form of the command-line contract;
// the message as visibleText shows it.
std::string formatDiagnostic(const std::string& fileName, const Diagnostic& diagnostic);

} // namespace rs::lang
