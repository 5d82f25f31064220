// SPDX-License-Identifier: GPL-3.0-or-later
#include "NameResolver.h"

#include "SymbolicName.h"

#include <array>
#include <map>
#include <unordered_map>

namespace rs::lang {

namespace {

// The last type_pluto declaration of a station decides.
void collectInstructionSets(const Document& document, std::array<int, 32>& sets) {
    auto scan = [&](const std::vector<Line>& lines) {
        for (const auto& line : lines)
            if (auto* declaration = std::get_if<Declaration>(&line.body))
                if (auto* type = std::get_if<TypeDeclaration>(&declaration->body))
                    if (type->station >= 0 && type->station < 32 && type->instructionSet)
                        sets[type->station] = type->instructionSet;
    };
    scan(document.preamble);
    for (const auto& unit : document.units)
        scan(unit.declarations);
}

struct Symbol {
    Name spelling; // shared with the operands that use it
    Address address;
    SourceLocation declared;
};

using Scope = std::map<std::string, Symbol>; // by folded name

class Resolver {
public:
    // Declares the global names (problems with them are the first diagnostics).
    explicit Resolver(const Document& document) {
        m_instructionSets.fill(2);
        collectInstructionSets(document, m_instructionSets);
        declare(document.preamble, m_global, -1);
    }

    // `document` is the one the resolver was made with.
    Diagnostics resolveStatements(Document& document) {
        for (auto& unit : document.units) {
            Scope local;
            declare(unit.declarations, local, unit.station());
            m_answers.clear();
            for (auto& step : unit.steps)
                for (auto& line : step.lines)
                    if (auto* statement = std::get_if<Statement>(&line.body))
                        resolveStatement(*statement, local, unit.station());
        }
        return std::move(m_diagnostics);
    }

    Diagnostics resolveOperands(const Document& document, int station,
                                const std::vector<Operand*>& operands) {
        Scope local;
        for (const auto& unit : document.units)
            if (unit.station() == station)
                declare(unit.declarations, local, station);
        m_diagnostics.clear(); // the declarations' problems are resolveNames' to report
        m_answers.clear();
        for (Operand* operand : operands)
            resolve(*operand, local, station);
        return std::move(m_diagnostics);
    }

private:
    void error(SourceLocation at, std::string message) {
        m_diagnostics.push_back({Severity::Error, at.line, at.column, std::move(message)});
    }

    void declare(const std::vector<Line>& lines, Scope& scope, int station) {
        std::map<Address, const Symbol*> named;
        for (const auto& [key, symbol] : scope)
            named[symbol.address] = &symbol;
        for (const auto& line : lines) {
            const auto* declaration = std::get_if<Declaration>(&line.body);
            if (!declaration)
                continue;
            const auto* nameDeclaration = std::get_if<NameDeclaration>(&declaration->body);
            if (!nameDeclaration)
                continue;
            const Address& address = nameDeclaration->variable.address;
            const std::string& name = nameDeclaration->name;
            const SourceLocation at = nameDeclaration->nameLocation;
            if (address.kind == AddressKind::Sequence) {
                error(nameDeclaration->variable.location, "a sequence cannot be given a name");
                continue;
            }
            const int owner = station >= 0 ? station : address.unit;
            int set = owner >= 0 && owner < 32 ? m_instructionSets[owner] : 2;
            if (auto problem = checkSymbolicName(name, set)) {
                error(at, *problem);
                continue;
            }
            std::string key = foldName(name);
            const Symbol* existing = lookupDeclared(key, scope);
            if (existing) {
                error(at, "the name '" + name + "' is already given to " +
                              toString(existing->address) + " at line " +
                              std::to_string(existing->declared.line));
                continue;
            }
            if (auto it = named.find(address); it != named.end()) {
                error(at, toString(address) + " is already named '" + it->second->spelling +
                              "' at line " + std::to_string(it->second->declared.line));
                continue;
            }
            Symbol& symbol = scope[key];
            symbol = {name, address, at};
            named[address] = &symbol;
        }
    }

    // What a name as written is declared as in `local`, asked of the scopes
    // once for each spelling: a name is written many times in a unit, and
    // folding it and finding it was most of resolving it.
    const Symbol* declaredAs(const Name& name, const Scope& local) {
        auto [answer, asked] = m_answers.try_emplace(name.c_str(), nullptr);
        if (asked)
            answer->second = lookupDeclared(foldName(name), local);
        return answer->second;
    }

    const Symbol* lookupDeclared(const std::string& key, const Scope& local) const {
        if (auto it = local.find(key); it != local.end())
            return &it->second;
        if (&local != &m_global)
            if (auto it = m_global.find(key); it != m_global.end())
                return &it->second;
        return nullptr;
    }

    void resolve(Operand& operand, const Scope& local, int station) {
        if (!operand.isName())
            return;
        if (const Symbol* symbol = declaredAs(operand.name, local)) {
            operand.address = symbol->address;
            operand.name = symbol->spelling;
            return;
        }
        if (Address system = systemName(operand.name, station); system.valid()) {
            operand.address = system;
            return;
        }
        // Halves of a named double register ("Example.Lo") and bits of a
        // named register ("Counter.3").
        const std::string& name = operand.name;
        if (auto dot = name.rfind('.'); dot != std::string::npos && dot > 0) {
            const std::string base = name.substr(0, dot);
            const std::string suffix = name.substr(dot + 1);
            if (const Symbol* symbol = lookupDeclared(foldName(base), local)) {
                const std::string lower = foldName(suffix);
                if (symbol->address.kind == AddressKind::DoubleRegister &&
                    (lower == "lo" || lower == "hi")) {
                    operand.address = symbol->address;
                    operand.address.kind = lower == "lo" ? AddressKind::DoubleRegisterLow
                                                         : AddressKind::DoubleRegisterHigh;
                    operand.name = symbol->spelling + (lower == "lo" ? ".Lo" : ".Hi");
                    return;
                }
                if (symbol->address.kind == AddressKind::Register && !suffix.empty() &&
                    suffix.size() <= 2 &&
                    suffix.find_first_not_of("0123456789") == std::string::npos) {
                    operand.address = symbol->address;
                    operand.address.kind = AddressKind::RegisterBit;
                    operand.address.bit = std::stoi(suffix);
                    operand.name = symbol->spelling + "." + std::to_string(operand.address.bit);
                    return;
                }
            }
        }
        error(operand.location, "unknown name '" + operand.name +
                                    "': declare it with '! <address>=" + operand.name + "'");
    }

    void requireKind(const Operand& operand, bool wantBit, const char* role) {
        if (!operand.isName() || !operand.address.valid())
            return;
        bool ok = wantBit ? operand.address.isBit() : operand.address.isWord();
        if (!ok)
            error(operand.location, "'" + operand.name + "' is " + toString(operand.address) +
                                        ", which cannot be used as " + role);
    }

    void resolveValue(Value& value, const Scope& local, int station) {
        if (value.operand) {
            resolve(*value.operand, local, station);
            requireKind(*value.operand, false, "a register value");
        }
    }

    void resolveExpr(Expr& expr, const Scope& local, int station) {
        switch (expr.kind) {
        case ExprKind::Or:
        case ExprKind::And:
            for (auto& child : expr.children)
                resolveExpr(child, local, station);
            return;
        case ExprKind::Contact:
        case ExprKind::Edge:
            resolve(expr.operand, local, station);
            requireKind(expr.operand, true, "a contact");
            return;
        case ExprKind::Timer:
            if (expr.preset.registerOperand) {
                resolve(*expr.preset.registerOperand, local, station);
                requireKind(*expr.preset.registerOperand, false, "a timer preset");
            }
            return;
        case ExprKind::Compare:
            resolve(expr.operand, local, station);
            requireKind(expr.operand, false, "a register in a comparison");
            resolveValue(expr.right, local, station);
            return;
        }
    }

    void resolveStatement(Statement& statement, const Scope& local, int station) {
        switch (statement.kind) {
        case StatementKind::Coil:
        case StatementKind::Set:
        case StatementKind::Reset:
        case StatementKind::Toggle:
            resolve(statement.target, local, station);
            requireKind(statement.target, true, "an output");
            break;
        case StatementKind::SequenceReset:
        case StatementKind::Jump:
            break;
        case StatementKind::Assign:
            resolve(statement.assignment->target, local, station);
            requireKind(statement.assignment->target, false, "the target of an assignment");
            resolveValue(statement.assignment->left, local, station);
            resolveValue(statement.assignment->right, local, station);
            break;
        }
        if (statement.condition)
            resolveExpr(*statement.condition, local, station);
    }

    std::array<int, 32> m_instructionSets{};
    Scope m_global;
    Diagnostics m_diagnostics;
    // declaredAs's answers in the unit being resolved (cleared for each
    // scope), by the spelling's place: one place a spelling (lang::Name).
    std::unordered_map<const char*, const Symbol*> m_answers;
};

} // namespace

int instructionSetOf(const Document& document, int station) {
    std::array<int, 32> sets{};
    sets.fill(2);
    collectInstructionSets(document, sets);
    return station >= 0 && station < 32 ? sets[station] : 2;
}

Diagnostics resolveNames(Document& document) {
    return Resolver(document).resolveStatements(document);
}

Diagnostics resolveOperands(const Document& document, int station,
                            const std::vector<Operand*>& operands) {
    return Resolver(document).resolveOperands(document, station, operands);
}

} // namespace rs::lang
