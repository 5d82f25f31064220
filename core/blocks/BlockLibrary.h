// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>
#include <string>
#include <vector>

// A function block library as read from a .rslib file
// (docs/block-libraries.md). The model holds what a block instance needs to
// be checked, expanded, drawn and described; it keeps no source positions,
// so a library read back from its written text compares equal to itself.
namespace rs::blocks {

// Macro blocks expand to ordinary statements only; a system block's
// expansion calls a system instruction of Rungsmith's image (blocks.md).
enum class BlockKind { Macro, System };

enum class PinDirection { In, Out };

enum class PinKind { Bit, Register, DoubleRegister, Time, Constant };

// A primary pin is drawn and bound first (the first bit input takes the
// rung's power); a secondary output may stay open (manual 3.13).
enum class PinRole { Primary, Secondary };

// What an instance may bind to a pin. The allowed set is part of the pin,
// so a block can narrow a bit input to inputs or widen a time to registers.
enum class OperandKind {
    Input,          // I, IQ as input
    Output,         // Q, IQ as output
    Memory,         // M
    GlobalMemory,   // GM
    SystemMemory,   // SM
    RegisterBit,    // Ru.n.b
    Register,       // R
    DoubleRegister, // DR
    SystemRegister, // SR
    TimeConstant,   // 0s50
    Number,         // a decimal constant
};

struct Pin {
    std::string name;
    PinDirection direction = PinDirection::In;
    PinKind kind = PinKind::Bit;
    PinRole role = PinRole::Primary;
    // Inputs only; an input without one must be bound by every instance.
    std::optional<std::string> defaultValue;
    std::vector<OperandKind> operands; // in the order of the enum, no repeats
    friend bool operator==(const Pin&, const Pin&) = default;
};

enum class PrivateKind { Memory, Register, DoubleRegister };

// A variable each instance gets for itself from what its unit does not use,
// written in the body as {#name}.
struct PrivateVariable {
    std::string name;
    PrivateKind kind = PrivateKind::Memory;
    friend bool operator==(const PrivateVariable&, const PrivateVariable&) = default;
};

// Text in the three languages of the manual's "Block Description Language";
// English is required, the others fall back to it.
struct Description {
    std::string english;
    std::string swedish;
    std::string german;

    // "en", "sv" or "de"; English for any other code or an empty text.
    const std::string& in(std::string_view language) const;
    friend bool operator==(const Description&, const Description&) = default;
};

// What one value of a block's state register (its DiagCode) means, for the
// block's documentation page: the library's `state` records.
struct StateMeaning {
    int code = 0; // the 16-bit pattern, 0x0000 to 0xFFFF (16#8001 is 0x8001)
    Description meaning;
    friend bool operator==(const StateMeaning&, const StateMeaning&) = default;
};

struct BlockDefinition {
    std::string name;
    BlockKind kind = BlockKind::Macro;
    std::string version;
    Description description;
    std::vector<Pin> pins;
    std::vector<PrivateVariable> privates;
    // How many timers (TON, TPS, TOF occurrences) the body holds; each
    // instance counts them against its unit's 50.
    int timers = 0;
    std::string systemInstruction;    // System blocks only
    std::vector<std::string> body;    // lines, placeholders unsubstituted
    std::vector<StateMeaning> states; // in the library's order; empty for a block without states

    // Pin names are matched without regard to case (blocks.md).
    const Pin* findPin(std::string_view pinName) const;
    const PrivateVariable* findPrivate(std::string_view privateName) const;
    friend bool operator==(const BlockDefinition&, const BlockDefinition&) = default;
};

struct BlockLibrary {
    std::string name;
    std::string version;
    Description description;
    std::vector<BlockDefinition> blocks;

    // Block names are matched without regard to case, as pin names are.
    const BlockDefinition* findBlock(std::string_view blockName) const;
    friend bool operator==(const BlockLibrary&, const BlockLibrary&) = default;
};

// ASCII case-insensitive equality: every name of a library is ASCII.
bool sameName(std::string_view a, std::string_view b);

} // namespace rs::blocks
