// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/Ast.h"

#include <map>
#include <string>

namespace rs::ladder {

// The symbolic names a unit's code sees, by address: the project's global
// names and the unit's own. The drawing shows an element's name and address
// together whichever of the two the text uses.
class SymbolTable {
public:
    static SymbolTable of(const lang::Document& document, int station);

    // Empty when the address has no name.
    const std::string& nameOf(const lang::Address& address) const;

private:
    void declare(const std::vector<lang::Line>& lines);

    std::map<lang::Address, std::string> m_names;
};

} // namespace rs::ladder
