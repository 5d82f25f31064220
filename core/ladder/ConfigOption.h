// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Network.h"

#include <optional>
#include <string>

// A Config Option (manual Part 1, 11.6): a described check box at the start of
// the PLC code that sets or resets a memory, so that variants of a machine
// differ in one tick. Its text is a network record with an "option" attribute
// and the statement the box stands for:
//
//   ;@network comment="Door switch fitted" option="on"
//   S(M0.5)
//
// "on" sets the memory on every scan, "off" resets it (R(M0.5)). To the
// compiler it is an ordinary statement; any other network is not an option.
namespace rs::ladder {

struct ConfigOption {
    std::string description;
    lang::Operand memory;
    bool checked = false;
    friend bool operator==(const ConfigOption&, const ConfigOption&) = default;
};

// The option a network is, or nothing when it is an ordinary network.
std::optional<ConfigOption> configOptionOf(const Network& network);

Network configOptionNetwork(const ConfigOption& option);

} // namespace rs::ladder
