// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Invocation.h"

namespace rs::cli {

// `merge A.sps B.sps -o OUT.sps [--ignore-conflicts]`: the manual's Merge
// Project (Part 1, 12.2, project/ProjectMerge.h), A with B's units added.
// Each conflict is a line on stderr and nothing is written (exit 1); with
// --ignore-conflicts the shared names are said and kept only in their own
// units. Exit 1 as well when a project has errors, 2 for usage or a file that
// cannot be read or written.
int runMerge(const Invocation& invocation);

} // namespace rs::cli
