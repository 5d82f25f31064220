// SPDX-License-Identifier: GPL-3.0-or-later
#include "project/ProjectChange.h"
#include "ProjectText.h"
#include "RandomProgram.h"
#include "project/IoOptions.h"
#include "project/ProjectProperties.h"
#include "project/Sequences.h"
#include "project/UnitSettings.h"
#include "project/UnitText.h"
#include "project/VariableTable.h"

#include <gtest/gtest.h>

#include <functional>
#include <random>

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

// The text view's edits compare and copy one unit (issue 23): the change
// made from the project without the other units' code does to the whole
// project what the change of the whole project does.
TEST(ProjectChange, AChangeOfOneUnitsCodeMadeWithoutTheOtherUnitsCodeIsTheWholeChange) {
    project::Project before = start();
    project::UnitSettings unit;
    unit.station = 5;
    unit.type = target::UnitType::A20;
    ASSERT_FALSE(project::addUnit(before, unit));
    // The last unit's declarations end with a blank line, before its code:
    // left out of the part, that code must not make the blank line "last".
    auto last =
        project::readUnitText(before, 5, "! pgm_pluto:05\n! M5.1=Lamp\n\nS5.0_0\nQ5.2 = Lamp\n");
    ASSERT_TRUE(last.ok());
    before = last.project;
    const std::string typed = "! pgm_pluto:02\n! M2.4=Busy\n;@var M2.4 description=\"busy\"\n"
                              "S2.0_0\nQ2.2 = Busy\n";
    const auto whole = project::readUnitText(before, 2, typed);
    const auto part = project::readUnitCode(before, 2, typed);
    ASSERT_TRUE(whole.ok());
    ASSERT_TRUE(part.ok());
    EXPECT_TRUE(part.project.program.units.back().steps.empty()) << "the other code is left out";

    project::Project changed = before;
    const auto change = project::ProjectChange::ofUnitCode(before, part.project, 2);
    change.apply(changed);
    EXPECT_TRUE(changed == whole.project);
    EXPECT_EQ(textOf(changed), textOf(whole.project));
    change.revert(changed);
    EXPECT_TRUE(changed == before);
    EXPECT_TRUE(
        project::ProjectChange::ofUnitCode(before, project::withOnlyCodeOf(before, 2), 2).empty());
}

// A change of a step keeps the run of lines that differs (issue 23): random
// insertions, removals and replacements of lines, anywhere in a step, and a
// changed step header, are undone and redone exactly.
TEST(ProjectChange, RandomEditsOfAStepsLinesAreUndoneAndRedone) {
    test::RandomProgram random(23);
    std::mt19937 pick(23);
    const auto uniform = [&](int low, int high) {
        return std::uniform_int_distribution<int>(low, high)(pick);
    };
    for (int round = 0; round < 200; ++round) {
        project::Project before = start();
        lang::Step& step = project::programOf(before, 2).steps.front();
        for (int i = uniform(0, 12); i > 0; --i)
            step.lines.push_back({random.statement(), std::nullopt, {}});
        project::Project after = before;
        lang::Step& edited = project::programOf(after, 2).steps.front();
        for (int edit = uniform(1, 4); edit > 0; --edit) {
            const auto at = [&] {
                return edited.lines.begin() + uniform(0, static_cast<int>(edited.lines.size()) - 1);
            };
            switch (edited.lines.empty() ? 0 : uniform(0, 3)) {
            case 0:
                edited.lines.insert(edited.lines.begin() +
                                        uniform(0, static_cast<int>(edited.lines.size())),
                                    {random.statement(), std::nullopt, {}});
                break;
            case 1:
                edited.lines.erase(at());
                break;
            case 2:
                *at() = {random.statement(), std::string(" changed"), {}};
                break;
            default:
                edited.comment = " step " + std::to_string(round);
                break;
            }
        }
        const auto change = project::ProjectChange::between(before, after);
        project::Project current = before;
        change.apply(current);
        ASSERT_TRUE(current == after) << "round " << round;
        change.revert(current);
        ASSERT_TRUE(current == before) << "round " << round;
    }
}
