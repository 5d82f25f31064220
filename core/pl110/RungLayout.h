// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Program.h"
#include "ladder/Layout.h"

#include <QString>

// A PL110 rung drawn as the ladder draws every target's rungs
// (ladder/RungGeometry.h): one network per rung, its contacts, IF boxes,
// NOT and P/N on the power flow, and its output at the right.
namespace rs::pl110 {

struct RungLayoutContext {
    QString title;               // "Rung 3"
    QString comment;             // the comment lines above the rung, shown beside the title
    std::uint32_t statement = 0; // the rung's number in its part, for live power
    ladder::LayoutMetrics metrics;
};

ladder::NetworkLayout layoutRung(const Rung& rung, const RungLayoutContext& context);

} // namespace rs::pl110
