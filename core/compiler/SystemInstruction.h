// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Image.h"

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
};

enum class ParameterDirection : std::uint8_t { In, Out };

// What an operand of a system instruction holds: a bit, a 16-bit word (R,
// a half of a DR, SR) or a double register.
enum class ParameterKind : std::uint8_t { Bit, Register, DoubleRegister };

struct SystemParameter {
    std::string_view name;
    ParameterDirection direction = ParameterDirection::In;
    ParameterKind kind = ParameterKind::Bit;
    bool takesNumber = false; // an input that may be a decimal number instead of a variable
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
} // namespace parameters

inline constexpr SystemInstruction kSystemInstructions[] = {
    {SystemInstructionId::RegisterValid, "RegisterValid", parameters::kRegisterValid},
    {SystemInstructionId::DRegisterValid, "DRegisterValid", parameters::kDRegisterValid},
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
