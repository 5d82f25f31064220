// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Address.h"
#include "Name.h"
#include "OptionalApart.h"
#include "Rare.h"
#include "SourceLocation.h"

#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

// The syntax tree of a Pluto program file. It keeps everything a user wrote
// that has meaning or is meant for people: statements, declarations, comments
// and blank-line structure. Spelling (case, spaces, redundant parentheses) is
// not kept: the printer writes the canonical form.
namespace rs::lang {

// A variable reference: an address, or a symbolic name that resolves to one.
struct Operand {
    Name name;       // as written, when the program uses a symbolic name
    Address address; // written, or filled in by name resolution
    SourceLocation location;

    bool isName() const { return !name.empty(); }
    friend bool operator==(const Operand&, const Operand&) = default;
};

// A register operand or an integer constant.
struct Value {
    OptionalApart<Operand> operand;
    std::int64_t constant = 0;
    SourceLocation location;

    bool isConstant() const { return !operand.has_value(); }
    friend bool operator==(const Value&, const Value&) = default;
};

enum class TimerKind : std::uint8_t { OnDelay, Pulse, OffDelay };

// The manuals have two spellings for two of the timers; a file keeps its own.
enum class TimerSpelling : std::uint8_t { TON, TPS, TOF, T, IT };

TimerKind timerKind(TimerSpelling spelling);

struct TimerPreset {
    OptionalApart<Operand> registerOperand; // a register holding hundredths of a second
    int hundredths = 0;                     // a time constant such as 5s10 = 510
    friend bool operator==(const TimerPreset&, const TimerPreset&) = default;
};

enum class CompareOp : std::uint8_t { Equal, Greater, Less, GreaterEqual, LessEqual };

enum class ExprKind : std::uint8_t {
    Or,      // children, at least two, none of them an Or
    And,     // children, at least two, none of them an And
    Contact, // operand, negated: /I0.0
    Edge,    // P(x) / N(x); operandNegated: P(/x); negated: /P(x), instruction set 3
    Timer,   // TON(t) ...; negated: /TON(t)
    Compare, // (R0.1>=5); negated: /(R0.1>=5)
};

// The one-byte fields come first, together: spread between the others they
// were padded to 8 bytes each (a node 160 bytes, now 144).
struct Expr {
    ExprKind kind = ExprKind::Contact;
    bool negated = false;
    bool operandNegated = false; // Edge of a negated operand
    bool risingEdge = true;      // Edge: P (true) or N (false)
    TimerSpelling timer = TimerSpelling::TON;
    CompareOp compare = CompareOp::Equal;
    std::vector<Expr> children;
    Operand operand; // Contact, Edge; left side of Compare
    TimerPreset preset;
    Value right; // Compare
    SourceLocation location;

    friend bool operator==(const Expr&, const Expr&) = default;
};

enum class AssignOp : std::uint8_t {
    Increment, // (X++)
    Decrement, // (X--)
    AddAssign, // (X += v)
    SubAssign, // (X -= v)
    MulAssign, // (X *= v), instruction set 3
    DivAssign, // (X /= v), instruction set 3
    Copy,      // (X = v)
    Binary,    // (X = a op b)
};

enum class BinaryOp : std::uint8_t { Add, Sub, Mul, Div };

struct Assignment {
    Operand target;
    AssignOp op = AssignOp::Copy;
    Value left; // Copy, the compound forms, and Binary's first operand
    BinaryOp binary = BinaryOp::Add;
    Value right; // Binary's second operand
    friend bool operator==(const Assignment&, const Assignment&) = default;
};

enum class StatementKind : std::uint8_t {
    Coil,          // X = expr, or X alone
    Set,           // S(X)
    Reset,         // R(X)
    Toggle,        // T(X)
    Jump,          // J(n), J(+n), J(-n)
    SequenceReset, // R(Su.s)
    Assign,        // (R0.1 += 2)
};

struct Statement { // the small fields first, as in Expr
    StatementKind kind = StatementKind::Coil;
    bool relativeJump = false;
    int jumpStep = 0;            // absolute step, or signed offset when relative
    Operand target;              // Coil, Set, Reset, Toggle, SequenceReset
    Rare<Assignment> assignment; // Assign: most statements are none
    std::optional<Expr> condition;
    SourceLocation location;
    friend bool operator==(const Statement&, const Statement&) = default;
};

enum class UnitFamily : std::uint8_t { Pluto, Double, ASi, B42ASi };

struct IdDeclaration { // ! id_pluto:00=000034AD4AE1
    UnitFamily family = UnitFamily::Pluto;
    int station = 0;
    std::string idfix; // 12 hex digits, upper case
    friend bool operator==(const IdDeclaration&, const IdDeclaration&) = default;
};

struct TypeDeclaration { // ! type_pluto:00=B46,is3
    int station = 0;
    std::string type;       // canonical spelling, e.g. "B42_ASi"
    int instructionSet = 0; // 2, 3, or 0 when not written
    friend bool operator==(const TypeDeclaration&, const TypeDeclaration&) = default;
};

struct ProgramDeclaration { // ! pgm_pluto:00
    int station = 0;
    friend bool operator==(const ProgramDeclaration&, const ProgramDeclaration&) = default;
};

struct IoDeclaration { // ! I0.5,c_pulse,non_inv,no_filt
    Operand io;
    std::vector<std::string> options; // lower case, in written order
    friend bool operator==(const IoDeclaration&, const IoDeclaration&) = default;
};

struct NameDeclaration { // ! I0.0=MuteSensor1
    Operand variable;
    std::string name;
    SourceLocation nameLocation;
    friend bool operator==(const NameDeclaration&, const NameDeclaration&) = default;
};

using DeclarationBody = std::variant<IdDeclaration, TypeDeclaration, ProgramDeclaration,
                                     IoDeclaration, NameDeclaration>;

struct Declaration {
    DeclarationBody body;
    SourceLocation location;
    friend bool operator==(const Declaration&, const Declaration&) = default;
};

struct Directive {       // $name Example, manual
    std::string keyword; // lower case
    std::string text;
    friend bool operator==(const Directive&, const Directive&) = default;
};

// A comment alone on its line. An indented one is printed at the comment
// column, so comment blocks that explain the line above stay in place.
struct CommentLine {
    std::string text; // after ';', trailing spaces removed
    bool indented = false;
    friend bool operator==(const CommentLine&, const CommentLine&) = default;
};

struct BlankLine {
    friend bool operator==(const BlankLine&, const BlankLine&) = default;
};

using LineBody = std::variant<BlankLine, CommentLine, Directive, Declaration, Statement>;

struct Line {
    LineBody body;
    OptionalApart<std::string> comment; // trailing comment, text after ';'
    SourceLocation location;
    friend bool operator==(const Line&, const Line&) = default;
};

struct Step {
    StepAddress address;
    std::optional<std::string> comment;
    SourceLocation location;
    std::vector<Line> lines;
    friend bool operator==(const Step&, const Step&) = default;
};

// The code of one unit: from "! pgm_pluto:NN" to the next one.
struct UnitProgram {
    Line header; // the pgm_pluto declaration
    std::vector<Line> declarations;
    std::vector<Step> steps;

    int station() const;
    friend bool operator==(const UnitProgram&, const UnitProgram&) = default;
};

struct Document {
    std::vector<Line> preamble; // directives, id/type declarations, global names
    std::vector<UnitProgram> units;
    friend bool operator==(const Document&, const Document&) = default;
};

} // namespace rs::lang
