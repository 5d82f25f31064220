// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Image.h"
#include "lang/Keywords.h"

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

// The system instructions of Rungsmith's image (docs/image-format.md,
// "System instructions"): what a system block's expansion calls for what the
// language cannot say (blocks.md). This table is what the compiler knows of
// them; what each does is the simulator's (core/sim/engine/SystemCalls.cpp).
// A new one is an id here, a row of kSystemInstructions and a case there.
namespace rs::compiler {

enum class SystemInstructionId : std::uint8_t {
    RegisterValid = 1,
    DRegisterValid = 2,
    ReadVoltage = 3,
    ReadCurrent = 4,
    ReadVoltage32 = 5,
    ReadCurrent32 = 6,
    HSSpeedCountUp = 7,
    HSSpeedCountDir = 8,
};

enum class ParameterDirection : std::uint8_t { In, Out };

// What an operand of a system instruction holds: a bit, a 16-bit word (R,
// a half of a DR, SR), a double register, or an analogue input (IA) read as
// its value.
enum class ParameterKind : std::uint8_t { Bit, Register, DoubleRegister, AnalogInput };

struct SystemParameter {
    std::string_view name;
    ParameterDirection direction = ParameterDirection::In;
    ParameterKind kind = ParameterKind::Bit;
    bool takesNumber = false; // an input that may be a decimal number instead of a variable
    // An analogue input: the I/O option it must be declared with ("voltage",
    // "current", "counter_up", "counter_updown"), for the value is in that
    // option's unit (mV, µA, Hz).
    std::string_view analogueOption = {};
};

struct SystemInstruction {
    SystemInstructionId id;
    std::string_view name;
    std::span<const SystemParameter>
        parameters; // in the order of the image's Argument instructions
};

namespace parameters {
inline constexpr SystemParameter kRegisterValid[] = {
    {"Input", ParameterDirection::In, ParameterKind::Register},
    {"Valid", ParameterDirection::Out, ParameterKind::Bit},
    {"Value", ParameterDirection::Out, ParameterKind::Register},
};
inline constexpr SystemParameter kDRegisterValid[] = {
    {"Input", ParameterDirection::In, ParameterKind::DoubleRegister},
    {"Valid", ParameterDirection::Out, ParameterKind::Bit},
    {"Value", ParameterDirection::Out, ParameterKind::DoubleRegister},
};
// ReadVoltage, ReadCurrent (manual Part 1, 8): the manual's pin names,
// with '_' for its spaces. The _32 forms take double registers throughout.
inline constexpr SystemParameter kReadVoltage[] = {
    {"Input", ParameterDirection::In, ParameterKind::AnalogInput, false, lang::kVoltageOption},
    {"Value_0V", ParameterDirection::In, ParameterKind::Register, true},
    {"Value_10V", ParameterDirection::In, ParameterKind::Register, true},
    {"Q", ParameterDirection::Out, ParameterKind::Bit},
    {"Voltage", ParameterDirection::Out, ParameterKind::Register},
    {"Scaled_Value", ParameterDirection::Out, ParameterKind::Register},
};
inline constexpr SystemParameter kReadCurrent[] = {
    {"Input", ParameterDirection::In, ParameterKind::AnalogInput, false, lang::kCurrentOption},
    {"Value_4mA", ParameterDirection::In, ParameterKind::Register, true},
    {"Value_20mA", ParameterDirection::In, ParameterKind::Register, true},
    {"Q", ParameterDirection::Out, ParameterKind::Bit},
    {"Current", ParameterDirection::Out, ParameterKind::Register},
    {"Scaled_Value", ParameterDirection::Out, ParameterKind::Register},
};
inline constexpr SystemParameter kReadVoltage32[] = {
    {"Input", ParameterDirection::In, ParameterKind::AnalogInput, false, lang::kVoltageOption},
    {"Value_0V", ParameterDirection::In, ParameterKind::DoubleRegister, true},
    {"Value_10V", ParameterDirection::In, ParameterKind::DoubleRegister, true},
    {"Q", ParameterDirection::Out, ParameterKind::Bit},
    {"Voltage", ParameterDirection::Out, ParameterKind::DoubleRegister},
    {"Scaled_Value", ParameterDirection::Out, ParameterKind::DoubleRegister},
};
inline constexpr SystemParameter kReadCurrent32[] = {
    {"Input", ParameterDirection::In, ParameterKind::AnalogInput, false, lang::kCurrentOption},
    {"Value_4mA", ParameterDirection::In, ParameterKind::DoubleRegister, true},
    {"Value_20mA", ParameterDirection::In, ParameterKind::DoubleRegister, true},
    {"Q", ParameterDirection::Out, ParameterKind::Bit},
    {"Current", ParameterDirection::Out, ParameterKind::DoubleRegister},
    {"Scaled_Value", ParameterDirection::Out, ParameterKind::DoubleRegister},
};
// HS_SpeedCount_Up, HS_SpeedCount_Dir (manual Part 1, 9): the manual's pin
// names; its speeds "shall be connected to a register (R)".
inline constexpr SystemParameter kHSSpeedCountUp[] = {
    {"Input", ParameterDirection::In, ParameterKind::AnalogInput, false, lang::kCounterUpOption},
    {"Valid", ParameterDirection::Out, ParameterKind::Bit},
    {"EdgePer10ms", ParameterDirection::Out, ParameterKind::Register},
    {"PulsePerSec", ParameterDirection::Out, ParameterKind::Register},
};
inline constexpr SystemParameter kHSSpeedCountDir[] = {
    {"Input_A", ParameterDirection::In, ParameterKind::AnalogInput, false,
     lang::kCounterUpDownOption},
    {"Input_B", ParameterDirection::In, ParameterKind::AnalogInput, false,
     lang::kCounterUpDownOption},
    {"Valid", ParameterDirection::Out, ParameterKind::Bit},
    {"EdgePer10ms", ParameterDirection::Out, ParameterKind::Register},
    {"PulsePerSec", ParameterDirection::Out, ParameterKind::Register},
};
} // namespace parameters

inline constexpr SystemInstruction kSystemInstructions[] = {
    {SystemInstructionId::RegisterValid, "RegisterValid", parameters::kRegisterValid},
    {SystemInstructionId::DRegisterValid, "DRegisterValid", parameters::kDRegisterValid},
    {SystemInstructionId::ReadVoltage, "ReadVoltage", parameters::kReadVoltage},
    {SystemInstructionId::ReadCurrent, "ReadCurrent", parameters::kReadCurrent},
    {SystemInstructionId::ReadVoltage32, "ReadVoltage_32", parameters::kReadVoltage32},
    {SystemInstructionId::ReadCurrent32, "ReadCurrent_32", parameters::kReadCurrent32},
    {SystemInstructionId::HSSpeedCountUp, "HS_SpeedCount_Up", parameters::kHSSpeedCountUp},
    {SystemInstructionId::HSSpeedCountDir, "HS_SpeedCount_Dir", parameters::kHSSpeedCountDir},
};

// By name, without regard to case (as block and pin names); null when unknown.
const SystemInstruction* findSystemInstruction(std::string_view name);
// By the id an image holds; null when unknown.
const SystemInstruction* findSystemInstruction(std::uint8_t id);
// The parameter of that name, without regard to case; null when it has none.
const SystemParameter* findParameter(const SystemInstruction& instruction, std::string_view name);

// The aux of the Argument instruction that carries an operand for `parameter`.
constexpr std::uint8_t argumentRole(const SystemParameter& parameter) {
    return static_cast<std::uint8_t>(
        (parameter.direction == ParameterDirection::Out ? ArgumentWritten : 0) |
        (parameter.kind == ParameterKind::Bit ? 0 : ArgumentWord));
}

// "RegisterValid, DRegisterValid": for messages.
std::string systemInstructionNames();

} // namespace rs::compiler
