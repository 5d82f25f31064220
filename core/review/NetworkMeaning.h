// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "project/Project.h"

#include <string>

namespace rs::review {

// What a network does, as text to compare: its statements with every operand
// by its address (a symbolic name is only a name), each timer in one
// spelling, and the system calls of its ;@system records, also by address. Comments and layout are
// left out, so two networks with the same text here do the same.
std::string networkMeaning(const lang::Document& document, int station,
                           const project::Network& network);

} // namespace rs::review
