// SPDX-License-Identifier: GPL-3.0-or-later
#include "Rungs.h"

namespace rs::pl110 {

namespace {

std::string trimmed(const std::string& text) {
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string::npos)
        return {};
    return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

} // namespace

std::vector<NumberedRung> numberedRungs(const Program& program) {
    std::vector<NumberedRung> rungs;
    for (const auto* part : {&program.init, &program.main}) {
        std::string comment;
        for (const Line& line : *part) {
            if (const auto* note = std::get_if<CommentLine>(&line.body)) {
                if (!comment.empty())
                    comment += '\n';
                comment += trimmed(note->text);
                continue;
            }
            if (const auto* rung = std::get_if<Rung>(&line.body))
                rungs.push_back({static_cast<int>(rungs.size()) + 1, part == &program.init, &line,
                                 rung, std::move(comment)});
            comment.clear();
        }
    }
    return rungs;
}

int rungAtLine(const Program& program, int line) {
    int found = 1;
    for (const NumberedRung& rung : numberedRungs(program))
        if (rung.line->location.line <= line)
            found = rung.number;
    return found;
}

std::string declaredName(const Program& program, const Address& address) {
    for (const Line& line : program.declarations)
        if (const auto* declaration = std::get_if<NameDeclaration>(&line.body);
            declaration && declaration->variable.address == address)
            return declaration->name;
    return {};
}

} // namespace rs::pl110
