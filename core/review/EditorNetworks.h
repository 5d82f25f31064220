// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "project/Project.h"

#include <vector>

namespace rs::review {

// The networks of a step as the ladder editor numbers them (cli.md: from 1
// within each step): statements grouped by ;@network records, each other
// statement its own network, and a block instance (;@block … ;@end, its
// record and expansion) one network, as the ladder draws it as one box.
std::vector<project::Network> editorNetworks(const lang::Step& step);

} // namespace rs::review
