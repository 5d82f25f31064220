// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "BlockInstance.h"
#include "BlockLibrary.h"
#include "UnitVariables.h"
#include "lang/Ast.h"
#include "lang/Diagnostic.h"

#include <map>
#include <string>
#include <vector>

// One instance's statements from its block's body (blocks.md): each pin's
// bound operand, or what stands in for an unbound pin, and each private
// variable's operand put in the body's placeholders, read as Pluto with the
// unit's names.
//
// What stands in for an unbound pin:
// - an input with a time, register or constant default: the default itself;
// - a bit input with a default: a private memory of the instance, set in the
//   first scan when the default is 1 (the language has no constant contact);
// - an output: a private variable of its kind, which nothing else reads.
// An input without a default must be bound.
namespace rs::blocks {

// The unit an instance stands in, as its statements are read: its names
// (and the project's global ones), made once for all instances of the unit.
class UnitFrame {
public:
    UnitFrame(const lang::Document& document, int station);

    int station() const { return m_station; }
    const std::map<std::string, lang::Address>& names() const { return m_names; }
    // Statements read as code of the unit, names resolved; problems in `problems`.
    std::vector<lang::Line> read(const std::string& body, lang::Diagnostics& problems);

private:
    int m_station;
    std::map<std::string, lang::Address> m_names;
    lang::Document m_frame; // the unit's declarations; the statements come and go
    std::string m_head;     // its program header and a step
};

// The name under which a private variable standing in for an unbound pin is
// recorded: "#pin.Fault".
std::string standInName(const Pin& pin);

struct Expansion {
    std::vector<lang::Line> lines; // with the record's place as their place
    lang::Diagnostics diagnostics; // at the record

    bool ok() const { return lang::errorCount(diagnostics) == 0; }
};

// The private variables the instance records are taken from `variables`
// beforehand (so that no other instance gets them); those it lacks are
// taken now and added to `instance.privates`. A shortage, an unknown pin, an
// operand of a kind the pin does not take or an input left open is an error.
Expansion expandInstance(const BlockDefinition& block, BlockInstance& instance, UnitFrame& frame,
                         PrivateVariables& variables);

} // namespace rs::blocks
