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

// `validate FILE.sps --by NAME [--comment TEXT] [--date YYYY-MM-DD] -o OUT.sps`:
// the project with its current version recorded as validated (a ;@validated
// baseline, project/Baseline.h). Exit 1 when it has errors.
int runValidate(const Invocation& invocation);

// `review FILE.sps`: the review report, what changed since the project was
// validated: who validated it when, the lines of `diff` against that
// version, and the verdict. Exit 0 when the behaviour did not change, 1 when
// it did, the project has errors or was never validated.
int runReview(const Invocation& invocation);

} // namespace rs::cli
