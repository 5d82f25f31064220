// SPDX-License-Identifier: GPL-3.0-or-later
#include "RandomNetworks.h"

#include "project/Annotation.h"

namespace rs::test {

namespace {

std::string randomComment(RandomCondition& random) {
    static const char* const comments[] = {"", "Safety outputs", "Muting \"A\" and B", "två\nrader",
                                           "back\\slash"};
    return comments[random.uniform(0, 4)];
}

} // namespace

void addNetworkStructure(lang::Step& step, RandomCondition& random) {
    std::vector<lang::Line> lines;
    const lang::Statement* previous = nullptr;
    for (auto& line : step.lines) {
        if (random.chance(20)) {
            project::Annotation record{"network", {}, {{"comment", randomComment(random)}}};
            if (random.chance(20))
                record.attributes.emplace_back("collapsed", "yes");
            lines.push_back(
                {lang::CommentLine{project::formatAnnotation(record), random.chance(20)},
                 std::nullopt,
                 {}});
        }
        if (auto* statement = std::get_if<lang::Statement>(&line.body)) {
            if (previous && random.chance(40))
                statement->condition = previous->condition;
            previous = statement;
        }
        lines.push_back(line);
    }
    step.lines = std::move(lines);
}

} // namespace rs::test
