// SPDX-License-Identifier: GPL-3.0-or-later
#include "BlockDraft.h"

#include "LibraryLimits.h"
#include "LibraryWords.h"
#include "lang/Printer.h"

#include <algorithm>

namespace rs::blocks {

namespace {

using lang::AddressKind;

// How the statements use one address, in the order first met.
struct Use {
    lang::Address address;
    std::string written; // the operand as the statements write it
    bool read = false;
    bool writes = false;
    bool preset = false; // a timer's preset register
};

class Uses {
public:
    void note(const lang::Operand& operand, bool writes, bool preset = false) {
        if (!operand.address.valid())
            return;
        auto found = std::find_if(m_uses.begin(), m_uses.end(),
                                  [&](const Use& use) { return use.address == operand.address; });
        if (found == m_uses.end()) {
            m_uses.push_back({operand.address, operand.isName() ? operand.name.str()
                                                                : lang::toString(operand.address)});
            found = m_uses.end() - 1;
        }
        (writes ? found->writes : found->read) = true;
        found->preset = found->preset || preset;
    }

    void note(const lang::Value& value) {
        if (value.operand)
            note(*value.operand, false);
    }

    void note(const lang::Expr& expr) {
        note(expr.operand, false);
        note(expr.right);
        if (expr.preset.registerOperand)
            note(*expr.preset.registerOperand, false, true);
        for (const auto& child : expr.children)
            note(child);
    }

    void note(const lang::Statement& statement) {
        if (statement.condition)
            note(*statement.condition);
        if (statement.kind == lang::StatementKind::Assign) {
            note(statement.assignment->left);
            note(statement.assignment->right);
            note(statement.assignment->target, true);
        } else {
            note(statement.target, true);
        }
    }

    const std::vector<Use>& uses() const { return m_uses; }

private:
    std::vector<Use> m_uses;
};

bool isBit(AddressKind kind) {
    switch (kind) {
    case AddressKind::Register:
    case AddressKind::DoubleRegister:
    case AddressKind::SystemRegister:
    case AddressKind::AnalogInput:
        return false;
    default:
        return true;
    }
}

// A memory only the statements use, not remanent (M100-M131 keep their value
// over a power cut, which a new instance's memory would not): private.
bool isPrivate(const Use& use, const std::set<lang::Address>& usedElsewhere) {
    const bool remanent = use.address.index >= 100 && use.address.index <= 131;
    return use.address.kind == AddressKind::Memory && use.writes && !remanent &&
           !usedElsewhere.count(use.address);
}

PinKind pinKind(const Use& use) {
    if (use.preset)
        return PinKind::Time;
    if (use.address.kind == AddressKind::DoubleRegister)
        return PinKind::DoubleRegister;
    return isBit(use.address.kind) ? PinKind::Bit : PinKind::Register;
}

// A name of the library format from an operand's spelling: "EStop", "I0_12".
std::string nameFrom(const std::string& written) {
    std::string name;
    for (char c : written) {
        const bool letter = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
        const bool digit = c >= '0' && c <= '9';
        name += letter || digit ? c : '_';
    }
    if (!isLibraryName(name))
        name.insert(0, "P");
    name.resize(std::min(name.size(), kMaxPinNameLength));
    return name;
}

void rename(lang::Operand& operand, const std::map<lang::Address, std::string>& placeholders) {
    const auto found = placeholders.find(operand.address);
    if (found != placeholders.end())
        operand.name = found->second;
}

void rename(lang::Value& value, const std::map<lang::Address, std::string>& placeholders) {
    if (value.operand)
        rename(*value.operand, placeholders);
}

void rename(lang::Expr& expr, const std::map<lang::Address, std::string>& placeholders) {
    rename(expr.operand, placeholders);
    rename(expr.right, placeholders);
    if (expr.preset.registerOperand)
        rename(*expr.preset.registerOperand, placeholders);
    for (auto& child : expr.children)
        rename(child, placeholders);
}

} // namespace

std::set<lang::Address> addressesIn(const std::vector<lang::Line>& lines) {
    Uses uses;
    for (const auto& line : lines)
        if (const auto* statement = std::get_if<lang::Statement>(&line.body))
            uses.note(*statement);
    std::set<lang::Address> addresses;
    for (const auto& use : uses.uses())
        addresses.insert(use.address);
    return addresses;
}

BlockDraft draftBlock(const std::string& blockName, const std::vector<lang::Line>& lines,
                      const std::set<lang::Address>& usedElsewhere,
                      const std::map<lang::Address, std::string>& names) {
    BlockDraft draft;
    draft.block.name = blockName;
    draft.instance.type = blockName;
    if (!isLibraryName(blockName) || blockName.size() > kMaxNameLength) {
        draft.refusal = "a block's name is a letter, then letters, digits and '_', at most " +
                        std::to_string(kMaxNameLength) + " characters";
        return draft;
    }
    Uses uses;
    std::vector<lang::Statement> statements;
    for (const auto& line : lines) {
        const auto* statement = std::get_if<lang::Statement>(&line.body);
        if (!statement)
            continue;
        if (statement->kind == lang::StatementKind::Jump ||
            statement->kind == lang::StatementKind::SequenceReset) {
            draft.refusal = "a block cannot jump or reset a sequence: the step around it decides";
            return draft;
        }
        uses.note(*statement);
        statements.push_back(*statement);
        if (statement->condition) {
            std::vector<const lang::Expr*> pending{&*statement->condition};
            while (!pending.empty()) {
                const lang::Expr* expr = pending.back();
                pending.pop_back();
                draft.block.timers += expr->kind == lang::ExprKind::Timer ? 1 : 0;
                for (const auto& child : expr->children)
                    pending.push_back(&child);
            }
        }
    }
    if (statements.empty()) {
        draft.refusal = "the networks hold no statements";
        return draft;
    }

    std::map<lang::Address, std::string> placeholders;
    std::set<std::string> taken;
    auto nameOf = [&](const Use& use) {
        const auto chosen = names.find(use.address);
        std::string name = chosen != names.end() ? chosen->second : nameFrom(use.written);
        const std::string base = name;
        for (int n = 2; taken.count(name); ++n)
            name = base + "_" + std::to_string(n);
        taken.insert(name);
        draft.addresses[name] = use.address;
        return name;
    };
    std::vector<Pin> outputs;
    for (const auto& use : uses.uses()) {
        if (isPrivate(use, usedElsewhere)) {
            const std::string name = nameOf(use);
            draft.block.privates.push_back({name, PrivateKind::Memory});
            draft.instance.privates.push_back({name, lang::toString(use.address), 0});
            placeholders[use.address] = "{#" + name + "}";
            continue;
        }
        Pin pin;
        pin.name = nameOf(use);
        pin.direction = use.writes ? PinDirection::Out : PinDirection::In;
        pin.kind = pinKind(use);
        pin.operands = possibleOperands(pin.kind, pin.direction); // as reading the block gives
        (use.writes ? outputs : draft.block.pins).push_back(pin);
        draft.instance.pins.push_back({pin.name, use.written, 0});
        placeholders[use.address] = "{" + pin.name + "}";
    }
    draft.block.pins.insert(draft.block.pins.end(), outputs.begin(), outputs.end());
    if (draft.block.pins.size() > kMaxPins || draft.block.privates.size() > kMaxPrivates) {
        draft.refusal = "the networks use more variables than a block may have pins";
        return draft;
    }
    for (const auto& name : taken)
        if (!isLibraryName(name) || name.size() > kMaxPinNameLength) {
            draft.refusal = "'" + name +
                            "' is no name of a pin: a letter, then letters, digits "
                            "and '_', at most " +
                            std::to_string(kMaxPinNameLength) + " characters";
            return draft;
        }

    for (auto statement : statements) {
        if (statement.condition)
            rename(*statement.condition, placeholders);
        rename(statement.target, placeholders);
        rename(statement.assignment->target, placeholders);
        rename(statement.assignment->left, placeholders);
        rename(statement.assignment->right, placeholders);
        draft.block.body.push_back(lang::printStatement(statement));
    }
    return draft;
}

} // namespace rs::blocks
