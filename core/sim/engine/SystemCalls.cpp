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

constexpr std::size_t kErrorCode = 11; // SR_ErrorCode, the unit's error code

std::uint32_t byteAt(std::uint32_t value, int byte) {
    return (value & 0xFFu) << (8 * byte);
}

// Eight bits from the unit's inputs, I<first> to I<first + 7>.
std::uint32_t inputByte(const UnitMemory& memory, int first) {
    std::uint32_t bits = 0;
    for (int i = 0; i < 8; ++i)
        bits |= (memory.inputs[static_cast<std::size_t>(first + i)] ? 1u : 0u) << i;
    return bits;
}

// Slave `slave`'s inputs: .1-.4 of the A (or standard) slave in the low
// nibble, those of its B slave in the high one (4.3.3.2, IO-types 103-110).
std::uint32_t asiSlaveByte(const UnitMemory& memory, int slave) {
    std::uint32_t bits = 0;
    for (int i = 0; i < 4; ++i) {
        bits |=
            (memory.asiInputs[static_cast<std::size_t>(slave)][static_cast<std::size_t>(i)] ? 1u
                                                                                            : 0u)
            << i;
        bits |= (memory.asiInputs[static_cast<std::size_t>(slave + 32)][static_cast<std::size_t>(i)]
                     ? 1u
                     : 0u)
                << (4 + i);
    }
    return bits;
}

// Eight safety slaves' inputs, ASI<first> to ASI<first + 7>.
std::uint32_t safeSlaveByte(const UnitMemory& memory, int first) {
    std::uint32_t bits = 0;
    for (int i = 0; i < 8; ++i)
        bits |= (memory.asiSafeInputs[static_cast<std::size_t>(first + i)] ? 1u : 0u) << i;
    return bits;
}

// The 32 bits a standard block sends, in the layout of its IO-type (Gateway
// manual 4.3.3.2); the bits the manual leaves undefined are 0.
std::uint32_t standardData(const UnitMemory& memory, int ioType) {
    const std::uint32_t error =
        byteAt(static_cast<std::uint32_t>(memory.systemRegisters[kErrorCode]), 3);
    const auto in = [&](int terminal) {
        return memory.inputs[static_cast<std::size_t>(terminal)] ? 1u : 0u;
    };
    switch (ioType) {
    case 100:
        return error;
    case 101:
    case 112:
        return inputByte(memory, 20) | inputByte(memory, 30) << 8 | inputByte(memory, 40) << 16 |
               error;
    case 102:
        return (in(1) << 1 | in(2) << 2 | in(3) << 3 | ((inputByte(memory, 10) << 4) & 0xF0u)) |
               safeSlaveByte(memory, 16) << 8 | safeSlaveByte(memory, 24) << 16 | error;
    case 113:
        return inputByte(memory, 10) | (safeSlaveByte(memory, 0) & 0xFEu) << 8 |
               safeSlaveByte(memory, 8) << 16 | error;
    default: { // 103-110: four slaves a byte, from slave 4 * (type - 103), slave 0 undefined
        const int first = 4 * (ioType - 103);
        std::uint32_t data = 0;
        for (int byte = 0; byte < 4; ++byte)
            if (first + byte > 0)
                data |= asiSlaveByte(memory, first + byte) << (8 * byte);
        return data;
    }
    }
}

// A ToGateway block: while Send is 1 it sends its telegram, one per scan (a
// scan is at least 10 ms), and Q says it went; a unit sends at most four a
// scan, so a fifth block's Send that scan is not sent and its Q stays 0.
void toGateway(UnitState& unit, const DecodedInstruction* operands,
               compiler::SystemInstructionId id) {
    const bool user = compiler::standardIoType(id) == 0;
    const DecodedInstruction* send = user ? operands + 1 : operands;
    const DecodedInstruction& q =
        operands[compiler::findSystemInstruction(static_cast<std::uint8_t>(id))->parameters.size() -
                 1];
    if (!send->readBit() || unit.telegrams.size() >= kTelegramsPerScan) {
        q.writeBit(false);
        return;
    }
    GatewayTelegram telegram;
    if (!user) {
        telegram.ioType = compiler::standardIoType(id);
        telegram.data = standardData(unit.memory, telegram.ioType);
    } else {
        telegram.ioType = static_cast<int>(valueOf(operands[0]));
        const auto reg0 = static_cast<std::uint16_t>(valueOf(operands[2]));
        std::uint32_t high = 0; // bytes 2 and 3
        if (id == compiler::SystemInstructionId::ToGatewayUserA) {
            high = static_cast<std::uint16_t>(valueOf(operands[3]));
        } else {
            const int bits = id == compiler::SystemInstructionId::ToGatewayUserB ? 8 : 16;
            for (int i = 0; i < bits; ++i)
                high |= (operands[3 + i].readBit() ? 1u : 0u) << i;
            if (bits == 8)
                high |=
                    (static_cast<std::uint32_t>(unit.memory.systemRegisters[kErrorCode]) & 0xFFu)
                    << 8;
        }
        telegram.data = reg0 | high << 16;
    }
    unit.telegrams.push_back(telegram);
    q.writeBit(true);
}

// Ext_Sig, Ext_Val, ExtVarBlock: External Comm Block BlockNo's validity, then
// its bits (Ext_Sig, ExtVarBlock) and registers (Ext_Val, ExtVarBlock). A
// BlockNo outside 0-3 reads as a block never received.
void externalData(UnitState& unit, const DecodedInstruction* operands, bool bits, bool registers) {
    const std::int64_t number = valueOf(operands[0]);
    const bool known = number >= 0 && number < UnitMemory::kExternalBlocks;
    const auto block = static_cast<std::size_t>(known ? number : 0);
    const UnitMemory& memory = unit.memory;
    operands[1].writeBit(known && memory.externalValid[block]);
    const DecodedInstruction* next = operands + 2;
    if (bits) {
        const std::uint16_t word = known ? memory.externalBits[block] : 0;
        for (int i = 0; i < 16; ++i)
            (next++)->writeBit((word >> i) & 1u);
    }
    if (registers)
        for (std::size_t r = 0; r < 2; ++r)
            store(*next++, known ? memory.externalRegisters[2 * block + r] : 0);
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
    case SystemInstructionId::ExtSig:
        externalData(unit, operands, true, false);
        return;
    case SystemInstructionId::ExtVal:
        externalData(unit, operands, false, true);
        return;
    case SystemInstructionId::ExtVarBlock:
        externalData(unit, operands, true, true);
        return;
    default:
        toGateway(unit, operands, static_cast<SystemInstructionId>(call.aux));
        return;
    }
}

} // namespace rs::sim::engine
