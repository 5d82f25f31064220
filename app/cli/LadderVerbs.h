// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Invocation.h"

namespace rs::cli {

// `ladder FILE.sps --unit U [--sequence S --step N] --network K
// [--scenario SCN.scn] -o OUT.svg|.png`: draws one network of a step (the
// unit's PLC code S<U>.0_0 by default) as the editor does. Networks are
// numbered from 1 within their step. With a scenario, the project is
// compiled and the scenario run from power on, and the network is drawn
// with the power it has when the scenario ends.
int runLadder(const Invocation& invocation);

// `roundtrip FILE.sps`: turns every network into the ladder model and back
// and prints the project text. Exit 1 when the project has errors, or when
// the text differs from the canonical text (which would be a bug: the
// differing line is reported).
int runRoundtrip(const Invocation& invocation);

} // namespace rs::cli
