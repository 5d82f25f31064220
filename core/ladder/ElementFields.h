// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Element.h"
#include "ElementKind.h"
#include "Output.h"

#include <string>
#include <string_view>

// An element or output as the ladder editor's properties dialog edits it:
// its kind and the words typed for it. The kind makes the syntax-tree node;
// the printed node is then read as the language reads any text
// (ElementText.h), with the unit's names.
namespace rs::ladder {

struct ElementFields {
    ElementKind kind = ElementKind::NormallyOpen;
    std::string operand; // the variable, a timer's preset, a jump's step
    std::string value;   // after the operand: ">=5" of a comparison, "+= 2" of an assignment
    bool negated = false;
    std::string comment; // an output's trailing comment
};

ElementFields fieldsOf(const Element& element);
ElementFields fieldsOf(const Output& output);

struct FieldsText {
    std::string text;  // the element as the language writes it
    std::string error; // why the fields make no element of the kind; empty when made
};

// The typed words stand in the node as written, so the language reads them as typed.
FieldsText textOf(const ElementFields& fields);

// A typed word without the spaces and tabs around it.
std::string trimmedField(std::string_view text);

} // namespace rs::ladder
