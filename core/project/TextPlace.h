// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Project.h"

#include <string_view>
#include <vector>

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

// The places of the lines of one canonical text, which is read once: for the
// many diagnostics of a large project, where placeOfLine would read the text
// again for each. The text must outlive it.
class TextPlaces {
public:
    explicit TextPlaces(std::string_view canonicalText);
    TextPlace of(int line) const;

private:
    std::vector<std::string_view> m_lines;
    std::vector<int> m_codeHeader; // by line index: the index of its unit's "! pgm_pluto:", or -1
};

} // namespace rs::project
