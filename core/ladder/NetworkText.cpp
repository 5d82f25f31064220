// SPDX-License-Identifier: GPL-3.0-or-later
#include "NetworkText.h"

#include "LadderToText.h"
#include "TextToLadder.h"
#include "lang/OperandWalk.h"
#include "lang/Parser.h"
#include "lang/Printer.h"
#include "project/Annotation.h"

namespace rs::ladder {

namespace {

void unname(lang::Statement& statement) {
    lang::forEachOperand(statement, [](lang::Operand& operand) { operand.name = {}; });
}

constexpr int kStation = 0;

std::string stepHeader() {
    return "! pgm_pluto:00\n" + lang::toString(lang::StepAddress{kStation, 0, 0}) + "\n";
}

} // namespace

std::string networksText(const std::vector<Network>& networks) {
    lang::Document document;
    lang::UnitProgram unit;
    unit.header.body = lang::Declaration{lang::ProgramDeclaration{kStation}, {}};
    lang::Step step;
    step.address = {kStation, 0, 0};
    StepLadder ladder;
    ladder.networks = networks;
    // A record on every network keeps them apart, whatever they hold.
    for (auto& network : ladder.networks)
        if (!network.record)
            network.record = lang::CommentLine{
                project::formatAnnotation({"network", {}, {{"comment", network.comment}}}), false};
    step.lines = toLines(ladder);
    for (auto& line : step.lines)
        if (auto* statement = std::get_if<lang::Statement>(&line.body))
            unname(*statement);
    unit.steps.push_back(std::move(step));
    document.units.push_back(std::move(unit));
    const std::string text = lang::print(document);
    return text.substr(stepHeader().size());
}

NetworksReading readNetworksText(std::string_view text) {
    const lang::ParseResult parsed = lang::parse(stepHeader() + std::string(text) + "\n");
    for (const auto& diagnostic : parsed.diagnostics)
        if (diagnostic.severity == lang::Severity::Error)
            return {{}, "line " + std::to_string(diagnostic.line - 2) + ": " + diagnostic.message};
    if (parsed.document.units.size() != 1 || parsed.document.units.front().steps.size() != 1)
        return {{}, "the text holds more than networks"};
    for (const auto& line : parsed.document.units.front().steps.front().lines)
        if (const auto* statement = std::get_if<lang::Statement>(&line.body))
            for (const lang::Operand* operand :
                 {&statement->target, &statement->assignment->target})
                if (operand->isName())
                    return {{},
                            "the text uses the name " + operand->name +
                                "; networks on the "
                                "clipboard use addresses"};
    StepLadder ladder = toLadder(parsed.document.units.front().steps.front());
    // A pasted instance is a new one: it gets its own private variables and
    // statements when the project expands it, never the copied instance's.
    for (auto& network : ladder.networks)
        if (network.block) {
            blocks::BlockInstance instance = std::move(network.block->instance);
            instance.privates.clear();
            network.block = unexpandedCall(std::move(instance));
        }
    return {std::move(ladder.networks), {}};
}

} // namespace rs::ladder
