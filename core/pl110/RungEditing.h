// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Program.h"
#include "ladder/CircuitEditing.h"

#include <cstddef>
#include <string>
#include <vector>

// Editing a PL110 program as its ladder shows it (docs/pl110.md, "The
// window"): rungs numbered as numberedRungs numbers them, a rung's comment
// the comment lines right above it, elements by their path in the rung's
// condition (ladder::ElementLayout::path). Each edit leaves the program in
// the canonical form its printed text reads back as, or refuses with the
// reason and changes nothing.
namespace rs::pl110 {

using ElementNodePath = std::vector<std::size_t>;

// A rung line (body Rung) after rung `after` in its part; after 0 it is the
// first of MAIN, or of INIT when `init`.
std::string insertRung(Program& program, int after, Line line, bool init = false);
// A new line for rung `number`; its comment lines above stay.
std::string replaceRung(Program& program, int number, Line line);
// The rung and its comment lines.
std::string removeRung(Program& program, int number);
// Swaps the rung, with its comment lines, with the one above (-1) or below
// (+1) in the same part.
std::string moveRung(Program& program, int number, int direction);

// A part (an element, or a whole circuit) before or after the node, or in a
// parallel branch around it.
std::string insertInSeries(Program& program, int number, const ElementNodePath& path, Circuit part,
                           ladder::Side side);
std::string insertInParallel(Program& program, int number, const ElementNodePath& path,
                             Circuit part);
// A rung whose last element goes has its output powered every scan.
std::string removeElement(Program& program, int number, const ElementNodePath& path);
// The node (an element or a group) becomes the part.
std::string replaceNode(Program& program, int number, const ElementNodePath& path, Circuit part);
std::string replaceOutput(Program& program, int number, Output output);

} // namespace rs::pl110
