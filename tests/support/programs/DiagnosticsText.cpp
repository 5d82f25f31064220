// SPDX-License-Identifier: GPL-3.0-or-later
#include "DiagnosticsText.h"

namespace rs::test {

std::string diagnosticsText(const lang::Diagnostics& diagnostics) {
    std::string text;
    for (const auto& d : diagnostics)
        text += std::to_string(d.line) + ":" + std::to_string(d.column) + ": " + d.message + "\n";
    return text;
}

std::string problemsText(const compiler::CompileResult& result) {
    std::string text;
    for (const auto& d : result.diagnostics)
        text += std::to_string(d.line) + ":" + std::to_string(d.column) + ": " +
                (d.severity == lang::Severity::Error ? "error" : "warning") + ": " + d.message +
                "\n";
    return text;
}

lang::Address addressOf(const char* word) {
    return lang::readAddressWord(word).address;
}

} // namespace rs::test
