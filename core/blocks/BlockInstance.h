// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/Ast.h"
#include "lang/Diagnostic.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rs::project {
struct Annotation;
}

// A block instance in the project text (blocks.md): a ";@block TYPE
// PIN="OPERAND" ..." record, the ordinary statements it stands for (its
// expansion) and a ";@end" record, all inside one step. Besides the pins the
// record may name its library and version, and it records the private
// variables the instance was given as #NAME="OPERAND", so that expanding it
// again gives the same statements.
namespace rs::blocks {

inline constexpr const char* kBlockRecord = "block";
inline constexpr const char* kEndRecord = "end";

struct Binding {
    std::string name;    // a pin, or a private variable without its '#'
    std::string operand; // as written
    int column = 0;      // of the name in the record's line; 0 when not read from one
};

struct BlockInstance {
    std::string type;
    std::vector<Binding> pins;
    std::vector<Binding> privates;
    std::string library; // lib="…"; empty when not named
    std::string version;
    std::size_t record = 0; // index of the ;@block line in the step's lines
    std::size_t end = 0;    // index of its ;@end line
    lang::SourceLocation location;

    bool hasExpansion() const { return end > record + 1; }
    const Binding* findPin(std::string_view pin) const;
    const Binding* findPrivate(std::string_view name) const;
};

// The instance a ;@block record describes (without its place in the step);
// nothing when the annotation is no block record. Problems (no type, a
// binding given twice) go to `diagnostics` at `at`.
std::optional<BlockInstance> instanceOf(const project::Annotation& record, lang::SourceLocation at,
                                        lang::Diagnostics& diagnostics);

// The record's comment text (after ';') for an instance: type, pins in their
// order, then lib, version and the private variables.
std::string recordText(const BlockInstance& instance);

struct StepInstances {
    std::vector<BlockInstance> instances; // in the order of the step
    lang::Diagnostics diagnostics;
};

// The instances of one step. A record without its ;@end before the step
// ends, an ;@end without a record, or a record inside another instance is an
// error at that line, and the record is not an instance.
StepInstances findInstances(const lang::Step& step);

} // namespace rs::blocks
