// SPDX-License-Identifier: GPL-3.0-or-later
#include "VariableTable.h"

#include "BlankLines.h"
#include "UnitAsiOptions.h"
#include "UnitSettings.h"
#include "lang/SymbolicName.h"

#include <algorithm>
#include <map>

namespace rs::project {

lang::Address canonicalVariable(lang::Address address) {
    if (address.kind == lang::AddressKind::RegisterBit) {
        address.kind = lang::AddressKind::Register;
        address.bit = -1;
    } else if (address.kind == lang::AddressKind::DoubleRegisterLow ||
               address.kind == lang::AddressKind::DoubleRegisterHigh) {
        address.kind = lang::AddressKind::DoubleRegister;
    }
    return address;
}

namespace {

using lang::Address;
using lang::AddressKind;
using lang::Line;
using target::contains;

constexpr int kAsiSlaves = 31;
constexpr int kAsiSlaveBits = 4;
constexpr int kMaxTerminal = 99;

const lang::NameDeclaration* nameOf(const Line& line) {
    if (auto* declaration = std::get_if<lang::Declaration>(&line.body))
        return std::get_if<lang::NameDeclaration>(&declaration->body);
    return nullptr;
}

lang::NameDeclaration* nameOf(Line& line) {
    if (auto* declaration = std::get_if<lang::Declaration>(&line.body))
        return std::get_if<lang::NameDeclaration>(&declaration->body);
    return nullptr;
}

bool isDeclaration(const Line& line) {
    return std::holds_alternative<lang::Declaration>(line.body) ||
           std::holds_alternative<lang::Directive>(line.body);
}

bool isIo(const Line& line) {
    if (auto* declaration = std::get_if<lang::Declaration>(&line.body))
        return std::holds_alternative<lang::IoDeclaration>(declaration->body);
    return false;
}

const lang::UnitProgram* unitProgram(const Project& project, int station) {
    for (const auto& unit : project.program.units)
        if (unit.station() == station)
            return &unit;
    return nullptr;
}

// The name declarations that can name the unit's variables: the global ones
// and those in the unit's own code.
std::map<Address, std::string> namesOf(const Project& project, int station) {
    std::map<Address, std::string> names;
    auto collect = [&](const std::vector<Line>& lines) {
        for (const auto& line : lines)
            if (const auto* name = nameOf(line); name && name->variable.address.unit == station)
                names.emplace(name->variable.address, name->name);
    };
    collect(project.program.preamble);
    if (const auto* unit = unitProgram(project, station))
        collect(unit->declarations);
    return names;
}

template <typename E, typename Visit> void forEachExpressionOperand(E& expr, Visit& visit) {
    switch (expr.kind) {
    case lang::ExprKind::Or:
    case lang::ExprKind::And:
        for (auto& child : expr.children)
            forEachExpressionOperand(child, visit);
        return;
    case lang::ExprKind::Contact:
    case lang::ExprKind::Edge:
        visit(expr.operand);
        return;
    case lang::ExprKind::Timer:
        if (expr.preset.registerOperand)
            visit(*expr.preset.registerOperand);
        return;
    case lang::ExprKind::Compare:
        visit(expr.operand);
        if (expr.right.operand)
            visit(*expr.right.operand);
        return;
    }
}

// Every operand of the unit's code: targets, contacts, compared and assigned values.
template <typename Unit, typename Visit> void forEachOperand(Unit& unit, Visit visit) {
    for (auto& step : unit.steps) {
        for (auto& line : step.lines) {
            auto* statement = std::get_if<lang::Statement>(&line.body);
            if (!statement)
                continue;
            if (statement->kind == lang::StatementKind::Assign) {
                visit(statement->assignment->target);
                for (auto* value : {&statement->assignment->left, &statement->assignment->right})
                    if (value->operand)
                        visit(*value->operand);
            } else if (statement->kind != lang::StatementKind::Jump &&
                       statement->kind != lang::StatementKind::SequenceReset) {
                visit(statement->target);
            }
            if (statement->condition)
                forEachExpressionOperand(*statement->condition, visit);
        }
    }
}

// The code names a variable by its declaration: a renamed variable is
// written with its new name, one whose name is removed with its address.
// Register bits and double-register halves are written after their register.
void renameUses(lang::UnitProgram& unit, const Address& address, std::string_view name) {
    forEachOperand(unit, [&](lang::Operand& operand) {
        if (!operand.isName() || !(canonicalVariable(operand.address) == address) ||
            lang::systemName(operand.name, unit.station()).valid())
            return;
        if (name.empty()) {
            operand.name = {};
            return;
        }
        std::string written(name);
        if (operand.address.kind == AddressKind::RegisterBit)
            written += "." + std::to_string(operand.address.bit);
        else if (operand.address.kind == AddressKind::DoubleRegisterLow)
            written += ".Lo";
        else if (operand.address.kind == AddressKind::DoubleRegisterHigh)
            written += ".Hi";
        operand.name = written;
    });
}

bool declaresName(const std::vector<Line>& lines, const Address& address) {
    return std::any_of(lines.begin(), lines.end(), [&](const Line& line) {
        const auto* name = nameOf(line);
        return name && name->variable.address == address;
    });
}

// Where a new name declaration goes: among the other names in address order;
// without any, after the I/O declarations (or the unit declarations) it follows.
std::size_t placeForName(std::vector<Line>& lines, const Address& address, bool inUnit) {
    std::ptrdiff_t afterLastName = -1;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        if (const auto* name = nameOf(lines[i])) {
            if (address < name->variable.address)
                return i;
            afterLastName = static_cast<std::ptrdiff_t>(i) + 1;
        }
    }
    if (afterLastName >= 0)
        return static_cast<std::size_t>(afterLastName);
    std::ptrdiff_t afterLast = -1;
    for (std::size_t i = 0; i < lines.size(); ++i)
        if (inUnit ? isIo(lines[i]) : isDeclaration(lines[i]))
            afterLast = static_cast<std::ptrdiff_t>(i) + 1;
    if (afterLast >= 0) {
        if (inUnit) // a blank line between the I/O declarations and the names
            lines.insert(lines.begin() + afterLast, Line{lang::BlankLine{}, std::nullopt, {}});
        return static_cast<std::size_t>(afterLast + (inUnit ? 1 : 0));
    }
    std::size_t first = 0;
    while (first < lines.size() && std::holds_alternative<lang::BlankLine>(lines[first].body))
        ++first;
    return first;
}

} // namespace

std::vector<VariableGroup> variableGroups(const target::UnitTypeInfo& type, int instructionSet) {
    std::vector<VariableGroup> groups{VariableGroup::SafetyInputs};
    if (!type.globalSafetyOutputs.empty() || !type.localSafetyOutputs.empty())
        groups.push_back(VariableGroup::SafetyOutputs);
    if (!type.nonSafetyOutputs.empty())
        groups.push_back(VariableGroup::NonSafetyOutputs);
    // push_back rather than insert of a list: GCC 12 at -O3 warns falsely on the latter.
    groups.push_back(VariableGroup::GlobalMemories);
    groups.push_back(VariableGroup::Memories);
    groups.push_back(VariableGroup::Registers);
    if (instructionSet >= 3)
        groups.push_back(VariableGroup::DoubleRegisters);
    groups.push_back(VariableGroup::SystemMemories);
    groups.push_back(VariableGroup::SystemRegisters);
    if (type.asiSlaves)
        groups.push_back(VariableGroup::AsiSlaves);
    return groups;
}

std::vector<Address> variablesIn(const target::UnitTypeInfo& type, int station, int instructionSet,
                                 VariableGroup group) {
    std::vector<Address> list;
    auto numbered = [&](AddressKind kind, int count) {
        for (int index = 0; index < count; ++index)
            list.push_back({kind, station, index});
    };
    auto terminals = [&](AddressKind kind, auto&& included) {
        for (int number = 0; number <= kMaxTerminal; ++number)
            if (included(number))
                list.push_back({kind, station, number});
    };
    switch (group) {
    case VariableGroup::SafetyInputs:
        for (int number = 0; number <= kMaxTerminal; ++number) {
            if (contains(type.analogInputs, number))
                list.push_back({AddressKind::AnalogInput, station, number});
            else if (contains(type.globalInputs, number) || contains(type.localInputs, number))
                list.push_back({AddressKind::Input, station, number});
        }
        for (int slave = 1; slave <= kAsiSlaves; ++slave)
            if (contains(type.asiGlobalSafeInputs, slave) ||
                contains(type.asiLocalSafeInputs, slave))
                list.push_back({AddressKind::AsiInput, station, slave});
        break;
    case VariableGroup::SafetyOutputs:
        terminals(AddressKind::Output, [&](int n) {
            return contains(type.globalSafetyOutputs, n) || contains(type.localSafetyOutputs, n);
        });
        break;
    case VariableGroup::NonSafetyOutputs:
        terminals(AddressKind::Output, [&](int n) { return contains(type.nonSafetyOutputs, n); });
        break;
    case VariableGroup::GlobalMemories:
        numbered(AddressKind::GlobalMemory, type.globalMemories);
        break;
    case VariableGroup::Memories:
        numbered(AddressKind::Memory, target::memoryCount(type, instructionSet));
        break;
    case VariableGroup::Registers:
        numbered(AddressKind::Register, type.registers);
        break;
    case VariableGroup::DoubleRegisters:
        if (instructionSet >= 3)
            for (int index = 0; index + 1 < type.registers; index += 2)
                list.push_back({AddressKind::DoubleRegister, station, index});
        break;
    case VariableGroup::SystemMemories:
        numbered(AddressKind::SystemMemory, type.systemMemories);
        break;
    case VariableGroup::SystemRegisters:
        numbered(AddressKind::SystemRegister, type.systemRegisters);
        break;
    case VariableGroup::AsiSlaves:
        if (!type.asiSlaves)
            break;
        for (AddressKind kind : {AddressKind::AsiInput, AddressKind::AsiOutput})
            for (int slave = 1; slave <= kAsiSlaves; ++slave)
                for (bool b : {false, true})
                    for (int bit = 1; bit <= kAsiSlaveBits; ++bit)
                        list.push_back({kind, station, slave, bit, b});
        break;
    }
    return list;
}

std::optional<VariableGroup> groupOf(const target::UnitTypeInfo& type, int instructionSet,
                                     const Address& address) {
    if (!target::hasVariable(type, address, instructionSet))
        return std::nullopt;
    switch (address.kind) {
    case AddressKind::Input:
    case AddressKind::AnalogInput:
        return VariableGroup::SafetyInputs;
    case AddressKind::Output:
        return contains(type.nonSafetyOutputs, address.index) ? VariableGroup::NonSafetyOutputs
                                                              : VariableGroup::SafetyOutputs;
    case AddressKind::GlobalMemory:
        return VariableGroup::GlobalMemories;
    case AddressKind::Memory:
        return VariableGroup::Memories;
    case AddressKind::Register:
        return VariableGroup::Registers;
    case AddressKind::DoubleRegister:
        return instructionSet >= 3 ? std::optional(VariableGroup::DoubleRegisters) : std::nullopt;
    case AddressKind::SystemMemory:
        return VariableGroup::SystemMemories;
    case AddressKind::SystemRegister:
        return VariableGroup::SystemRegisters;
    case AddressKind::AsiInput:
        return address.bit < 0 ? VariableGroup::SafetyInputs : VariableGroup::AsiSlaves;
    case AddressKind::AsiOutput:
        return VariableGroup::AsiSlaves;
    default:
        return std::nullopt;
    }
}

std::vector<Variable> variableTable(const Project& project, int station, VariableGroup group) {
    const target::UnitTypeInfo& type = unitTypeOf(project, station);
    const int instructionSet = instructionSetOf(project, station);
    const std::map<Address, std::string> names = namesOf(project, station);
    const std::set<Address> used = usedVariables(project, station);
    const std::set<Address> slaves = configuredAsiVariables(project, station);
    std::vector<Variable> rows;
    for (const Address& address : variablesIn(type, station, instructionSet, group)) {
        // An AS-i variable is listed when its slave is defined on the AS-i
        // Options page, or when the project already names, describes or uses it.
        const bool asi =
            address.kind == AddressKind::AsiInput || address.kind == AddressKind::AsiOutput;
        if (asi && !slaves.count(address) && !used.count(address) && !names.count(address) &&
            !project.variableDescriptions.count(address) &&
            !project.exportedVariables.count(address))
            continue;
        Variable row;
        row.address = address;
        row.global = target::isGlobal(type, address);
        row.exported = project.exportedVariables.count(address) > 0;
        row.remanent = project.remanentVariables.count(address) > 0;
        row.used = used.count(address) > 0;
        if (auto it = names.find(address); it != names.end())
            row.name = it->second;
        if (auto it = project.variableDescriptions.find(address);
            it != project.variableDescriptions.end())
            row.description = it->second;
        if (const auto* system = target::systemVariable(type, address)) {
            row.systemName = system->name;
            row.systemFunction = system->function;
        }
        rows.push_back(std::move(row));
    }
    return rows;
}

std::string variableName(const Project& project, const Address& address) {
    const auto names = namesOf(project, address.unit);
    auto it = names.find(address);
    return it == names.end() ? std::string() : it->second;
}

std::vector<Address> namedAddresses(const Project& project, int station) {
    std::vector<Address> addresses;
    for (const auto& [address, name] : namesOf(project, station))
        addresses.push_back(address);
    return addresses;
}

std::optional<std::string> checkVariableName(const Project& project, const Address& address,
                                             std::string_view name) {
    if (name.empty())
        return std::nullopt;
    if (auto problem = lang::checkSymbolicName(name, instructionSetOf(project, address.unit)))
        return problem;
    const std::string key = lang::foldName(name);
    bool declaredGlobally = false;
    bool declaredLocally = false;
    for (const auto& line : project.program.preamble)
        if (const auto* n = nameOf(line); n && n->variable.address == address)
            declaredGlobally = true;
    if (const auto* unit = unitProgram(project, address.unit))
        for (const auto& line : unit->declarations)
            if (const auto* n = nameOf(line); n && n->variable.address == address)
                declaredLocally = true;
    const bool global =
        declaredGlobally ||
        (!declaredLocally && target::isGlobal(unitTypeOf(project, address.unit), address));

    // A global name clashes with every name; a local one with the global
    // names and those of its own unit.
    auto clash = [&](const std::vector<Line>& lines) -> std::optional<std::string> {
        for (const auto& line : lines)
            if (const auto* n = nameOf(line);
                n && !(n->variable.address == address) && lang::foldName(n->name) == key)
                return "'" + std::string(name) + "' is already the name of " +
                       lang::toString(n->variable.address);
        return std::nullopt;
    };
    if (auto problem = clash(project.program.preamble))
        return problem;
    for (const auto& unit : project.program.units)
        if (global || unit.station() == address.unit)
            if (auto problem = clash(unit.declarations))
                return problem;
    return std::nullopt;
}

std::optional<std::string> setVariableName(Project& project, const Address& address,
                                           std::string_view name) {
    if (auto problem = checkVariableName(project, address, name))
        return problem;
    bool written = false;
    auto rewrite = [&](std::vector<Line>& lines) {
        for (std::size_t i = 0; i < lines.size();) {
            auto* declared = nameOf(lines[i]);
            if (!declared || !(declared->variable.address == address)) {
                ++i;
                continue;
            }
            if (!name.empty() && !written) {
                declared->name = std::string(name);
                written = true;
                ++i;
            } else {
                lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(i));
            }
        }
    };
    const bool wasGlobal = declaresName(project.program.preamble, address);
    rewrite(project.program.preamble);
    for (auto& unit : project.program.units) {
        const bool local =
            unit.station() == address.unit && declaresName(unit.declarations, address);
        if (local || (wasGlobal && !declaresName(unit.declarations, address)))
            renameUses(unit, address, name);
        if (unit.station() == address.unit)
            rewrite(unit.declarations);
    }

    if (!name.empty() && !written) {
        lang::NameDeclaration declaration;
        declaration.variable.address = address;
        declaration.name = std::string(name);
        const bool global = target::isGlobal(unitTypeOf(project, address.unit), address);
        std::vector<Line>& lines =
            global ? project.program.preamble : programOf(project, address.unit).declarations;
        const std::size_t at = placeForName(lines, address, !global);
        lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(at),
                     Line{lang::Declaration{std::move(declaration), {}}, std::nullopt, {}});
    }
    tidyBlankLines(project.program);
    return std::nullopt;
}

void setVariableDescription(Project& project, const Address& address, std::string description) {
    if (description.empty())
        project.variableDescriptions.erase(address);
    else
        project.variableDescriptions[address] = std::move(description);
}

std::set<Address> usedVariables(const Project& project, int station) {
    std::set<Address> used;
    if (const auto* unit = unitProgram(project, station))
        forEachOperand(*unit, [&](const lang::Operand& operand) {
            used.insert(canonicalVariable(operand.address));
        });
    return used;
}

} // namespace rs::project
