// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Invocation.h"

namespace rs::cli {

// The verbs a reviewer uses (cli.md, "Verbs for review, change control and
// project work").

// `signature FILE.sps`: one line per unit, "Pluto NN XXXXXXXX", then
// "project XXXXXXXX" (compiler/Signature.h). Given a compiled FILE.hps it
// prints the same figures as read from the images, so the image on a unit
// can be matched with the source it came from.
int runSignature(const Invocation& invocation);

} // namespace rs::cli
