// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Element.h"
#include "ElementKind.h"
#include "Output.h"
#include "lang/Ast.h"

#include <cstdint>
#include <optional>
#include <string_view>
#include <variant>
#include <vector>

// What each element kind is in the language: the syntax-tree node it makes
// from its parts, how a node is recognised as the kind, and how it is drawn
// and inserted. Adding a kind is an entry in this table and its drawing
// (docs/design.md, "Adding an element kind").
namespace rs::ladder {

// The node an element stands for: a leaf of a condition, or a statement
// without its condition.
using ElementNode = std::variant<lang::Expr, lang::Statement>;

// What a node is made of; each kind takes the parts it has.
struct ElementParts {
    lang::Operand operand;       // the bit, the compared register, the output's target
    bool operandNegated = false; // an edge of the inverted bit: P(/x)
    bool negated = false;        // a timer or comparison passing power when false
    lang::TimerSpelling timer = lang::TimerSpelling::TON; // kept when it spells the kind
    lang::TimerPreset preset;
    lang::CompareOp compare = lang::CompareOp::Equal;
    lang::Value right;           // a comparison's right side
    lang::Assignment assignment; // its target is `operand`
    bool relativeJump = false;
    int jumpStep = 0;
    friend bool operator==(const ElementParts&, const ElementParts&) = default;
};

// What an element's operand is, for an editor to ask for.
enum class OperandRole : std::uint8_t {
    Variable,
    Preset,
    Register,
    TargetRegister,
    Step,
    Sequence
};

struct ElementKindInfo {
    ElementKind kind;
    bool output; // stands at a rung's right end
    Shape shape;
    OperandRole operandRole;
    bool hasValue;            // besides its operand: a comparison's, an assignment's
    bool canNegate;           // passes power when false: /TON(t), /(R0.1>=5)
    const char* insertKey;    // the key inserting it, as QKeySequence spells it
    const char* picture;      // the symbol in characters, for a toolbar button
    std::string_view mark;    // drawn inside a contact or coil: "P", "/P", "S", "RS";
                              // "/" is a normally closed contact's slash
    std::string_view boxWord; // what a box shows when it stands for the kind alone
    ElementNode (*make)(const ElementParts& parts);
    bool (*reads)(const ElementNode& node); // whether the node is of the kind
};

// Every kind, in the order the editor lists them.
const std::vector<ElementKindInfo>& elementKinds();
const ElementKindInfo& infoOf(ElementKind kind);
bool isOutput(ElementKind kind);
bool isBox(ElementKind kind);

ElementNode makeNode(ElementKind kind, const ElementParts& parts);
// The kind of a leaf or a statement; none for an AND or OR of several.
std::optional<ElementKind> kindOf(const ElementNode& node);
ElementParts partsOf(const ElementNode& node);

ElementKind kindOf(const Element& element);
ElementKind kindOf(const Output& output);

} // namespace rs::ladder
