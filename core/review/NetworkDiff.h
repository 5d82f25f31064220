// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Alignment.h"
#include "project/Project.h"

#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace rs::review {

// One network that a reviewer has to look at: added, removed or changed.
struct NetworkDifference {
    int station = 0;
    lang::StepAddress step;
    int number = 0;    // in its step, from 1: in the new project, in the old one when removed
    int oldNumber = 0; // in the old project, when changed or removed; 0 when added
    Pairing::Kind change = Pairing::Changed;

    // "Pluto 00 S0.0_0 network 3: changed" (cli.md)
    std::string describe() const;
    friend bool operator==(const NetworkDifference&, const NetworkDifference&) = default;
};

// Every step of every unit that has code, by (station, sequence, step): its
// networks in order (editorNetworks), each as text to compare (networkMeaning, or a CRC-32 of
// it as a baseline keeps them).
using StepNetworks = std::map<std::tuple<int, int, int>, std::vector<std::string>>;

StepNetworks networksByStep(const project::Project& project);

// Each network of `networks` by the CRC-32 of its text, as 8 hex digits.
StepNetworks fingerprints(const StepNetworks& networks);

std::vector<NetworkDifference> networkDifferences(const StepNetworks& before,
                                                  const StepNetworks& after);

// The networks that differ in what they do, unit by unit (by station), step
// by step (the PLC code, then each sequence and step by number), in the
// order of the step. Networks are matched by what they do and by their
// order (Alignment.h): comments, layout, symbolic names and timer spellings
// make no difference.
std::vector<NetworkDifference> networkDifferences(const project::Project& before,
                                                  const project::Project& after);

} // namespace rs::review
