// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Invocation.h"

namespace rs::cli {

// "vars export FILE.sps -o OUT.csv": the project's variable names and
// descriptions as CSV. "vars import FILE.sps IN.csv -o OUT.sps": names and
// descriptions from CSV into the project, written to OUT.sps; a bad row is an
// error at its line, and then nothing is written.
int runVars(const Invocation& invocation);

} // namespace rs::cli
