// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "LadderCursor.h"
#include "LadderLiveState.h"
#ifndef Q_MOC_RUN
#include "LadderStyle.h"
#endif

#include <QString>

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <utility>

namespace rs::ui {

// What every network item of a ladder page draws besides its network: the
// page's colours, the simulator's state, the selection and the problems.
struct LadderDrawing {
    render::LadderStyle style;
    QColor selection;              // the frame around what is selected
    QColor markedNetwork;          // behind the title of a network chosen for Cut or Copy
    QColor problem;                // the frame around an element a diagnostic concerns
    QColor editing;                // the frame of the network in edit mode
    QColor explained;              // the frames of why an output is on or off
    QColor changedSinceValidation; // the bar left of a network that differs from the baseline
    QColor addedSinceValidation;   // the same for a network the baseline did not have
    const LadderLiveState* live = nullptr;
    LadderCursor cursor;
    std::set<std::pair<int, int>> marked; // (step, network) chosen for Cut, Copy, Delete
    std::optional<std::pair<int, int>> editingNetwork;
    // While live, of the selected output: the elements that block its rung's
    // paths (when no path conducts), or those of the path that holds it.
    std::set<std::pair<std::uint32_t, std::uint16_t>> blocking;
    std::set<std::pair<std::uint32_t, std::uint16_t>> holding;
    // Diagnostics by (statement in unit, element), element 0 for the statement as a whole.
    std::map<std::pair<std::uint32_t, std::uint16_t>, QString> problems;
    // The networks that differ from the validated baseline, by (step,
    // network): true when added (docs/review.md), and when it was validated.
    std::map<std::pair<int, int>, bool> sinceValidation;
    QString validatedOn;
};

// The user's ladder colours (the preferences, manual Part 1, 14). Each one
// left invalid is as the window's theme draws it.
struct LadderColours {
    QColor background;
    QColor focusedBackground; // the frame of the selection
    QColor componentBody;     // inside an open contact, a box, a coil
    QColor lines;             // wires, rails and symbols while editing
    QColor linesOff;          // the same while simulating, where no power flows
    QColor linesOn;           // where power flows, and a closed contact's fill
};

// Colours of the drawing that follow the window's palette (light or dark),
// and the user's colours over them; `live` while simulating.
LadderDrawing drawingFor(const QPalette& palette, const LadderColours& chosen = {},
                         bool live = false);

} // namespace rs::ui
