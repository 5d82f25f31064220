// SPDX-License-Identifier: GPL-3.0-or-later
#include "PowerSnapshot.h"

#include "sim/Conduction.h"

#include <algorithm>

namespace rs::render {

bool PowerSnapshot::ran(std::uint32_t statement) const {
    return statements.count(statement) != 0;
}

bool PowerSnapshot::conducts(std::uint32_t statement, std::uint16_t element) const {
    auto found = statements.find(statement);
    if (found == statements.end())
        return false;
    if (element == 0)
        return found->second.energised;
    return found->second.conducting.count(element) != 0;
}

std::uint8_t PowerSnapshot::state(std::uint32_t statement, std::uint16_t element) const {
    auto found = statements.find(statement);
    if (found == statements.end() || element >= found->second.states.size())
        return 0;
    return found->second.states[element];
}

bool PowerSnapshot::closed(std::uint32_t statement, std::uint16_t element) const {
    return (state(statement, element) & sim::ElementState::Closed) != 0;
}

bool PowerSnapshot::running(std::uint32_t statement, std::uint16_t element) const {
    return (state(statement, element) & sim::ElementState::Running) != 0;
}

bool PowerSnapshot::powers(const ladder::PowerFeed& feed) const {
    switch (feed.kind) {
    case ladder::PowerFeed::Kind::None:
        return false;
    case ladder::PowerFeed::Kind::Rail:
        return ran(feed.statement);
    case ladder::PowerFeed::Kind::Elements:
        return std::any_of(feed.elements.begin(), feed.elements.end(), [&](std::uint16_t element) {
            return conducts(feed.statement, element);
        });
    }
    return false;
}

} // namespace rs::render
