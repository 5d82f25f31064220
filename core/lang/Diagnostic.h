#pragma once

#include "SourceLocation.h"

#include <string>
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

// "FILE:LINE:COLUMN: error: MESSAGE", the form of the command-line contract.
std::string formatDiagnostic(const std::string& fileName, const Diagnostic& diagnostic);

} // namespace rs::lang
