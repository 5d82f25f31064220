// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/Address.h"
#include "project/Project.h"

#include <string>
#include <vector>

// What the block instances of a unit take of its variables, so that the
// pages can say which block uses a variable: each pin's operand and each
// private variable the instance was given (its #NAME="ADDRESS" bindings).
namespace rs::blocks {

struct InstanceVariable {
    enum class Role { Pin, Private };

    // As the Variables page lists it (project::canonicalVariable).
    lang::Address address;
    Role role = Role::Pin;
    std::string name;      // the pin, or the private variable without its '#'
    std::string blockType; // the instance's block
    int line = 0;          // of its ;@block record in the unit's text (project::unitText)

    friend bool operator==(const InstanceVariable&, const InstanceVariable&) = default;
};

// The variables of unit `station` that its instances bind, in the order of
// the instances and, within one, of the record. A pin bound to a time or a
// number, or to a name the unit does not see, takes no variable.
std::vector<InstanceVariable> instanceVariables(const project::Project& project, int station);

} // namespace rs::blocks
