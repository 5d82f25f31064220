// SPDX-License-Identifier: GPL-3.0-or-later
#include "StepText.h"

#include "lang/Printer.h"
#include "project/ProjectFile.h"

#include <stdexcept>

namespace rs::test {

project::Project projectWithCode(const std::string& body) {
    const std::string text = "! id_pluto:00=000034AD4AE1\n! type_pluto:00=B46,is3\n"
                             "! I0.12=EStop\n! pgm_pluto:00\n! Q0.17=Lamp\nS0.0_0\n" +
                             body;
    auto result = project::readProject(text);
    if (!result.ok())
        throw std::invalid_argument("test code does not read: " + text);
    return std::move(result.project);
}

lang::Step stepWithCode(const std::string& body) {
    return projectWithCode(body).program.units.front().steps.front();
}

std::string printLines(const std::vector<lang::Line>& lines) {
    lang::Document document;
    lang::UnitProgram unit;
    unit.header = {lang::Declaration{lang::ProgramDeclaration{0}, {}}, std::nullopt, {}};
    unit.steps.push_back({{0, 0, 0}, std::nullopt, {}, lines});
    document.units.push_back(std::move(unit));
    const std::string text = lang::print(document);
    const std::string header = "! pgm_pluto:00\nS0.0_0\n";
    return text.substr(header.size());
}

} // namespace rs::test
