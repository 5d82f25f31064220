// SPDX-License-Identifier: GPL-3.0-or-later
#include "LibraryWriter.h"

#include "LibraryWords.h"

namespace rs::blocks {

namespace {

void appendLines(std::string& out, std::string_view prefix, const std::string& text) {
    if (text.empty())
        return;
    std::size_t start = 0;
    while (true) {
        const std::size_t end = text.find('\n', start);
        out += prefix;
        const std::string_view line =
            std::string_view(text).substr(start, end == std::string::npos ? end : end - start);
        if (!line.empty()) {
            out += ' ';
            out += line;
        }
        out += '\n';
        if (end == std::string::npos)
            return;
        start = end + 1;
    }
}

void appendDescription(std::string& out, std::string_view indent, const Description& description) {
    const std::string prefix(indent);
    appendLines(out, prefix + "description en", description.english);
    appendLines(out, prefix + "description sv", description.swedish);
    appendLines(out, prefix + "description de", description.german);
}

void appendPin(std::string& out, const Pin& pin) {
    out += "    pin ";
    out += pin.name;
    out += ' ';
    out += wordOf(pin.direction);
    out += ' ';
    out += wordOf(pin.kind);
    out += ' ';
    out += wordOf(pin.role);
    if (pin.defaultValue) {
        out += " default=";
        out += *pin.defaultValue;
    }
    if (!pin.operands.empty()) {
        out += " operands=";
        for (std::size_t i = 0; i < pin.operands.size(); ++i) {
            if (i > 0)
                out += ',';
            out += wordOf(pin.operands[i]);
        }
    }
    out += '\n';
}

} // namespace

std::string writeLibrary(const BlockLibrary& library) {
    std::string out = "rungsmith-library 1\n";
    out += "library " + library.name + '\n';
    out += "version " + library.version + '\n';
    appendDescription(out, "", library.description);
    for (const BlockDefinition& block : library.blocks) {
        out += "\nblock " + block.name + '\n';
        out += "    kind ";
        out += wordOf(block.kind);
        out += '\n';
        out += "    version " + block.version + '\n';
        if (block.kind == BlockKind::System)
            out += "    system " + block.systemInstruction + '\n';
        appendDescription(out, "    ", block.description);
        for (const StateMeaning& state : block.states) {
            const std::string prefix = "    state " + stateCodeWord(state.code) + ' ';
            out += prefix + "en " + state.meaning.english + '\n';
            if (!state.meaning.swedish.empty())
                out += prefix + "sv " + state.meaning.swedish + '\n';
            if (!state.meaning.german.empty())
                out += prefix + "de " + state.meaning.german + '\n';
        }
        for (const Pin& pin : block.pins)
            appendPin(out, pin);
        for (const PrivateVariable& variable : block.privates) {
            out += "    private " + variable.name + ' ';
            out += wordOf(variable.kind);
            out += '\n';
        }
        out += "    timers " + std::to_string(block.timers) + '\n';
        for (const std::string& line : block.body)
            out += line.empty() ? std::string("    body\n") : "    body " + line + '\n';
    }
    return out;
}

} // namespace rs::blocks
