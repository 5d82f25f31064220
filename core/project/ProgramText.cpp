// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProgramText.h"

#include "Annotation.h"
#include "BlankLines.h"
#include "lang/Printer.h"

namespace rs::project {

namespace {

bool isRecord(const lang::Line& line) {
    const auto* comment = std::get_if<lang::CommentLine>(&line.body);
    if (!comment)
        return false;
    try {
        return parseAnnotation(comment->text).has_value();
    } catch (const AnnotationError&) {
        return true; // a malformed record is still the IDE's, not the program's
    }
}

} // namespace

std::string programText(const Project& project) {
    lang::Document document = project.program;
    std::erase_if(document.preamble, isRecord);
    for (auto& unit : document.units) {
        std::erase_if(unit.declarations, isRecord);
        for (auto& step : unit.steps)
            std::erase_if(step.lines, isRecord);
    }
    tidyBlankLines(document);
    return lang::print(document);
}

} // namespace rs::project
