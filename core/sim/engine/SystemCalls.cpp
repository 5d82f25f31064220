// SPDX-License-Identifier: GPL-3.0-or-later
#include "SystemCalls.h"

#include "InstructionMeaning.h"
#include "UnitState.h"
#include "compiler/SystemInstruction.h"

namespace rs::sim::engine {

namespace {

using compiler::SystemInstructionId;

constexpr int kFirstPresent = 100; // SM_Pluto0_Present; station n's is SM100 + n

std::int64_t valueOf(const DecodedInstruction& argument) {
    return (argument.flags & compiler::ConstantOperand) ? argument.constant : argument.readWord();
}

// A register output holds what fits it, as arithmetic saturates.
void store(const DecodedInstruction& argument, std::int64_t value) {
    argument.writeWord(saturated(value, argument.isWordKind(WordRef::Kind::Register)
                                            ? kRegisterBounds
                                            : Bounds{INT32_MIN, INT32_MAX}));
}

// RegisterValid, DRegisterValid (manual Part 1, 10.2.1): Input is valid
// while the unit it belongs to is on the bus, which the simulator says with
// that unit's SM_Pluto<n>_Present; Value is Input then, else 0.
void registerValid(UnitState& unit, const DecodedInstruction* operands) {
    const DecodedInstruction& input = operands[0];
    const bool valid = unit.memory.systemMemories[kFirstPresent + input.slot] != 0;
    operands[1].writeBit(valid);
    store(operands[2], valid ? valueOf(input) : 0);
}

} // namespace

void runSystemCall(UnitState& unit, const DecodedInstruction& call) {
    const DecodedInstruction* operands = &call + 1;
    switch (static_cast<SystemInstructionId>(call.aux)) {
    case SystemInstructionId::RegisterValid:
    case SystemInstructionId::DRegisterValid:
        registerValid(unit, operands);
        return;
    }
}

} // namespace rs::sim::engine
