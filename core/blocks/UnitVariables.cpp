// SPDX-License-Identifier: GPL-3.0-or-later
#include "UnitVariables.h"

#include "compiler/SystemCall.h"
#include "lang/SymbolicName.h"
#include "project/Annotation.h"
#include "project/RemanentVariables.h"
#include "target/UnitType.h"

#include <variant>

namespace rs::blocks {

namespace {

bool isRemanentIndex(int index) {
    return index >= project::kFirstRemanent && index <= project::kLastRemanent;
}

void declareNames(const std::vector<lang::Line>& lines,
                  std::map<std::string, lang::Address>& names) {
    for (const auto& line : lines)
        if (const auto* declaration = std::get_if<lang::Declaration>(&line.body))
            if (const auto* name = std::get_if<lang::NameDeclaration>(&declaration->body))
                names[lang::foldName(name->name)] = name->variable.address;
}

class AddressCollector {
public:
    AddressCollector(int station, std::set<lang::Address>& used)
        : m_station(station), m_used(used) {}

    void add(const lang::Address& address) {
        if (!address.valid() || address.unit != m_station)
            return;
        using K = lang::AddressKind;
        switch (address.kind) {
        case K::RegisterBit:
            m_used.insert({K::Register, address.unit, address.index});
            break;
        case K::DoubleRegister:
        case K::DoubleRegisterLow:
        case K::DoubleRegisterHigh:
            m_used.insert({K::Register, address.unit, address.index});
            m_used.insert({K::Register, address.unit, address.index + 1});
            break;
        default:
            m_used.insert({address.kind, address.unit, address.index, address.bit});
            break;
        }
    }
    void add(const lang::Operand& operand) { add(operand.address); }
    void add(const lang::Value& value) {
        if (value.operand)
            add(*value.operand);
    }
    void add(const lang::Expr& expr) {
        add(expr.operand);
        if (expr.preset.registerOperand)
            add(*expr.preset.registerOperand);
        add(expr.right);
        for (const auto& child : expr.children)
            add(child);
    }
    void add(const lang::Line& line) {
        if (const auto* statement = std::get_if<lang::Statement>(&line.body)) {
            add(statement->target);
            add(statement->assignment->target);
            add(statement->assignment->left);
            add(statement->assignment->right);
            if (statement->condition)
                add(*statement->condition);
        } else if (const auto* declaration = std::get_if<lang::Declaration>(&line.body)) {
            if (const auto* name = std::get_if<lang::NameDeclaration>(&declaration->body))
                add(name->variable);
            else if (const auto* io = std::get_if<lang::IoDeclaration>(&declaration->body))
                add(io->io);
        } else if (const auto* comment = std::get_if<lang::CommentLine>(&line.body)) {
            addCall(comment->text);
        }
    }

private:
    // The addresses a ;@system record names (a name's is in its declaration).
    void addCall(const std::string& text) {
        std::optional<project::Annotation> record;
        try {
            record = project::parseAnnotation(text);
        } catch (const project::AnnotationError&) {
            return;
        }
        if (!record || record->kind != compiler::kSystemRecord)
            return;
        for (const auto& attribute : record->attributes) {
            const lang::AddressWord word = lang::readAddressWord(attribute.second);
            if (word.shape == lang::AddressWord::Shape::Variable)
                add(word.address);
        }
    }

    int m_station;
    std::set<lang::Address>& m_used;
};

} // namespace

std::map<std::string, lang::Address> unitNames(const lang::Document& document, int station) {
    std::map<std::string, lang::Address> names;
    declareNames(document.preamble, names);
    for (const auto& unit : document.units)
        if (unit.station() == station)
            declareNames(unit.declarations, names);
    return names;
}

std::optional<lang::Address> operandAddress(const std::map<std::string, lang::Address>& names,
                                            std::string_view operand) {
    const lang::AddressWord word = lang::readAddressWord(operand);
    if (word.shape == lang::AddressWord::Shape::Variable)
        return word.address;
    if (word.shape != lang::AddressWord::Shape::NotAnAddress)
        return std::nullopt;
    const auto found = names.find(lang::foldName(operand));
    if (found == names.end())
        return std::nullopt;
    return found->second;
}

std::set<lang::Address> usedAddresses(const lang::Document& document, int station) {
    std::set<lang::Address> used;
    AddressCollector collector(station, used);
    for (const auto& line : document.preamble)
        collector.add(line);
    for (const auto& unit : document.units) {
        if (unit.station() != station)
            continue;
        for (const auto& line : unit.declarations)
            collector.add(line);
        for (const auto& step : unit.steps)
            for (const auto& line : step.lines)
                collector.add(line);
    }
    return used;
}

PrivateVariables::PrivateVariables(const target::UnitTypeInfo& type, int instructionSet,
                                   int station, std::set<lang::Address> used)
    : m_station(station), m_memories(target::memoryCount(type, instructionSet)),
      m_registers(type.registers), m_used(std::move(used)) {}

void PrivateVariables::take(const lang::Address& address) {
    AddressCollector(m_station, m_used).add(address);
}

bool PrivateVariables::isFree(lang::AddressKind kind, int index) const {
    return !isRemanentIndex(index) && !m_used.count({kind, m_station, index});
}

std::optional<lang::Address> PrivateVariables::memory() {
    for (int index = m_memories - 1; index >= 0; --index)
        if (isFree(lang::AddressKind::Memory, index)) {
            const lang::Address address{lang::AddressKind::Memory, m_station, index};
            take(address);
            return address;
        }
    return std::nullopt;
}

std::optional<lang::Address> PrivateVariables::registerWord() {
    for (int index = m_registers - 1; index >= 0; --index)
        if (isFree(lang::AddressKind::Register, index)) {
            const lang::Address address{lang::AddressKind::Register, m_station, index};
            take(address);
            return address;
        }
    return std::nullopt;
}

std::optional<lang::Address> PrivateVariables::doubleRegister() {
    for (int index = (m_registers - 2) & ~1; index >= 0; index -= 2)
        if (isFree(lang::AddressKind::Register, index) &&
            isFree(lang::AddressKind::Register, index + 1)) {
            const lang::Address address{lang::AddressKind::DoubleRegister, m_station, index};
            take(address);
            return address;
        }
    return std::nullopt;
}

} // namespace rs::blocks
