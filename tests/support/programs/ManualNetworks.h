// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ladder/Layout.h"
#include "project/Project.h"

#include <filesystem>
#include <string>
#include <vector>

namespace rs::test {

// The manuals' example programs (tests/data/manual), sorted.
std::vector<std::filesystem::path> manualExamples();

project::Project readExample(const std::filesystem::path& path);

// One network of a project, laid out as the editor shows it.
struct LaidOutNetwork {
    int station = 0;
    lang::StepAddress step;
    int number = 0; // in its step, from 1
    ladder::NetworkLayout layout;

    std::string describe() const; // "S0.1_2 network 3"
};

// Every network of every unit's every step.
std::vector<LaidOutNetwork> layOutEveryNetwork(const project::Project& project);

} // namespace rs::test
