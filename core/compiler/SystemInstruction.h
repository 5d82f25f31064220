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
    // The gateway blocks (Gateway manual 4.3.3, 4.5.3; docs/gateway.md).
    ToGatewayUserA = 9,
    ToGatewayUserB = 10,
    ToGatewayUserC = 11,
    ToGatewayErrorCode = 12,
    ToGatewayB46 = 13,
    ToGatewayAsi16To31Safe = 14,
    ToGatewayAsi1To3NonSafe = 15,
    ToGatewayAsi4To7NonSafe = 16,
    ToGatewayAsi8To11NonSafe = 17,
    ToGatewayAsi12To15NonSafe = 18,
    ToGatewayAsi16To19NonSafe = 19,
    ToGatewayAsi20To23NonSafe = 20,
    ToGatewayAsi24To27NonSafe = 21,
    ToGatewayAsi28To31NonSafe = 22,
    ToGatewayB42Asi = 23,
    ToGatewayAsi1To15Safe = 24,
    ExtSig = 25,
    ExtVal = 26,
    ExtVarBlock = 27,
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
// The ToGateway blocks (Gateway manual 4.3.3): each sends one telegram of
// 32 bits while Send is 1, and Q says it went. A user block's No (1-99) is
// its IO-type, a number in the call; the manual's figures of the pins were
// lost, so the names below are Rungsmith's (docs/gateway.md).
inline constexpr SystemParameter kToGatewayUserA[] = {
    {"No", ParameterDirection::In, ParameterKind::Register, true},
    {"Send", ParameterDirection::In, ParameterKind::Bit},
    {"Reg_0", ParameterDirection::In, ParameterKind::Register, true},
    {"Reg_1", ParameterDirection::In, ParameterKind::Register, true},
    {"Q", ParameterDirection::Out, ParameterKind::Bit},
};
inline constexpr SystemParameter kToGatewayUserB[] = {
    {"No", ParameterDirection::In, ParameterKind::Register, true},
    {"Send", ParameterDirection::In, ParameterKind::Bit},
    {"Reg_0", ParameterDirection::In, ParameterKind::Register, true},
    {"Bit_0", ParameterDirection::In, ParameterKind::Bit},
    {"Bit_1", ParameterDirection::In, ParameterKind::Bit},
    {"Bit_2", ParameterDirection::In, ParameterKind::Bit},
    {"Bit_3", ParameterDirection::In, ParameterKind::Bit},
    {"Bit_4", ParameterDirection::In, ParameterKind::Bit},
    {"Bit_5", ParameterDirection::In, ParameterKind::Bit},
    {"Bit_6", ParameterDirection::In, ParameterKind::Bit},
    {"Bit_7", ParameterDirection::In, ParameterKind::Bit},
    {"Q", ParameterDirection::Out, ParameterKind::Bit},
};
inline constexpr SystemParameter kToGatewayUserC[] = {
    {"No", ParameterDirection::In, ParameterKind::Register, true},
    {"Send", ParameterDirection::In, ParameterKind::Bit},
    {"Reg_0", ParameterDirection::In, ParameterKind::Register, true},
    {"Bit_0", ParameterDirection::In, ParameterKind::Bit},
    {"Bit_1", ParameterDirection::In, ParameterKind::Bit},
    {"Bit_2", ParameterDirection::In, ParameterKind::Bit},
    {"Bit_3", ParameterDirection::In, ParameterKind::Bit},
    {"Bit_4", ParameterDirection::In, ParameterKind::Bit},
    {"Bit_5", ParameterDirection::In, ParameterKind::Bit},
    {"Bit_6", ParameterDirection::In, ParameterKind::Bit},
    {"Bit_7", ParameterDirection::In, ParameterKind::Bit},
    {"Bit_8", ParameterDirection::In, ParameterKind::Bit},
    {"Bit_9", ParameterDirection::In, ParameterKind::Bit},
    {"Bit_10", ParameterDirection::In, ParameterKind::Bit},
    {"Bit_11", ParameterDirection::In, ParameterKind::Bit},
    {"Bit_12", ParameterDirection::In, ParameterKind::Bit},
    {"Bit_13", ParameterDirection::In, ParameterKind::Bit},
    {"Bit_14", ParameterDirection::In, ParameterKind::Bit},
    {"Bit_15", ParameterDirection::In, ParameterKind::Bit},
    {"Q", ParameterDirection::Out, ParameterKind::Bit},
};
// A standard block's data is fixed by its IO-type: it reads the unit itself.
inline constexpr SystemParameter kToGatewayStandard[] = {
    {"Send", ParameterDirection::In, ParameterKind::Bit},
    {"Q", ParameterDirection::Out, ParameterKind::Bit},
};
// Ext_Sig, Ext_Val, ExtVarBlock (Gateway manual 4.5.3): the data of one
// External Comm Block (BlockNo 0-3, a number), Valid while it is received.
inline constexpr SystemParameter kExtSig[] = {
    {"BlockNo", ParameterDirection::In, ParameterKind::Register, true},
    {"Valid", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_0", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_1", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_2", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_3", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_4", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_5", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_6", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_7", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_8", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_9", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_10", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_11", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_12", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_13", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_14", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_15", ParameterDirection::Out, ParameterKind::Bit},
};
inline constexpr SystemParameter kExtVal[] = {
    {"BlockNo", ParameterDirection::In, ParameterKind::Register, true},
    {"Valid", ParameterDirection::Out, ParameterKind::Bit},
    {"Reg_0", ParameterDirection::Out, ParameterKind::Register},
    {"Reg_1", ParameterDirection::Out, ParameterKind::Register},
};
inline constexpr SystemParameter kExtVarBlock[] = {
    {"BlockNo", ParameterDirection::In, ParameterKind::Register, true},
    {"Valid", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_0", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_1", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_2", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_3", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_4", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_5", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_6", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_7", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_8", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_9", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_10", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_11", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_12", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_13", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_14", ParameterDirection::Out, ParameterKind::Bit},
    {"Bit_15", ParameterDirection::Out, ParameterKind::Bit},
    {"Reg_0", ParameterDirection::Out, ParameterKind::Register},
    {"Reg_1", ParameterDirection::Out, ParameterKind::Register},
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
    {SystemInstructionId::ToGatewayUserA, "ToGateway_User_A", parameters::kToGatewayUserA},
    {SystemInstructionId::ToGatewayUserB, "ToGateway_User_B", parameters::kToGatewayUserB},
    {SystemInstructionId::ToGatewayUserC, "ToGateway_User_C", parameters::kToGatewayUserC},
    {SystemInstructionId::ToGatewayErrorCode, "ToGateway_ErrorCode",
     parameters::kToGatewayStandard},
    {SystemInstructionId::ToGatewayB46, "ToGateway_B46_I20_I47", parameters::kToGatewayStandard},
    {SystemInstructionId::ToGatewayAsi16To31Safe, "ToGateway_ASi_16_31_Safe",
     parameters::kToGatewayStandard},
    {SystemInstructionId::ToGatewayAsi1To3NonSafe, "ToGateway_ASi_1_3_NonSafe_In",
     parameters::kToGatewayStandard},
    {SystemInstructionId::ToGatewayAsi4To7NonSafe, "ToGateway_ASi_4_7_NonSafe_In",
     parameters::kToGatewayStandard},
    {SystemInstructionId::ToGatewayAsi8To11NonSafe, "ToGateway_ASi_8_11_NonSafe_In",
     parameters::kToGatewayStandard},
    {SystemInstructionId::ToGatewayAsi12To15NonSafe, "ToGateway_ASi_12_15_NonSafe_In",
     parameters::kToGatewayStandard},
    {SystemInstructionId::ToGatewayAsi16To19NonSafe, "ToGateway_ASi_16_19_NonSafe_In",
     parameters::kToGatewayStandard},
    {SystemInstructionId::ToGatewayAsi20To23NonSafe, "ToGateway_ASi_20_23_NonSafe_In",
     parameters::kToGatewayStandard},
    {SystemInstructionId::ToGatewayAsi24To27NonSafe, "ToGateway_ASi_24_27_NonSafe_In",
     parameters::kToGatewayStandard},
    {SystemInstructionId::ToGatewayAsi28To31NonSafe, "ToGateway_ASi_28_31_NonSafe_In",
     parameters::kToGatewayStandard},
    {SystemInstructionId::ToGatewayB42Asi, "ToGateway_B42_ASi_I20_I47",
     parameters::kToGatewayStandard},
    {SystemInstructionId::ToGatewayAsi1To15Safe, "ToGateway_ASi_1_15_Safe",
     parameters::kToGatewayStandard},
    {SystemInstructionId::ExtSig, "Ext_Sig", parameters::kExtSig},
    {SystemInstructionId::ExtVal, "Ext_Val", parameters::kExtVal},
    {SystemInstructionId::ExtVarBlock, "ExtVarBlock", parameters::kExtVarBlock},
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

// The IO-type a standard ToGateway block's telegram carries (100-113), 0 for
// a user block (its No is its IO-type) and every other instruction.
int standardIoType(SystemInstructionId id);
bool isToGateway(SystemInstructionId id);

// What to tell a user who named an unknown instruction: those whose names
// begin as `unknown` does ("did you mean ReadVoltage, ReadCurrent?"), else
// where the list is.
std::string systemInstructionHint(std::string_view unknown);

} // namespace rs::compiler
