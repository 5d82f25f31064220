// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Address.h"
#include "ladder/SeriesParallel.h"
#include "lang/SourceLocation.h"

#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

// A PL110 program as Rungsmith's text form writes it (docs/pl110.md): the
// tree keeps what has meaning or is meant for people, not spelling, so the
// printer's text is canonical and a rung's condition is the ladder's
// series/parallel circuit.
namespace rs::pl110 {

// A memory place, written as an address or as a declared name.
struct Operand {
    std::string name; // as written, when the program uses a name
    Address address;  // written, or filled in from the names
    lang::SourceLocation location;

    bool isName() const { return !name.empty(); }
    friend bool operator==(const Operand&, const Operand&) = default;
};

// A word operand or a constant.
struct Value {
    std::optional<Operand> operand;
    std::int32_t constant = 0;
    lang::SourceLocation location;

    bool isConstant() const { return !operand.has_value(); }
    friend bool operator==(const Value&, const Value&) = default;
};

enum class CompareOp : std::uint8_t { Equal, NotEqual, Greater, Less, GreaterEqual, LessEqual };

enum class ElementKind : std::uint8_t {
    NormallyOpen,   // I3, V3.4 (the BIT contact)
    NormallyClosed, // /I3
    Compare,        // (VW1>=10): the IF contact
    Not,            // NOT: inverts the power reaching it
    RisingEdge,     // P: one scan of power when the power reaching it comes on
    FallingEdge,    // N: one scan of power when it goes off
};

struct Element {
    ElementKind kind = ElementKind::NormallyOpen;
    Operand operand; // contacts
    Value left;      // Compare
    CompareOp compare = CompareOp::Equal;
    Value right;
    friend bool operator==(const Element&, const Element&) = default;
};

using Circuit = ladder::SeriesParallel<Element>;

enum class OutputKind : std::uint8_t {
    Coil,     // Q1 = ..., M1, B1 (a bistable relay changes on each energisation)
    SetBit,   // SBIT(V3.4)
    ResetBit, // RBIT(V3.4)
    Timer,    // TON(T1, 100ms, 50)
    Counter,  // MUP(C1, UP, 10)
    Move,     // (VW1 = 5): MOV
    Formula,  // (VW1 = VW2 + 3): FM
};

enum class TimerType : std::uint8_t { OnDelay, OffDelay, Retentive }; // TON, TOFF, TONR
enum class TimeBase : std::uint8_t { Ms10, Ms100, S1 };
enum class CounterType : std::uint8_t { Up, Down };         // MUP, MDOWN
enum class CounterInput : std::uint8_t { Up, Down, Reset }; // the coil's input
enum class FormulaOp : std::uint8_t { Add, Sub, Mul, Div, Or, And, Xor, ShiftLeft, ShiftRight };

int milliseconds(TimeBase base);

struct Output {
    OutputKind kind = OutputKind::Coil;
    Operand target; // the coil's bit, SBIT/RBIT's bit, T or C, MOV/FM's destination
    TimerType timer = TimerType::OnDelay;
    TimeBase base = TimeBase::Ms100;
    CounterType counter = CounterType::Up;
    CounterInput input = CounterInput::Up;
    Value preset; // Timer (into PT), Counter (into PV)
    Value left;   // Move's source, Formula's first operand
    FormulaOp formula = FormulaOp::Add;
    Value right; // Formula's second operand
    friend bool operator==(const Output&, const Output&) = default;
};

// One rung: a condition from the left rail to one output. Without a
// condition the output is powered every scan.
struct Rung {
    std::optional<Circuit> condition;
    Output output;
    friend bool operator==(const Rung&, const Rung&) = default;
};

// "! I1=Start": a name for an address, in the declarations before INIT.
struct NameDeclaration {
    Operand variable;
    std::string name;
    lang::SourceLocation nameLocation;
    friend bool operator==(const NameDeclaration&, const NameDeclaration&) = default;
};

struct BlankLine {
    friend bool operator==(const BlankLine&, const BlankLine&) = default;
};

struct CommentLine {
    std::string text; // after ';'
    friend bool operator==(const CommentLine&, const CommentLine&) = default;
};

using LineBody = std::variant<BlankLine, CommentLine, NameDeclaration, Rung>;

struct Line {
    LineBody body;
    std::optional<std::string> comment; // trailing, after ';'
    lang::SourceLocation location;
    friend bool operator==(const Line&, const Line&) = default;
};

// "$target PL110", "$name ...", declarations, then the two program parts:
// INIT runs once before the first scan, MAIN every scan (docs/pl110.md).
struct Program {
    std::string name;
    std::vector<Line> declarations; // blank, comment and name lines
    std::vector<Line> init;
    std::vector<Line> main;
    friend bool operator==(const Program&, const Program&) = default;
};

} // namespace rs::pl110
