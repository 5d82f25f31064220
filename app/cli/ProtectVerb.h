// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Invocation.h"

namespace rs::cli {

// `protect FILE.sps -o OUT.sps --password-file F [--options main|free|own]
// [--options-password-file G]`: the manual's Password protect (Part 1, 4.1).
// OUT is FILE protected with the password in F (its first line), the Config
// Options changeable as --options says (own: with the password in G). A
// protected FILE takes its own main password in F; `--remove` takes the
// protection off. A FILE changed by hand since it was protected is refused
// unless `--accept-changes` says its holder has reviewed the change. Exit 1
// when FILE has errors or the password does not open it, 2 for usage or a
// file that cannot be read or written.
int runProtect(const Invocation& invocation);

} // namespace rs::cli
