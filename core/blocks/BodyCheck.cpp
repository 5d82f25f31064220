// SPDX-License-Identifier: GPL-3.0-or-later
#include "BodyCheck.h"

#include "lang/Parser.h"
#include "project/Utf8Text.h"

#include <string_view>
#include <variant>

namespace rs::blocks {

namespace {

// The program around the body when it is parsed: the body starts on the
// third line.
constexpr std::string_view kFrame = "! pgm_pluto:00\nS0.0_0\n";
constexpr int kFrameLines = 2;

template <typename T> std::size_t indexIn(const std::vector<T>& items, const T* item) {
    return static_cast<std::size_t>(item - items.data());
}

int countTimers(const lang::Expr& expr) {
    int count = expr.kind == lang::ExprKind::Timer ? 1 : 0;
    for (const auto& child : expr.children)
        count += countTimers(child);
    return count;
}

} // namespace

std::string sampleOperand(const BlockDefinition& block, const Placeholder& placeholder) {
    if (placeholder.isPrivate) {
        const PrivateVariable* variable = block.findPrivate(placeholder.name);
        const std::size_t n = indexIn(block.privates, variable);
        switch (variable->kind) {
        case PrivateKind::Memory:
            return "M0." + std::to_string(300 + n);
        case PrivateKind::Register:
            return "R0." + std::to_string(70 + n);
        case PrivateKind::DoubleRegister:
            return "DR0." + std::to_string(2 * (70 + n));
        }
    }
    const Pin* pin = block.findPin(placeholder.name);
    const std::size_t n = indexIn(block.pins, pin);
    switch (pin->kind) {
    case PinKind::Bit:
        return "M0." + std::to_string(n);
    case PinKind::Register:
        return "R0." + std::to_string(n);
    case PinKind::DoubleRegister:
        return "DR0." + std::to_string(2 * n);
    case PinKind::Time:
        return "0s10";
    case PinKind::Constant:
        return "1";
    }
    return {};
}

BodyCheckResult checkBody(const BlockDefinition& block) {
    BodyCheckResult result;
    result.pinUsed.assign(block.pins.size(), false);
    result.privateUsed.assign(block.privates.size(), false);
    const auto problem = [&](std::size_t line, int column, std::string message) {
        result.problems.push_back({line, column, std::move(message)});
    };

    bool placeholdersGood = true;
    for (std::size_t i = 0; i < block.body.size(); ++i) {
        const std::string& line = block.body[i];
        const ScannedLine scanned = scanPlaceholders(line);
        if (scanned.fault) {
            problem(i, project::characterColumn(line, scanned.fault->offset),
                    scanned.fault->message);
            placeholdersGood = false;
            continue;
        }
        for (const Placeholder& placeholder : scanned.placeholders) {
            const int column = project::characterColumn(line, placeholder.offset);
            if (placeholder.isPrivate) {
                if (const PrivateVariable* variable = block.findPrivate(placeholder.name)) {
                    result.privateUsed[indexIn(block.privates, variable)] = true;
                    continue;
                }
                problem(i, column,
                        "'{#" + placeholder.name + "}' names no private variable of the block");
            } else {
                if (const Pin* pin = block.findPin(placeholder.name)) {
                    result.pinUsed[indexIn(block.pins, pin)] = true;
                    continue;
                }
                problem(i, column, "'{" + placeholder.name + "}' names no pin of the block");
            }
            placeholdersGood = false;
        }
    }
    // The parser's messages would only repeat a bad placeholder's.
    if (!placeholdersGood || block.body.empty())
        return result;

    std::string program(kFrame);
    std::vector<SubstitutedLine> lines;
    const auto sample = [&block](const Placeholder& p) {
        return sampleOperand(block, p);
    };
    for (const std::string& line : block.body) {
        lines.push_back(substitute(line, sample));
        program += lines.back().text;
        program += '\n';
    }
    // A problem in the substituted text, placed where the author wrote it.
    const auto at = [&](int programLine, int programColumn, std::string message) {
        const auto index = static_cast<std::size_t>(programLine - kFrameLines - 1);
        if (programLine <= kFrameLines || index >= lines.size()) {
            problem(0, 1, std::move(message));
            return;
        }
        const SubstitutedLine& line = lines[index];
        const std::size_t offset = byteOffset(line.text, programColumn);
        const std::size_t source = offset < line.templateOffset.size() ? line.templateOffset[offset]
                                                                       : block.body[index].size();
        problem(index, project::characterColumn(block.body[index], source), std::move(message));
    };

    const lang::ParseResult parsed = lang::parse(program);
    for (const auto& diagnostic : parsed.diagnostics)
        if (diagnostic.severity == lang::Severity::Error)
            at(diagnostic.line, diagnostic.column, diagnostic.message);
    if (!result.problems.empty())
        return result;

    const lang::Document& document = parsed.document;
    const auto notAStatement = [&](const lang::SourceLocation& location) {
        at(location.line, 1,
           "a block's body holds statements only, no declarations, directives or step headers");
    };
    for (const auto& line : document.preamble)
        notAStatement(line.location);
    if (document.units.size() != 1) {
        problem(0, 1, "a block's body holds statements only");
        return result;
    }
    const lang::UnitProgram& unit = document.units.front();
    for (const auto& line : unit.declarations)
        notAStatement(line.location);
    for (std::size_t s = 0; s < unit.steps.size(); ++s) {
        if (s > 0)
            notAStatement(unit.steps[s].location);
        for (const auto& line : unit.steps[s].lines) {
            if (std::holds_alternative<lang::Declaration>(line.body) ||
                std::holds_alternative<lang::Directive>(line.body)) {
                notAStatement(line.location);
                continue;
            }
            const auto* statement = std::get_if<lang::Statement>(&line.body);
            if (!statement)
                continue;
            if (statement->kind == lang::StatementKind::Jump ||
                statement->kind == lang::StatementKind::SequenceReset)
                at(line.location.line, 1,
                   "a block's body cannot jump or reset a sequence: the step around an "
                   "instance decides that");
            if (statement->condition)
                result.timers += countTimers(*statement->condition);
        }
    }
    return result;
}

} // namespace rs::blocks
