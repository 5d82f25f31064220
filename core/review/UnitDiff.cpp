// SPDX-License-Identifier: GPL-3.0-or-later
#include "UnitDiff.h"

#include "project/Annotation.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <tuple>

namespace rs::review {

namespace {

// What a project says about one unit, besides its networks.
struct UnitFacts {
    bool present = false;
    std::tuple<int, std::string, int> type; // family, type, instruction set
    std::string idCode;
    std::set<std::pair<lang::Address, std::vector<std::string>>> io;
    std::set<lang::Address> exported;
    std::set<lang::Address> remanent;
    std::set<std::pair<lang::Address, std::string>> names;
    std::map<lang::Address, std::string> descriptions;
    std::string description;
    std::vector<std::string> comments;
};

void addDeclaration(UnitFacts& facts, int station, const lang::Line& line) {
    const auto* declaration = std::get_if<lang::Declaration>(&line.body);
    if (!declaration)
        return;
    if (const auto* id = std::get_if<lang::IdDeclaration>(&declaration->body);
        id && id->station == station) {
        facts.present = true;
        std::get<0>(facts.type) = static_cast<int>(id->family);
        facts.idCode = id->idfix;
    } else if (const auto* type = std::get_if<lang::TypeDeclaration>(&declaration->body);
               type && type->station == station) {
        std::get<1>(facts.type) = type->type;
        std::get<2>(facts.type) = type->instructionSet;
    } else if (const auto* io = std::get_if<lang::IoDeclaration>(&declaration->body);
               io && io->io.address.unit == station) {
        auto options = io->options;
        std::sort(options.begin(), options.end());
        facts.io.emplace(io->io.address, std::move(options));
    } else if (const auto* name = std::get_if<lang::NameDeclaration>(&declaration->body);
               name && name->variable.address.unit == station) {
        facts.names.emplace(name->variable.address, name->name);
    }
}

void addComments(UnitFacts& facts, const lang::Line& line) {
    if (line.comment)
        facts.comments.push_back(*line.comment);
    const auto* comment = std::get_if<lang::CommentLine>(&line.body);
    if (!comment)
        return;
    if (!comment->text.starts_with('@'))
        facts.comments.push_back(comment->text);
    else if (const auto annotation = project::annotationOn(line);
             annotation && annotation->kind == "network")
        facts.comments.push_back(annotation->value("comment"));
}

UnitFacts factsOf(const project::Project& project, int station) {
    UnitFacts facts;
    for (const auto& line : project.program.preamble)
        addDeclaration(facts, station, line);
    for (const auto& unit : project.program.units) {
        if (unit.station() != station)
            continue;
        facts.present = true;
        addComments(facts, unit.header);
        for (const auto& line : unit.declarations) {
            addDeclaration(facts, station, line);
            addComments(facts, line);
        }
        for (const auto& step : unit.steps) {
            if (step.comment)
                facts.comments.push_back(*step.comment);
            for (const auto& line : step.lines)
                addComments(facts, line);
        }
    }
    for (const auto& address : project.exportedVariables)
        if (address.unit == station)
            facts.exported.insert(address);
    for (const auto& address : project.remanentVariables)
        if (address.unit == station)
            facts.remanent.insert(address);
    for (const auto& [address, text] : project.variableDescriptions)
        if (address.unit == station)
            facts.descriptions.emplace(address, text);
    if (const auto description = project.unitDescriptions.find(station);
        description != project.unitDescriptions.end())
        facts.description = description->second;
    return facts;
}

} // namespace

std::string UnitDifference::describe() const {
    char number[8];
    std::snprintf(number, sizeof number, "%02d", station);
    return "Pluto " + std::string(number) + ' ' + what;
}

std::vector<UnitDifference> unitDifferences(const project::Project& before,
                                            const project::Project& after) {
    std::set<int> stations;
    for (const auto* project : {&before, &after})
        for (const int station : project->stations())
            stations.insert(station);
    std::vector<UnitDifference> differences;
    for (const int station : stations) {
        const UnitFacts old = factsOf(before, station);
        const UnitFacts now = factsOf(after, station);
        const auto report = [&](bool differs, const char* what) {
            if (differs)
                differences.push_back({station, what});
        };
        if (old.present != now.present) {
            report(true, now.present ? "unit: added" : "unit: removed");
            continue;
        }
        report(old.type != now.type, "type: changed");
        report(old.idCode != now.idCode, "ID code: changed");
        report(old.io != now.io, "I/O options: changed");
        report(old.exported != now.exported || old.remanent != now.remanent,
               "exported and remanent variables: changed");
        report(old.names != now.names || old.descriptions != now.descriptions ||
                   old.description != now.description,
               "names and descriptions: changed");
        report(old.comments != now.comments, "comments: changed");
    }
    return differences;
}

} // namespace rs::review
