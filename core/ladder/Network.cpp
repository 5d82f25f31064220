// SPDX-License-Identifier: GPL-3.0-or-later
#include "Network.h"

namespace rs::ladder {

int statementCount(const Network& network) {
    int count = 0;
    for (const auto& item : network.items)
        if (const auto* rung = std::get_if<Rung>(&item))
            count += static_cast<int>(rung->outputs.size());
    return count;
}

} // namespace rs::ladder
