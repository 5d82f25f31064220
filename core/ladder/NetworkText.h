// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Network.h"

#include <string>
#include <string_view>
#include <vector>

// Networks as text on their own, for the clipboard: the lines of a step that
// holds just them, each network under a ";@network" record, with addresses in
// place of symbolic names so that they mean the same in any unit or project
// (where they are drawn with the names found there).
namespace rs::ladder {

std::string networksText(const std::vector<Network>& networks);

struct NetworksReading {
    std::vector<Network> networks;
    std::string error; // empty when read
};

// Reads what networksText wrote, or any statements of the language with
// addresses (each becomes a network, or those under a record one). A block
// instance comes without its statements and private variables: pasted, it
// is a new instance that the project expands.
NetworksReading readNetworksText(std::string_view text);

} // namespace rs::ladder
