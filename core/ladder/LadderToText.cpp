// SPDX-License-Identifier: GPL-3.0-or-later
#include "LadderToText.h"

#include "ElementVocabulary.h"

#include "project/Annotation.h"

#include <algorithm>

namespace rs::ladder {

namespace {

using lang::Expr;
using lang::ExprKind;

struct ElementToExpr {
    Expr operator()(const Contact& contact) const {
        ElementParts parts;
        parts.operand = contact.operand;
        parts.operandNegated = contact.operandNegated;
        return std::get<Expr>(makeNode(contact.kind, parts));
    }
    Expr operator()(const TimerBox& timer) const {
        Expr expr;
        expr.kind = ExprKind::Timer;
        expr.timer = timer.spelling;
        expr.preset = timer.preset;
        expr.negated = timer.negated;
        return expr;
    }
    Expr operator()(const ComparisonBox& box) const {
        Expr expr;
        expr.kind = ExprKind::Compare;
        expr.operand = box.left;
        expr.compare = box.op;
        expr.right = box.right;
        expr.negated = box.negated;
        return expr;
    }
};

bool needsOwnRecord(const Network& network) {
    if (network.block)
        return false; // its ";@block" record is its own
    return network.record || !network.comment.empty() || statementCount(network) != 1 ||
           (!network.items.empty() && std::holds_alternative<lang::Line>(network.items.front()));
}

lang::Line recordLine(const Network& network) {
    project::Annotation annotation{"network", {}, {}};
    if (network.record) {
        // Keep the record as it was written unless its comment changed; keep
        // whatever else it says either way.
        try {
            if (auto read = project::parseAnnotation(network.record->text)) {
                if (read->value("comment") == network.comment)
                    return {*network.record, std::nullopt, {}};
                annotation = std::move(*read);
            }
        } catch (const project::AnnotationError&) {
            // Not a record after all: write a new one.
        }
    }
    auto& attributes = annotation.attributes;
    attributes.erase(std::remove_if(attributes.begin(), attributes.end(),
                                    [](const auto& a) { return a.first == "comment"; }),
                     attributes.end());
    if (!network.comment.empty() || !network.record)
        attributes.insert(attributes.begin(), {"comment", network.comment});
    lang::CommentLine line{project::formatAnnotation(annotation), false};
    if (network.record)
        line.indented = network.record->indented;
    return {line, std::nullopt, {}};
}

} // namespace

lang::Statement toStatement(const Output& output) {
    lang::Statement statement;
    statement.kind = output.kind;
    statement.target = output.target;
    statement.relativeJump = output.relativeJump;
    statement.jumpStep = output.jumpStep;
    statement.assignment = output.assignment;
    statement.location = output.location;
    return statement;
}

Expr toExpr(const Circuit& circuit) {
    if (circuit.isElement()) {
        Expr expr = std::visit(ElementToExpr{}, circuit.element);
        expr.location = circuit.location;
        return expr;
    }
    Expr expr;
    expr.kind = circuit.kind == Circuit::Kind::Series ? ExprKind::And : ExprKind::Or;
    expr.children.reserve(circuit.parts.size());
    for (const auto& part : circuit.parts)
        expr.children.push_back(toExpr(part));
    return expr;
}

std::vector<lang::Line> toLines(const Rung& rung) {
    std::vector<lang::Line> lines;
    for (const auto& output : rung.outputs) {
        lang::Statement statement = toStatement(output);
        if (rung.condition)
            statement.condition = toExpr(*rung.condition);
        lines.push_back({std::move(statement), output.comment, output.location});
    }
    return lines;
}

std::vector<lang::Line> toLines(const StepLadder& step) {
    std::vector<lang::Line> lines = step.leading;
    const bool anyRecord = std::any_of(step.networks.begin(), step.networks.end(),
                                       [](const Network& n) { return n.record.has_value(); });
    const bool anyNeeds = std::any_of(step.networks.begin(), step.networks.end(), needsOwnRecord);
    bool recording = anyNeeds && !anyRecord;
    for (const auto& network : step.networks) {
        recording = recording || needsOwnRecord(network);
        if (network.block)
            lines.insert(lines.end(), network.block->lines.begin(), network.block->lines.end());
        else if (recording)
            lines.push_back(recordLine(network));
        for (const auto& item : network.items) {
            if (const auto* rung = std::get_if<Rung>(&item)) {
                auto statements = toLines(*rung);
                lines.insert(lines.end(), std::make_move_iterator(statements.begin()),
                             std::make_move_iterator(statements.end()));
            } else {
                lines.push_back(std::get<lang::Line>(item));
            }
        }
    }
    return lines;
}

} // namespace rs::ladder
