// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/Address.h"
#include "lang/Ast.h"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>

namespace rs::target {
struct UnitTypeInfo;
}

// What a unit's variables are for the block instances in it: the names its
// code sees, the addresses it already uses, and the free ones an instance's
// private variables are taken from.
namespace rs::blocks {

// The symbolic names unit `station` sees (the project's global names and its
// own), by their folded spelling.
std::map<std::string, lang::Address> unitNames(const lang::Document& document, int station);

// The address an operand written for a pin stands for: an address word, or
// a name the unit sees. Nothing when it is neither.
std::optional<lang::Address> operandAddress(const std::map<std::string, lang::Address>& names,
                                            std::string_view operand);

// Every address the unit's code, its declarations and the global names of
// its own variables mention. A double register uses its two registers.
std::set<lang::Address> usedAddresses(const lang::Document& document, int station);

// Hands out the unit's free memories and registers, highest first, so that
// they stay clear of the low numbers people write by hand; never a remanent
// one (M100-M131, R100-R131, manual Part 1, 10.3), never one already used.
class PrivateVariables {
public:
    PrivateVariables(const target::UnitTypeInfo& type, int instructionSet, int station,
                     std::set<lang::Address> used);

    // Marks an address as taken (one already recorded by an instance).
    void take(const lang::Address& address);
    // Nothing when the unit has no free one left.
    std::optional<lang::Address> memory();
    std::optional<lang::Address> registerWord();
    std::optional<lang::Address> doubleRegister();

private:
    bool isFree(lang::AddressKind kind, int index) const;

    int m_station = 0;
    int m_memories = 0;
    int m_registers = 0;
    std::set<lang::Address> m_used;
};

} // namespace rs::blocks
