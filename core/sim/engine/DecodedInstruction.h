// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "compiler/Image.h"
#include "sim/UnitMemory.h"

#include <cstdint>

namespace rs::sim::engine {

// How the marking interpreter runs an instruction: the image's ops, with the
// common cases split out so that their code has no branches on the data (a
// branch that depends on the data mispredicts whenever the data changes, and
// that is most of an interpreter's time).
enum Handler : std::uint8_t {
    HRung,
    HContactByte,
    HContact,
    HEdge,
    HTimer,
    HLoadA,
    HLoadB,
    HEqual, // HEqual + lang::CompareOp
    HGreater,
    HLess,
    HGreaterEqual,
    HLessEqual,
    HBranchOpen,
    HBranchNext,
    HBranchClose,
    HCoilByte,
    HCoil,
    HSetByte,
    HSet,
    HResetByte,
    HReset,
    HToggle,
    HJump,
    HSequenceReset,
    HArith,
    HSystem,
    HArgument,
    HandlerCount
};

// An instruction ready to run: 24 bytes, its operand resolved to a pointer
// into the unit's memory (or the copy of another unit's variables, or a sink
// for forced targets).
struct DecodedInstruction {
    compiler::Op op;
    std::uint8_t handler;
    std::uint8_t flags;
    std::uint8_t aux;
    std::uint8_t refKind; // BitRef::Kind or WordRef::Kind, by op
    std::uint8_t bit;     // register bit
    bool dropWrite;       // an arithmetic target that is forced
    std::uint16_t slot;
    std::int32_t constant;
    void* ref;

    void pointAt(const BitRef& target) {
        refKind = static_cast<std::uint8_t>(target.kind);
        bit = static_cast<std::uint8_t>(target.bit);
        ref = target.kind == BitRef::Kind::Byte          ? static_cast<void*>(target.byte)
              : target.kind == BitRef::Kind::RegisterBit ? static_cast<void*>(target.word)
                                                         : static_cast<void*>(target.wide);
    }
    void pointAt(const WordRef& target) {
        refKind = static_cast<std::uint8_t>(target.kind);
        ref = target.kind == WordRef::Kind::Wide ? static_cast<void*>(target.wide)
                                                 : static_cast<void*>(target.word);
    }
    bool isBitKind(BitRef::Kind kind) const { return refKind == static_cast<std::uint8_t>(kind); }
    bool isWordKind(WordRef::Kind kind) const { return refKind == static_cast<std::uint8_t>(kind); }

    bool readBit() const {
        switch (static_cast<BitRef::Kind>(refKind)) {
        case BitRef::Kind::Byte:
            return *static_cast<const std::uint8_t*>(ref) != 0;
        case BitRef::Kind::RegisterBit:
            return (static_cast<std::uint16_t>(*static_cast<const std::int16_t*>(ref)) >> bit) & 1u;
        case BitRef::Kind::Analog:
            return *static_cast<const std::int32_t*>(ref) != 0;
        case BitRef::Kind::None:
            break;
        }
        return false;
    }
    void writeBit(bool value) const {
        BitRef target;
        target.kind = static_cast<BitRef::Kind>(refKind);
        target.byte = static_cast<std::uint8_t*>(ref);
        target.word = static_cast<std::int16_t*>(ref);
        target.wide = static_cast<std::int32_t*>(ref);
        target.bit = bit;
        target.write(value);
    }
    std::int64_t readWord() const {
        WordRef source;
        source.kind = static_cast<WordRef::Kind>(refKind);
        source.word = static_cast<std::int16_t*>(ref);
        source.wide = static_cast<std::int32_t*>(ref);
        return source.read();
    }
    void writeWord(std::int64_t value) const {
        WordRef target;
        target.kind = static_cast<WordRef::Kind>(refKind);
        target.word = static_cast<std::int16_t*>(ref);
        target.wide = static_cast<std::int32_t*>(ref);
        target.write(value);
    }
    bool wideWord() const { return !isWordKind(WordRef::Kind::Register); }
};

} // namespace rs::sim::engine
