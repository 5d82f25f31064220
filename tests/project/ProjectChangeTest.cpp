// SPDX-License-Identifier: GPL-3.0-or-later
#include "project/ProjectChange.h"
#include "ProjectText.h"
#include "project/IoOptions.h"
#include "project/ProjectProperties.h"
#include "project/Sequences.h"
#include "project/UnitSettings.h"
#include "project/UnitText.h"
#include "project/VariableTable.h"

#include <gtest/gtest.h>

#include <functional>

using namespace rs;
using lang::AddressKind;

namespace {

project::Project start() {
    project::Project p = project::newProject("Change", "first", false);
    project::UnitSettings unit;
    unit.type = target::UnitType::B46;
    unit.instructionSet = 3;
    EXPECT_FALSE(project::addUnit(p, unit));
    unit.station = 2;
    EXPECT_FALSE(project::addUnit(p, unit));
    return p;
}

using Edit = std::function<void(project::Project&)>;

} // namespace

// Every kind of edit, applied one after the other; then the whole history is
// undone and redone step by step, as the undo stack does.
TEST(ProjectChange, ApplyAndRevertWalkTheHistoryExactly) {
    const std::vector<Edit> edits{
        [](auto& p) {
            project::setVariableName(p, {AddressKind::Input, 0, 1}, "Start");
        },
        [](auto& p) {
            project::setVariableName(p, {AddressKind::Memory, 2, 4}, "Busy");
        },
        [](auto& p) {
            project::setVariableDescription(p, {AddressKind::Memory, 2, 4}, "busy");
        },
        [](auto& p) {
            project::setTerminalSetting(p, {project::TerminalKind::Input, 0, 1},
                                        {project::SignalType::Input, project::SignalShape::Static});
        },
        [](auto& p) { project::addSequence(p, 2, 4); },
        [](auto& p) {
            auto read =
                project::readUnitText(p, 2, "! pgm_pluto:02\n! M2.4=Busy\nS2.0_0\nQ2.2 = Busy\n");
            ASSERT_TRUE(read.ok());
            p = read.project;
        },
        [](auto& p) { p.description = "second"; },
        // Marking as validated changes only the baseline (issue 18).
        [](auto& p) {
            p.baseline = project::Baseline{"2026-12-02", "A. Reviewer", "", 7, {}};
        },
        [](auto& p) {
            project::UnitSettings unit;
            unit.station = 1;
            project::addUnit(p, unit);
        },
        [](auto& p) { project::removeUnit(p, 0); },
    };
    std::vector<project::Project> states{start()};
    std::vector<project::ProjectChange> changes;
    for (const auto& edit : edits) {
        project::Project next = states.back();
        edit(next);
        changes.push_back(project::ProjectChange::between(states.back(), next));
        EXPECT_FALSE(changes.back().empty()) << "edit " << changes.size() - 1;
        states.push_back(std::move(next));
    }
    project::Project current = states.back();
    for (std::size_t i = changes.size(); i-- > 0;) {
        changes[i].revert(current);
        ASSERT_TRUE(current == states[i]) << "undo of edit " << i;
        EXPECT_EQ(textOf(current), textOf(states[i]));
    }
    for (std::size_t i = 0; i < changes.size(); ++i) {
        changes[i].apply(current);
        ASSERT_TRUE(current == states[i + 1]) << "redo of edit " << i;
    }
}

TEST(ProjectChange, NoEditIsAnEmptyChange) {
    const project::Project p = start();
    EXPECT_TRUE(project::ProjectChange::between(p, p).empty());
}
