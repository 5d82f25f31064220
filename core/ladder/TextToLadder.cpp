// SPDX-License-Identifier: GPL-3.0-or-later
#include "TextToLadder.h"

#include "ElementVocabulary.h"

#include "blocks/BlockInstance.h"
#include "project/Annotation.h"

namespace rs::ladder {

namespace {

using lang::ExprKind;

Element toElement(const lang::Expr& expr) {
    switch (expr.kind) {
    case ExprKind::Edge:
        return Contact{*kindOf(ElementNode{expr}), expr.operand, expr.operandNegated};
    case ExprKind::Timer:
        return TimerBox{expr.timer, expr.preset, expr.negated};
    case ExprKind::Compare:
        return ComparisonBox{expr.operand, expr.compare, expr.right, expr.negated};
    case ExprKind::Contact:
        return Contact{*kindOf(ElementNode{expr}), expr.operand, false};
    case ExprKind::Or:
    case ExprKind::And:
        break;
    }
    return Contact{expr.negated ? ElementKind::NormallyClosed : ElementKind::NormallyOpen,
                   expr.operand, false};
}

// The comment text of a ";@network" record, or nothing for any other line.
std::optional<std::string> networkComment(const lang::Line& line) {
    const auto annotation = project::annotationOn(line);
    if (annotation && annotation->kind == "network")
        return annotation->value("comment");
    return std::nullopt;
}

void addStatement(Network& network, const lang::Line& line, const lang::Statement& statement) {
    Rung rung = toRung(statement, line.comment);
    if (network.record && !network.items.empty())
        if (auto* previous = std::get_if<Rung>(&network.items.back());
            previous && canJoin(*previous, rung)) {
            previous->outputs.push_back(std::move(rung.outputs.front()));
            return;
        }
    network.items.emplace_back(std::move(rung));
}

} // namespace

Circuit toCircuit(const lang::Expr& expr) {
    if (expr.kind == ExprKind::And || expr.kind == ExprKind::Or) {
        std::vector<Circuit> parts;
        parts.reserve(expr.children.size());
        for (const auto& child : expr.children)
            parts.push_back(toCircuit(child));
        return expr.kind == ExprKind::And ? Circuit::series(std::move(parts))
                                          : Circuit::parallel(std::move(parts));
    }
    Circuit circuit = Circuit::of(toElement(expr));
    circuit.location = expr.location;
    return circuit;
}

Output toOutput(const lang::Statement& statement, const std::optional<std::string>& comment) {
    Output output;
    output.kind = statement.kind;
    output.target = statement.target;
    output.relativeJump = statement.relativeJump;
    output.jumpStep = statement.jumpStep;
    output.assignment = *statement.assignment;
    output.comment = comment;
    output.location = statement.location;
    return output;
}

Rung toRung(const lang::Statement& statement, const std::optional<std::string>& comment) {
    Rung rung;
    if (statement.condition)
        rung.condition = toCircuit(*statement.condition);
    rung.outputs.push_back(toOutput(statement, comment));
    return rung;
}

StepLadder toLadder(const lang::Step& step, const BlockShown& shown) {
    StepLadder ladder;
    std::vector<blocks::BlockInstance> instances;
    for (auto& instance : blocks::findInstances(step).instances)
        if (!shown || shown(instance))
            instances.push_back(std::move(instance));
    auto nextInstance = instances.begin();
    bool grouping = false;
    for (std::size_t index = 0; index < step.lines.size(); ++index) {
        const lang::Line& line = step.lines[index];
        if (nextInstance != instances.end() && nextInstance->record == index) {
            const auto first = step.lines.begin() + std::ptrdiff_t(index);
            const auto last = step.lines.begin() + std::ptrdiff_t(nextInstance->end) + 1;
            Network network;
            network.block = BlockCall{std::move(*nextInstance), {first, last}};
            ladder.networks.push_back(std::move(network));
            index = ladder.networks.back().block->instance.end;
            ++nextInstance;
            grouping = false; // what follows is not part of the block
            continue;
        }
        if (auto comment = networkComment(line)) {
            const auto& record = std::get<lang::CommentLine>(line.body);
            ladder.networks.push_back({std::move(*comment), record, {}, {}});
            grouping = true;
            continue;
        }
        const auto* statement = std::get_if<lang::Statement>(&line.body);
        if (statement && !grouping)
            ladder.networks.emplace_back();
        if (ladder.networks.empty())
            ladder.leading.push_back(line);
        else if (statement)
            addStatement(ladder.networks.back(), line, *statement);
        else
            ladder.networks.back().items.emplace_back(line);
    }
    return ladder;
}

} // namespace rs::ladder
