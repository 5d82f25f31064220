// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Project.h"

#include <cstddef>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace rs::project {

// A change that replaced a run of one step's lines and nothing else: lines
// [first, first + removed.size()) of the step became `added`. The spans
// point into the change that tells it.
struct StepLinesChange {
    std::size_t unit = 0; // its index in the program's units
    std::size_t step = 0; // its index in the unit's steps
    std::size_t first = 0;
    std::span<const lang::Line> removed;
    std::span<const lang::Line> added;
};

// The difference between two states of a project, as an undo step keeps it:
// only the parts that differ (the preamble, one unit's declarations, one
// step), both ways, so that a long undo history of small edits stays small.
class ProjectChange {
public:
    static ProjectChange between(const Project& before, const Project& after);
    // The same, where `after` holds the code of `station` only (its other
    // units' code left out, as withOnlyCodeOf does) and leaves the other
    // units as they were: only this unit, the preamble and the records are
    // compared, so the cost is the unit's.
    static ProjectChange ofUnitCode(const Project& before, const Project& after, int station);

    // Lines [first, first + removed) of step `step` of unit `unit` (indices in
    // the program) replaced by `added`; the cost is the lines', not the step's.
    static ProjectChange ofStepLines(const Project& before, std::size_t unit, std::size_t step,
                                     std::size_t first, std::size_t removed,
                                     std::vector<lang::Line> added);

    bool empty() const;
    // What applying (forward) or reverting the change does, when all it does
    // is replace a run of one step's lines: so that a view of the step can
    // read again only what the run touches.
    std::optional<StepLinesChange> stepLines(bool forward) const;
    // Turns the project as it was before into the project after, and back.
    void apply(Project& project) const;
    void revert(Project& project) const;

private:
    template <typename T> struct Replacement {
        T before;
        T after;
    };
    // What the language has no words for: descriptions, options, attributes.
    struct Records {
        std::string description;
        bool includeSource = false;
        std::map<int, std::string> unitDescriptions;
        std::set<int> idfixProg;
        std::map<int, AsiOptions> asiOptions;
        std::map<int, int> canCycleMs;
        std::map<int, ExternalComm> externalComm;
        std::map<int, Gateway> gateways;
        std::map<lang::Address, std::string> variableDescriptions;
        std::set<lang::Address> exportedVariables;
        std::set<lang::Address> remanentVariables;
        std::vector<std::string> libraries;
        std::optional<Baseline> baseline;
        std::optional<Protection> protection;
        friend bool operator==(const Records&, const Records&) = default;
    };
    // A step's header, and the run of its lines that differs: the lines
    // before and after it are the same, so a long step is not kept twice.
    struct StepChange {
        std::size_t index = 0;
        Replacement<lang::Step> header; // without lines
        std::size_t firstLine = 0;
        Replacement<std::vector<lang::Line>> lines;
    };
    struct UnitChange {
        std::size_t index = 0;
        std::optional<Replacement<std::vector<lang::Line>>> declarations;
        std::optional<Replacement<std::vector<lang::Step>>> allSteps; // steps added or removed
        std::vector<StepChange> steps;
    };
    static StepChange stepChange(std::size_t index, const lang::Step& before,
                                 const lang::Step& after);
    static void changeStep(lang::Step& step, const StepChange& change, bool forward);

    static ProjectChange between(const Project& before, const Project& after,
                                 std::optional<int> onlyCodeOf);
    static Records recordsOf(const Project& project);
    static void setRecords(Project& project, const Records& records);
    void change(Project& project, bool forward) const;

    std::optional<Replacement<Records>> m_records;
    std::optional<Replacement<std::vector<lang::Line>>> m_preamble;
    std::optional<Replacement<std::vector<lang::UnitProgram>>> m_units; // units added or removed
    std::vector<UnitChange> m_unitChanges;
};

} // namespace rs::project
