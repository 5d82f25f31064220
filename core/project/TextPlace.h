// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Project.h"

#include <string_view>

namespace rs::project {

// Where a line of the project's canonical text (what the compiler reports
// on) is edited in the IDE: a unit's code, a unit's settings, a variable's
// name or description, or the project's own settings.
struct TextPlace {
    enum class Kind { Project, Unit, Variable, UnitCode };
    Kind kind = Kind::Project;
    int station = -1;
    lang::Address address; // Variable
    int line = 0;          // UnitCode: the line in the unit's text, counted from 1

    friend bool operator==(const TextPlace&, const TextPlace&) = default;
};

TextPlace placeOfLine(const Project& project, int line);
// The same for a project's canonical text (writeProject), read once by the caller.
TextPlace placeOfLine(std::string_view canonicalText, int line);

} // namespace rs::project
