// SPDX-License-Identifier: GPL-3.0-or-later
#include "RungEditing.h"

#include <algorithm>
#include <cstdlib>
#include <utility>

namespace rs::pl110 {

namespace {

const char* const kNoRung = "there is no rung there";

// Where rung `number` stands: its part and its line's index there.
struct RungPlace {
    std::vector<Line>* lines = nullptr;
    std::size_t index = 0;
};

RungPlace placeOf(Program& program, int number) {
    int seen = 0;
    for (auto* part : {&program.init, &program.main})
        for (std::size_t i = 0; i < part->size(); ++i)
            if (std::holds_alternative<Rung>((*part)[i].body) && ++seen == number)
                return {part, i};
    return {};
}

// The first line of the rung's block: its comment lines right above it.
std::size_t blockStart(const std::vector<Line>& lines, std::size_t rung) {
    std::size_t start = rung;
    while (start > 0 && std::holds_alternative<CommentLine>(lines[start - 1].body))
        --start;
    return start;
}

// Runs a change of one rung's condition on a copy; keeps it when it worked.
template <typename Change> std::string editRung(Program& program, int number, Change&& change) {
    const RungPlace place = placeOf(program, number);
    if (!place.lines)
        return kNoRung;
    Rung edited = std::get<Rung>((*place.lines)[place.index].body);
    if (std::string refusal = change(edited); !refusal.empty())
        return refusal;
    ladder::normalizeCondition(edited.condition);
    std::get<Rung>((*place.lines)[place.index].body) = std::move(edited);
    return {};
}

std::string refuseNonRung(const Line& line) {
    return std::holds_alternative<Rung>(line.body) ? std::string() : "a rung line holds a rung";
}

} // namespace

std::string insertRung(Program& program, int after, Line line, bool init) {
    if (std::string refusal = refuseNonRung(line); !refusal.empty())
        return refusal;
    if (after == 0) {
        std::vector<Line>& part = init ? program.init : program.main;
        // Before the first rung and its comment lines.
        std::size_t at = part.size();
        for (std::size_t i = 0; i < part.size(); ++i)
            if (std::holds_alternative<Rung>(part[i].body)) {
                at = blockStart(part, i);
                break;
            }
        part.insert(part.begin() + static_cast<std::ptrdiff_t>(at), std::move(line));
        return {};
    }
    const RungPlace place = placeOf(program, after);
    if (!place.lines)
        return kNoRung;
    place.lines->insert(place.lines->begin() + static_cast<std::ptrdiff_t>(place.index + 1),
                        std::move(line));
    return {};
}

std::string replaceRung(Program& program, int number, Line line) {
    if (std::string refusal = refuseNonRung(line); !refusal.empty())
        return refusal;
    const RungPlace place = placeOf(program, number);
    if (!place.lines)
        return kNoRung;
    line.location = (*place.lines)[place.index].location;
    (*place.lines)[place.index] = std::move(line);
    return {};
}

std::string removeRung(Program& program, int number) {
    const RungPlace place = placeOf(program, number);
    if (!place.lines)
        return kNoRung;
    std::vector<Line>& lines = *place.lines;
    const std::size_t start = blockStart(lines, place.index);
    lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(start),
                lines.begin() + static_cast<std::ptrdiff_t>(place.index + 1));
    return {};
}

std::string moveRung(Program& program, int number, int direction) {
    const RungPlace place = placeOf(program, number);
    if (!place.lines)
        return kNoRung;
    const RungPlace other = placeOf(program, number + direction);
    if (direction == 0 || std::abs(direction) != 1 || !other.lines || other.lines != place.lines)
        return direction < 0 ? "it is the first rung of its part"
                             : "it is the last rung of its part";
    std::vector<Line>& lines = *place.lines;
    const std::size_t upper = std::min(place.index, other.index);
    const std::size_t lower = std::max(place.index, other.index);
    // [upperStart, upper] gap [lowerStart, lower] becomes [lowerStart, lower] gap [upperStart,
    // upper].
    const std::size_t upperStart = blockStart(lines, upper);
    const std::size_t lowerStart = blockStart(lines, lower);
    std::vector<Line> reordered(lines.begin(),
                                lines.begin() + static_cast<std::ptrdiff_t>(upperStart));
    const auto range = [&](std::size_t from, std::size_t to) {
        for (std::size_t i = from; i < to; ++i)
            reordered.push_back(std::move(lines[i]));
    };
    range(lowerStart, lower + 1);
    range(upper + 1, lowerStart);
    range(upperStart, upper + 1);
    range(lower + 1, lines.size());
    lines = std::move(reordered);
    return {};
}

std::string insertInSeries(Program& program, int number, const ElementNodePath& path, Circuit part,
                           ladder::Side side) {
    return editRung(program, number, [&](Rung& rung) {
        return ladder::insertInSeries(rung.condition, path, std::move(part), side);
    });
}

std::string insertInParallel(Program& program, int number, const ElementNodePath& path,
                             Circuit part) {
    return editRung(program, number, [&](Rung& rung) {
        return ladder::insertInParallel(rung.condition, path, std::move(part));
    });
}

std::string removeElement(Program& program, int number, const ElementNodePath& path) {
    return editRung(program, number,
                    [&](Rung& rung) { return ladder::removeNode(rung.condition, path); });
}

std::string replaceNode(Program& program, int number, const ElementNodePath& path, Circuit part) {
    return editRung(program, number, [&](Rung& rung) -> std::string {
        Circuit* node = ladder::nodeAt(rung.condition, path);
        if (!node)
            return ladder::kNoCircuitNode;
        *node = std::move(part);
        return {};
    });
}

std::string replaceOutput(Program& program, int number, Output output) {
    return editRung(program, number, [&](Rung& rung) -> std::string {
        rung.output = std::move(output);
        return {};
    });
}

} // namespace rs::pl110
