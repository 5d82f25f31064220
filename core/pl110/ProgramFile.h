// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

namespace rs::pl110 {

// Whether a file holds a PL110 program rather than a Pluto project, from its
// first 64 KB only: what a reader of either kind asks before it reads a file
// that may be megabytes long. False when it cannot be read.
bool isPl110File(const QString& path);

} // namespace rs::pl110
