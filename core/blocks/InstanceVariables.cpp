// SPDX-License-Identifier: GPL-3.0-or-later
#include "InstanceVariables.h"

#include "BlockInstance.h"
#include "UnitVariables.h"
#include "project/UnitText.h"
#include "project/VariableTable.h"

#include <algorithm>
#include <map>
#include <string_view>
#include <variant>

namespace rs::blocks {

namespace {

// A comment's text (after ';') that starts a ;@block record.
bool startsBlockRecord(std::string_view comment) {
    const std::string_view kind = kBlockRecord;
    if (!comment.starts_with('@') || !comment.substr(1).starts_with(kind))
        return false;
    const std::size_t end = 1 + kind.size();
    return comment.size() == end || comment[end] == ' ' || comment[end] == '\t';
}

bool isBlockRecordLine(const lang::Line& line) {
    const auto* comment = std::get_if<lang::CommentLine>(&line.body);
    return comment && startsBlockRecord(comment->text);
}

// The numbers (from 1) of the lines of a unit's text that hold a ;@block
// record, in order. The n-th of them prints the n-th record line of the
// unit's tree: the line numbers come from the text the user sees, so that
// they stay right whatever the tree's blank lines are.
std::vector<int> recordLineNumbers(std::string_view text) {
    std::vector<int> numbers;
    int number = 1;
    while (!text.empty()) {
        const std::size_t end = text.find('\n');
        std::string_view line = text.substr(0, end);
        line.remove_prefix(std::min(line.find_first_not_of(' '), line.size()));
        if (line.starts_with(';') && startsBlockRecord(line.substr(1)))
            numbers.push_back(number);
        ++number;
        text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
    }
    return numbers;
}

} // namespace

std::vector<InstanceVariable> instanceVariables(const project::Project& project, int station) {
    std::vector<InstanceVariable> variables;
    const lang::UnitProgram* unit = nullptr;
    for (const auto& candidate : project.program.units)
        if (candidate.station() == station)
            unit = &candidate;
    if (!unit)
        return variables;
    const std::map<std::string, lang::Address> names = unitNames(project.program, station);
    const std::vector<int> lineNumbers = recordLineNumbers(project::unitText(project, station));
    std::size_t records = 0; // record lines before the current one, in the order of the text
    for (const auto& line : unit->declarations)
        records += isBlockRecordLine(line) ? 1 : 0;
    for (const auto& step : unit->steps) {
        std::map<std::size_t, std::size_t> recordOrdinal; // by index in the step's lines
        for (std::size_t i = 0; i < step.lines.size(); ++i)
            if (isBlockRecordLine(step.lines[i]))
                recordOrdinal[i] = records++;
        for (const BlockInstance& instance : findInstances(step).instances) {
            const std::size_t ordinal = recordOrdinal[instance.record];
            const int line = ordinal < lineNumbers.size() ? lineNumbers[ordinal] : 0;
            auto add = [&](const Binding& binding, InstanceVariable::Role role) {
                const auto address = operandAddress(names, binding.operand);
                if (!address || !address->valid() || address->unit != station)
                    return;
                variables.push_back({project::canonicalVariable(*address), role, binding.name,
                                     instance.type, line});
            };
            for (const auto& pin : instance.pins)
                add(pin, InstanceVariable::Role::Pin);
            for (const auto& variable : instance.privates)
                add(variable, InstanceVariable::Role::Private);
        }
    }
    return variables;
}

} // namespace rs::blocks
