// SPDX-License-Identifier: GPL-3.0-or-later
#include "Project.h"

#include "Annotation.h"

#include <set>

namespace rs::project {

std::string Project::name() const {
    for (const auto& line : program.preamble)
        if (auto* directive = std::get_if<lang::Directive>(&line.body))
            if (directive->keyword == "name")
                return directive->text;
    return {};
}

std::vector<int> Project::stations() const {
    std::set<int> stations;
    for (const auto& line : program.preamble)
        if (auto* declaration = std::get_if<lang::Declaration>(&line.body))
            if (auto* id = std::get_if<lang::IdDeclaration>(&declaration->body))
                stations.insert(id->station);
    for (const auto& unit : program.units)
        stations.insert(unit.station());
    return {stations.begin(), stations.end()};
}

std::vector<Network> networksOf(const lang::Step& step) {
    std::vector<Network> networks;
    bool grouping = false;
    for (const auto& line : step.lines) {
        if (auto* comment = std::get_if<lang::CommentLine>(&line.body)) {
            std::optional<Annotation> annotation;
            try {
                annotation = parseAnnotation(comment->text);
            } catch (const AnnotationError&) {
                // Reading reported it; while it is malformed it is an ordinary comment.
            }
            if (annotation && annotation->kind == "network") {
                networks.push_back({annotation->value("comment"), {}});
                grouping = true;
                continue;
            }
        }
        const bool isStatement = std::holds_alternative<lang::Statement>(line.body);
        if (isStatement && !grouping)
            networks.push_back({});
        if (networks.empty())
            continue; // comments before the first network belong to the step
        networks.back().lines.push_back(&line);
    }
    return networks;
}

} // namespace rs::project
