// SPDX-License-Identifier: GPL-3.0-or-later
#include "Diagnostic.h"

#include <algorithm>
#include <tuple>

namespace rs::lang {

int errorCount(const Diagnostics& diagnostics) {
    return static_cast<int>(std::count_if(diagnostics.begin(), diagnostics.end(),
                                          [](auto& d) { return d.severity == Severity::Error; }));
}

std::string visibleText(std::string_view text) {
    const auto visible = [](char c) {
        const auto byte = static_cast<unsigned char>(c);
        return byte >= 0x20 && byte != 0x7F;
    };
    // Most messages have nothing to show otherwise: copied whole.
    if (std::all_of(text.begin(), text.end(), visible))
        return std::string(text);
    std::string shown;
    shown.reserve(text.size());
    for (char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (visible(c)) {
            shown += c;
            continue;
        }
        switch (c) {
        case '\0':
            shown += "\\0";
            break;
        case '\t':
            shown += "\\t";
            break;
        case '\n':
            shown += "\\n";
            break;
        case '\r':
            shown += "\\r";
            break;
        default: {
            static constexpr char kHex[] = "0123456789ABCDEF";
            shown += "\\x";
            shown += kHex[byte >> 4];
            shown += kHex[byte & 0xF];
        }
        }
    }
    return shown;
}

std::string formatDiagnostic(const std::string& fileName, const Diagnostic& diagnostic) {
    std::string text;
    text.reserve(fileName.size() + diagnostic.message.size() + 32);
    text += fileName;
    text += ':';
    text += std::to_string(diagnostic.line);
    text += ':';
    text += std::to_string(diagnostic.column);
    text += diagnostic.severity == Severity::Error ? ": error: " : ": warning: ";
    text += visibleText(diagnostic.message);
    return text;
}

void sortByPlace(Diagnostics& diagnostics) {
    const auto before = [](const Diagnostic& a, const Diagnostic& b) {
        return std::tie(a.line, a.column) < std::tie(b.line, b.column);
    };
    // Sorted already, as they often are, they are not copied into a buffer of
    // their size and back (a large project's warnings: megabytes).
    if (!std::is_sorted(diagnostics.begin(), diagnostics.end(), before))
        std::stable_sort(diagnostics.begin(), diagnostics.end(), before);
}

} // namespace rs::lang
