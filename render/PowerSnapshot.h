// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ladder/Layout.h"
#include "lang/Address.h"

#include <cstdint>
#include <map>
#include <set>
#include <vector>

namespace rs::render {

// What one scan did in one statement.
struct StatementPower {
    // The elements with power at their right side, numbered as the compiler
    // numbers them (ladder::ElementLayout::element). Group numbers may be
    // listed too; the drawing does not need them.
    std::set<std::uint16_t> conducting;
    bool energised = false; // the output was driven
    // Each element's state on its own, whatever power reached it, by element
    // number (sim::ElementState bits): a contact closed, a comparison or a
    // timer's output true, a timer counting, an output's variable 1. Elements
    // beyond its end have none.
    std::vector<std::uint8_t> states;
};

// The power flow of one scan of a unit, as the simulator publishes it: a
// statement that is not listed did not run (its step was not active). The
// drawing only restyles what the snapshot says; it never evaluates logic.
struct PowerSnapshot {
    std::map<std::uint32_t, StatementPower> statements; // by statement number in the unit
    // After the scan, the values of the variables bound to block pins (those
    // the page asked for): a box's pins show them.
    std::map<lang::Address, std::int64_t> values;

    bool ran(std::uint32_t statement) const;
    // Element 0 is the output: it conducts when it is energised.
    bool conducts(std::uint32_t statement, std::uint16_t element) const;
    // The element's own state (sim::ElementState bits; 0 when its statement
    // did not run): closed() and running() ask for one bit.
    std::uint8_t state(std::uint32_t statement, std::uint16_t element) const;
    bool closed(std::uint32_t statement, std::uint16_t element) const;
    bool running(std::uint32_t statement, std::uint16_t element) const;
    // A wire carries power when its feed does: the left rail of a statement
    // that ran, or any of the elements whose right side it joins.
    bool powers(const ladder::PowerFeed& feed) const;
};

} // namespace rs::render
