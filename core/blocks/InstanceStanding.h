// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "BlockInstance.h"
#include "InstanceExpansion.h"
#include "LibrarySearch.h"
#include "UnitVariables.h"
#include "lang/Ast.h"

#include <cstddef>
#include <vector>

// Whether an instance in the project text still is what its block makes of
// its record: the IDE draws such an instance as a box, and shows any other
// as the ordinary statements it holds (blocks.md).
namespace rs::blocks {

enum class Standing {
    AsMade,       // its statements are what the block makes of the record
    OtherVersion, // made by another version of the block than the library's
    EditedByHand, // its statements are no longer the block's
    NoBlock,      // no library of the project has its block
    NotExpanded,  // a record without statements, not yet expanded
};

// The library holding the instance's block: the one it names, else the
// first that has the block; nothing when there is none.
const LoadedLibrary* libraryOf(const BlockInstance& instance, const LibrarySet& libraries);

// What the instances of one unit may still take: the memories and registers
// the unit does not use, less every private variable an instance records.
PrivateVariables freeVariables(const lang::Document& document, int station,
                               const std::vector<const BlockInstance*>& instances);

// How an instance that holds statements stands, its statements being
// `step.lines` between its records. `variables` are what is free in its
// unit; the check takes nothing from them.
Standing standingOf(const BlockDefinition* block, const BlockInstance& instance,
                    const lang::Step& step, UnitFrame& frame, const PrivateVariables& variables);

struct InstanceStatus {
    std::size_t step = 0; // the step's index in the unit
    lang::StepAddress address;
    BlockInstance instance;
    Standing standing = Standing::NoBlock;
    const LoadedLibrary* library = nullptr; // with the block; null for NoBlock
    const BlockDefinition* block = nullptr;
};

// What is wrong with a call of `block` in unit `station` as `instance`
// binds it (an unknown pin or name, an operand of the wrong kind, a required
// input open, no free variable left); nothing when it expands.
lang::Diagnostics callProblems(const lang::Document& document, int station,
                               const BlockDefinition& block, const BlockInstance& instance);

// Whether the IDE draws the instance as its block's box: while its
// statements are what a version of its block made, or while it waits for
// them with its block at hand (a call with an error, to be bound anew).
bool drawnAsBox(const InstanceStatus& status);

// The status of the instance whose ";@block" record is line `record` of
// the step at `step`; null when there is none.
const InstanceStatus* statusAt(const std::vector<InstanceStatus>& statuses,
                               const lang::StepAddress& step, std::size_t record);

// Every instance of unit `station`, in file order, and how it stands.
std::vector<InstanceStatus> instanceStatuses(const lang::Document& document, int station,
                                             const LibrarySet& libraries);

} // namespace rs::blocks
