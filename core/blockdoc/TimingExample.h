// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "blocks/LibrarySearch.h"
#include "sim/WaveformRecorder.h"

#include <QString>

#include <string>
#include <vector>

// A block's timing example (docs/block-libraries.md, "Timing examples"): a
// small project with one instance of the block and a scenario that tells its
// story. The documentation page runs it and draws what the instance's pins
// did, so the diagram is the block's real behaviour, checked by the same
// scenario's expectations in the tests.
namespace rs::blockdoc {

struct TimingExampleFiles {
    QString project;  // BLOCK.sps
    QString scenario; // BLOCK.scn
};

// Beside the library's file, in a folder named as the library.
TimingExampleFiles timingExampleFiles(const blocks::LoadedLibrary& library,
                                      const blocks::BlockDefinition& block);

struct TimingExample {
    std::string problem; // why there is no diagram ("FILE:LINE:COLUMN: ..."); empty when it ran
    sim::WaveformRecorder recording; // the bound pins, in the block's order
    std::vector<std::string> labels; // the pin of each trace
    int passed = 0;
    int failed = 0; // expectations of the scenario that did not hold

    bool ran() const { return problem.empty(); }
};

// Expands the example with `library` alone, compiles it, runs its scenario
// from power on and records every pin of the project's first instance of
// `block` that is bound to a variable. A missing example is a problem too.
TimingExample runTimingExample(const blocks::LoadedLibrary& library,
                               const blocks::BlockDefinition& block);

} // namespace rs::blockdoc
