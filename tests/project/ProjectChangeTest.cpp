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

        // What a view of the step is told: the run, both ways, unless the
        // step's header changed too.
        if (change.empty())
            continue;
        const bool headerChanged = edited.comment != step.comment;
        for (const bool forward : {true, false}) {
            const auto run = change.stepLines(forward);
            ASSERT_EQ(run.has_value(), !headerChanged) << "round " << round;
            if (!run)
                continue;
            EXPECT_EQ(before.program.units[run->unit].station(), 2);
            EXPECT_EQ(run->step, 0u);
            std::vector<lang::Line> lines = (forward ? step : edited).lines;
            const auto at = lines.begin() + static_cast<std::ptrdiff_t>(run->first);
            ASSERT_TRUE(std::equal(run->removed.begin(), run->removed.end(), at));
            lines.insert(lines.erase(at, at + static_cast<std::ptrdiff_t>(run->removed.size())),
                         run->added.begin(), run->added.end());
            ASSERT_EQ(lines, (forward ? edited : step).lines) << "round " << round;
        }
    }
}

// An edit that knows its run of lines makes the change without comparing the step.
TEST(ProjectChange, ARunOfAStepsLinesReplacedIsTheChangeOfTheProject) {
    test::RandomProgram random(7);
    project::Project before = start();
    lang::Step& step = project::programOf(before, 2).steps.front();
    for (int i = 0; i < 10; ++i)
        step.lines.push_back({random.statement(), std::nullopt, {}});
    const std::vector<lang::Line> added{{random.statement(), std::nullopt, {}},
                                        {lang::CommentLine{" new", false}, std::nullopt, {}}};
    const auto change = project::ProjectChange::ofStepLines(before, 1, 0, 3, 4, added);

    project::Project after = before;
    auto& lines = project::programOf(after, 2).steps.front().lines;
    lines.insert(lines.erase(lines.begin() + 3, lines.begin() + 7), added.begin(), added.end());
    project::Project current = before;
    change.apply(current);
    EXPECT_TRUE(current == after);
    change.revert(current);
    EXPECT_TRUE(current == before);
    const auto run = change.stepLines(true);
    ASSERT_TRUE(run);
    EXPECT_EQ(run->unit, 1u);
    EXPECT_EQ(run->first, 3u);
    EXPECT_EQ(run->removed.size(), 4u);
    EXPECT_EQ(run->added.size(), 2u);

    // The same lines again change nothing; a run outside the step is refused.
    const std::vector<lang::Line> same(step.lines.begin() + 2, step.lines.begin() + 4);
    EXPECT_TRUE(project::ProjectChange::ofStepLines(before, 1, 0, 2, 2, same).empty());
    EXPECT_THROW((void)project::ProjectChange::ofStepLines(before, 1, 0, 9, 2, {}),
                 std::out_of_range);
}
