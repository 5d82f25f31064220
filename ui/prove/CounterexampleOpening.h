// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

namespace rs::ui {

class MainWindow;
class ProjectDocument;
struct PropertyProof;

// Open Counterexample (docs/ide.md, "Properties"): writes the proof's
// scenario beside the project as BASE-LINE.scn, the name rungsmith-cli prove
// gives it (in a temporary folder for a project without a file), and runs it
// in the simulator as Simulate > Run Scenario does: the waveform records it
// and the simulation stops after its last scan, the one that breaks the
// property. Then the ladder of the unit shows, live, with the operand that
// the scenario's last line expects chosen, so that the page says why it is
// on or off. Returns the scenario's path, or empty and the reason in `error`.
QString openCounterexample(MainWindow& window, ProjectDocument* document,
                           const PropertyProof& proof, QString& error);

} // namespace rs::ui
