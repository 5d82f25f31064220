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

// The nominal range of an analogue input and what the block scales it by.
struct AnalogueRange {
    std::int64_t low;  // mV or µA: the point Value_0V or Value_4mA is given for
    std::int64_t high; // the point Value_10V or Value_20mA is given for
};
constexpr AnalogueRange kVoltageRange{0, 10'000};     // 0-10 V in mV
constexpr AnalogueRange kCurrentRange{4'000, 20'000}; // 4-20 mA in µA

// a / b rounded down, for b > 0.
std::int64_t floorDivided(std::int64_t a, std::int64_t b) {
    return a / b - (a % b < 0 ? 1 : 0);
}

// offset · span / width to the nearest integer, a half rounded up, exact
// for every 32-bit offset and span: with offset = q · width + r, 0 <= r <
// width, no product leaves 64 bits.
std::int64_t scaled(std::int64_t offset, std::int64_t span, std::int64_t width) {
    const std::int64_t q = floorDivided(offset, width);
    const std::int64_t r = offset - q * width;
    return q * span + floorDivided(2 * r * span + width, 2 * width);
}

// ReadVoltage, ReadCurrent and their _32 forms (manual Part 1, 8): the
// input's value is the measured one in mV or µA, already calibrated; Q says
// it is within the nominal range; the scaled value is the straight line
// through (low, Value at low) and (high, Value at high), also outside the
// range (a wire break at 0 mA reads below the value at 4 mA).
void readAnalogue(const DecodedInstruction* operands, AnalogueRange range) {
    const std::int64_t measured = operands[0].readWord();
    const std::int64_t atLow = valueOf(operands[1]);
    const std::int64_t atHigh = valueOf(operands[2]);
    operands[3].writeBit(range.low <= measured && measured <= range.high);
    store(operands[4], measured);
    store(operands[5],
          atLow + scaled(measured - range.low, atHigh - atLow, range.high - range.low));
}

// A counter input of a D45 counts up to 14000 Hz (manual Part 1, 9).
constexpr std::int64_t kHighestCountedFrequency = 14'000;

// HS_SpeedCount_Up, HS_SpeedCount_Dir (manual Part 1, 9): the input's value
// is its pulse frequency in Hz, signed for an up/down counter (negative
// counting down); Valid says the counter counts it. PulsePerSec is the
// frequency and EdgePer10ms the same speed per 10 ms, to the nearest integer
// with a half away from zero, so that the opposite direction reads the
// opposite value. Of an up/down pair only Input_A is read: the simulator
// gives an encoder's speed to its first channel.
void countSpeed(const DecodedInstruction& input, const DecodedInstruction* outputs,
                std::int64_t lowest) {
    const std::int64_t hertz = input.readWord();
    outputs[0].writeBit(lowest <= hertz && hertz <= kHighestCountedFrequency);
    const std::int64_t magnitude = (hertz < 0 ? -hertz : hertz) + 50;
    store(outputs[1], hertz < 0 ? -(magnitude / 100) : magnitude / 100);
    store(outputs[2], hertz);
}

} // namespace

void runSystemCall(UnitState& unit, const DecodedInstruction& call) {
    const DecodedInstruction* operands = &call + 1;
    switch (static_cast<SystemInstructionId>(call.aux)) {
    case SystemInstructionId::RegisterValid:
    case SystemInstructionId::DRegisterValid:
        registerValid(unit, operands);
        return;
    case SystemInstructionId::ReadVoltage:
    case SystemInstructionId::ReadVoltage32:
        readAnalogue(operands, kVoltageRange);
        return;
    case SystemInstructionId::ReadCurrent:
    case SystemInstructionId::ReadCurrent32:
        readAnalogue(operands, kCurrentRange);
        return;
    case SystemInstructionId::HSSpeedCountUp:
        countSpeed(operands[0], operands + 1, 0);
        return;
    case SystemInstructionId::HSSpeedCountDir:
        countSpeed(operands[0], operands + 2, -kHighestCountedFrequency);
        return;
    }
}

} // namespace rs::sim::engine
