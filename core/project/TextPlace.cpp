// SPDX-License-Identifier: GPL-3.0-or-later
#include "TextPlace.h"

#include "ProjectFile.h"

#include <string_view>
#include <vector>

namespace rs::project {

namespace {

std::vector<std::string_view> linesOf(std::string_view text) {
    std::vector<std::string_view> lines;
    while (!text.empty()) {
        const auto end = text.find('\n');
        lines.push_back(text.substr(0, end));
        text = end == text.npos ? std::string_view{} : text.substr(end + 1);
    }
    return lines;
}

// "NN" after the colon of "! id_pluto_Double:NN=..." or "! type_pluto:NN=...".
int stationAfterColon(std::string_view line) {
    const auto colon = line.find(':');
    if (colon == line.npos || colon + 2 >= line.size())
        return -1;
    const std::string_view digits = line.substr(colon + 1, 2);
    if (digits.find_first_not_of("0123456789") != digits.npos)
        return -1;
    return (digits[0] - '0') * 10 + (digits[1] - '0');
}

// "NN" at the start of ";@unit NN ...", after the kind.
int stationOfRecord(std::string_view words) {
    if (words.size() < 2 || words.substr(0, 2).find_first_not_of("0123456789") != words.npos)
        return -1;
    return (words[0] - '0') * 10 + (words[1] - '0');
}

// The address at the start of a record's or declaration's words.
lang::AddressWord addressAt(std::string_view words) {
    const auto end = words.find_first_of(" =,;");
    return lang::readAddressWord(words.substr(0, end));
}

} // namespace

TextPlace placeOfLine(const Project& project, int line) {
    return placeOfLine(writeProject(project), line);
}

TextPlace placeOfLine(std::string_view text, int line) {
    return TextPlaces(text).of(line);
}

TextPlaces::TextPlaces(std::string_view canonicalText) : m_lines(linesOf(canonicalText)) {
    m_codeHeader.reserve(m_lines.size());
    int header = -1;
    for (std::size_t i = 0; i < m_lines.size(); ++i) {
        if (m_lines[i].starts_with("! pgm_pluto:"))
            header = static_cast<int>(i);
        m_codeHeader.push_back(header);
    }
}

TextPlace TextPlaces::of(int line) const {
    TextPlace place;
    if (line < 1 || line > static_cast<int>(m_lines.size()))
        return place;
    const std::size_t index = static_cast<std::size_t>(line - 1);
    if (const int header = m_codeHeader[index]; header >= 0) {
        place.kind = TextPlace::Kind::UnitCode;
        place.station = stationAfterColon(m_lines[static_cast<std::size_t>(header)]);
        place.line = line - header;
        return place;
    }
    // Before the first unit's code: the declarations and records of the pages.
    const std::string_view at = m_lines[index];
    if (at.starts_with("! id_pluto") || at.starts_with("! type_pluto") ||
        at.starts_with(";@unit ")) {
        place.kind = TextPlace::Kind::Unit;
        place.station =
            at.starts_with(";@unit ") ? stationOfRecord(at.substr(7)) : stationAfterColon(at);
        return place;
    }
    for (std::string_view prefix : {std::string_view("! "), std::string_view(";@var ")}) {
        if (!at.starts_with(prefix))
            continue;
        const lang::AddressWord word = addressAt(at.substr(prefix.size()));
        if (word.shape == lang::AddressWord::Shape::Variable) {
            place.kind = TextPlace::Kind::Variable;
            place.address = word.address;
            place.station = word.address.unit;
            return place;
        }
    }
    return place;
}

} // namespace rs::project
