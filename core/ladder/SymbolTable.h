// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/Ast.h"

#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace rs::ladder {

// The symbolic names a unit's code sees, by address: the project's global
// names and the unit's own. The drawing shows an element's name and address
// together whichever of the two the text uses.
class SymbolTable {
public:
    static SymbolTable of(const lang::Document& document, int station);

    // Empty when the address has no name.
    const std::string& nameOf(const lang::Address& address) const;
    // The address a name stands for, in any case; nothing when undeclared.
    std::optional<lang::Address> addressOf(std::string_view name) const;

private:
    void declare(const std::vector<lang::Line>& lines);

    std::map<lang::Address, std::string> m_names;
    std::map<std::string, lang::Address> m_addresses; // by folded name
};

} // namespace rs::ladder
