// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProjectProperties.h"

#include "BlankLines.h"

namespace rs::project {

std::optional<std::string> checkProjectName(std::string_view name) {
    if (name.find_first_not_of(" \t") == name.npos)
        return "a project needs a name";
    if (name.find_first_of("\r\n") != name.npos)
        return "a project name is one line";
    if (name.find(';') != name.npos)
        return "a project name cannot contain ';', which starts a comment";
    if (name.front() == ' ' || name.front() == '\t' || name.back() == ' ' || name.back() == '\t')
        return "a project name does not start or end with a space";
    return std::nullopt;
}

Project newProject(std::string_view name, std::string description, bool includeSource) {
    Project project;
    project.program.preamble.push_back(
        {lang::Directive{"name", std::string(name)}, std::nullopt, {}});
    project.description = std::move(description);
    project.includeSource = includeSource;
    return project;
}

std::optional<std::string> setProjectName(Project& project, std::string_view name) {
    if (auto problem = checkProjectName(name))
        return problem;
    auto& preamble = project.program.preamble;
    for (auto& line : preamble) {
        if (auto* directive = std::get_if<lang::Directive>(&line.body);
            directive && directive->keyword == "name") {
            directive->text = std::string(name);
            return std::nullopt;
        }
    }
    preamble.insert(preamble.begin(),
                    {lang::Directive{"name", std::string(name)}, std::nullopt, {}});
    tidyBlankLines(project.program);
    return std::nullopt;
}

} // namespace rs::project
