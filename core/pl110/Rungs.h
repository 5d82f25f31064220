// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Program.h"

#include <string>
#include <vector>

// A program's rungs as the ladder shows them and the engine numbers them:
// INIT's, then MAIN's, in file order, numbered from 1 (ScanEngine::marks()
// is indexed the same way), each with the comment lines right above it.
namespace rs::pl110 {

struct NumberedRung {
    int number = 0;
    bool init = false;          // in INIT, which runs once before the first scan
    const Line* line = nullptr; // the rung's line in the program it was taken from
    const Rung* rung = nullptr;
    std::string comment; // the comment lines above it, trimmed, one per line
};

// Points into the program, which must outlive the result.
std::vector<NumberedRung> numberedRungs(const Program& program);

// The number of the rung written at a text line (from 1), or of the last
// rung above it; 1 when there is none above.
int rungAtLine(const Program& program, int line);

// The name a declaration gives the address, empty when it has none.
std::string declaredName(const Program& program, const Address& address);

} // namespace rs::pl110
