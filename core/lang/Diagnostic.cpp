#include "Diagnostic.h"

#include <algorithm>

namespace rs::lang {

int errorCount(const Diagnostics& diagnostics) {
    return static_cast<int>(std::count_if(diagnostics.begin(), diagnostics.end(),
                                          [](auto& d) { return d.severity == Severity::Error; }));
}

std::string formatDiagnostic(const std::string& fileName, const Diagnostic& diagnostic) {
    std::string text = fileName;
    text += ':' + std::to_string(diagnostic.line) + ':' + std::to_string(diagnostic.column) + ": ";
    text += diagnostic.severity == Severity::Error ? "error: " : "warning: ";
    text += diagnostic.message;
    return text;
}

} // namespace rs::lang
