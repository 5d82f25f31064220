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

// `diff OLD.sps NEW.sps`: one line per difference of a unit and per added,
// removed or changed network (review/ProjectDiff.h), then whether the
// behaviour changed. Exit 0 when it did not, 1 when it did or a project has
// errors, 2 for usage or a file that cannot be read.
int runDiff(const Invocation& invocation);

} // namespace rs::cli
