// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "RandomCondition.h"
#include "lang/Ast.h"

namespace rs::test {

// Puts ";@network" records (with and without comments, some collapsed) into
// a random step, and gives some statements the condition of the statement
// before, so that networks of several rungs and rungs with several outputs occur.
void addNetworkStructure(lang::Step& step, RandomCondition& random);

} // namespace rs::test
