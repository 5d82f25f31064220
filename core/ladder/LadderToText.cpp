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

namespace {

// Writes a network; `recording` says whether the networks before it were
// written with records, and then whether it was.
void appendLines(std::vector<lang::Line>& lines, const Network& network, bool& recording) {
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

bool hasRecord(const Network& network) {
    return network.record.has_value();
}

} // namespace

std::vector<lang::Line> toLines(const StepLadder& step) {
    std::vector<lang::Line> lines = step.leading;
    const bool anyRecord = std::any_of(step.networks.begin(), step.networks.end(), hasRecord);
    const bool anyNeeds = std::any_of(step.networks.begin(), step.networks.end(), needsOwnRecord);
    bool recording = anyNeeds && !anyRecord;
    for (const auto& network : step.networks)
        appendLines(lines, network, recording);
    return lines;
}

std::optional<LineRun> networkRunLines(const StepLadder& step, std::size_t first,
                                       std::size_t removed, const std::vector<Network>& added) {
    const auto& networks = step.networks;
    if (first > networks.size() || removed > networks.size() - first)
        return std::nullopt;
    const auto begin = networks.begin() + static_cast<std::ptrdiff_t>(first);
    const auto end = begin + static_cast<std::ptrdiff_t>(removed);
    const auto isBlock = [](const Network& n) {
        return n.block.has_value();
    };
    if (std::any_of(begin, end, isBlock) || std::any_of(added.begin(), added.end(), isBlock))
        return std::nullopt;
    // Whether a network is written with a record depends on the networks
    // before it and, in a step where none had one, on all of them (toLines).
    const auto any = [](auto from, auto to, auto what) {
        return std::any_of(from, to, what);
    };
    const bool recordsKept =
        any(networks.begin(), begin, hasRecord) || any(end, networks.end(), hasRecord);
    const bool needsKept =
        any(networks.begin(), begin, needsOwnRecord) || any(end, networks.end(), needsOwnRecord);
    const bool was = (needsKept || any(begin, end, needsOwnRecord)) &&
                     !(recordsKept || any(begin, end, hasRecord));
    const bool is = (needsKept || any(added.begin(), added.end(), needsOwnRecord)) &&
                    !(recordsKept || any(added.begin(), added.end(), hasRecord));
    if (was != is)
        return std::nullopt;
    bool recording = is || any(networks.begin(), begin, needsOwnRecord);
    // After the run, networks that need no record of their own are written
    // with one only while the networks before them were.
    const bool wasRecording = recording || any(begin, end, needsOwnRecord);
    const bool isRecording = recording || any(added.begin(), added.end(), needsOwnRecord);
    if (wasRecording != isRecording && end != networks.end() && !needsOwnRecord(*end))
        return std::nullopt;

    LineRun run;
    run.first = step.leading.size();
    for (auto network = networks.begin(); network != begin; ++network)
        run.first += lineCount(*network);
    for (auto network = begin; network != end; ++network)
        run.removed += lineCount(*network);
    for (const auto& network : added)
        appendLines(run.lines, network, recording);
    return run;
}

} // namespace rs::ladder
