// SPDX-License-Identifier: GPL-3.0-or-later
#include "SymbolTable.h"

#include "lang/SymbolicName.h"

namespace rs::ladder {

SymbolTable SymbolTable::of(const lang::Document& document, int station) {
    SymbolTable table;
    table.declare(document.preamble);
    for (const auto& unit : document.units)
        if (unit.station() == station)
            table.declare(unit.declarations);
    return table;
}

const std::string& SymbolTable::nameOf(const lang::Address& address) const {
    static const std::string none;
    auto found = m_names.find(address);
    return found == m_names.end() ? none : found->second;
}

std::optional<lang::Address> SymbolTable::addressOf(std::string_view name) const {
    auto found = m_addresses.find(lang::foldName(name));
    if (found == m_addresses.end())
        return std::nullopt;
    return found->second;
}

void SymbolTable::declare(const std::vector<lang::Line>& lines) {
    for (const auto& line : lines)
        if (const auto* declaration = std::get_if<lang::Declaration>(&line.body))
            if (const auto* name = std::get_if<lang::NameDeclaration>(&declaration->body)) {
                m_names.emplace(name->variable.address, name->name);
                m_addresses.emplace(lang::foldName(name->name), name->variable.address);
            }
}

} // namespace rs::ladder
