// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Project.h"

#include <optional>
#include <string>
#include <vector>

// Sequences (manual Part 1, 11.7; Part 2, 3): besides its main code, sequence
// 0, a unit can have sequences 1-9, each a run of steps Su.s_n.
namespace rs::project {

inline constexpr int kFirstSequence = 1;
inline constexpr int kLastSequence = 9;

// The sequences 1-9 the unit's code has steps of, in order.
std::vector<int> sequencesOf(const Project& project, int station);

// Sequence numbers 1-9 the unit does not use yet.
std::vector<int> freeSequences(const Project& project, int station);

// Adds the first step of a sequence, Su.s_0, after the steps of the sequences
// before it. Refuses a number outside 1-9 or one the unit already has.
std::optional<std::string> addSequence(Project& project, int station, int sequence);

// Adds the next step of a sequence after its last one (Su.s_0 when the
// sequence has none); returns the step's number, or the refusal.
struct AddedStep {
    int step = -1;
    std::string refusal;
};
AddedStep addStep(Project& project, int station, int sequence);

} // namespace rs::project
