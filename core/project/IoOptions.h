// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Project.h"
#include "target/UnitType.h"

#include <optional>
#include <string>
#include <vector>

// The I/O Options page as data (manual Part 1, 3.7 and 6; Part 2, 5.3): which
// terminals a unit type has, what each can be set to, and the I/O declaration
// a setting is written as. Only the choices offered here can be made, and
// every one of them is a declaration the compiler's unit setup accepts.
namespace rs::project {

enum class TerminalKind {
    Input,        // a failsafe input only: I0.0..I0.7 on an A20
    Configurable, // input, output or illuminated push button: I/Q/IQ0.10..17
    Analogue,     // D20, D45: IA terminals, ordinary inputs or analogue or counter values
    SafetyOutput, // Q2, Q3 of the types whose test pulses can be disabled
};

// "Type of signal".
enum class SignalType {
    Undefined, // no declaration
    Input,
    Output,
    LightButton, // illuminated push button, IQ
    Voltage,     // analogue 0-10 V
    Current,     // analogue 4-20 mA
    CounterUp,
    CounterUpDown,
};

// "Signal shape": static, or the dynamic signals A, B and C.
enum class SignalShape { None, Static, APulse, BPulse, CPulse };

struct Terminal {
    TerminalKind kind = TerminalKind::Input;
    int station = 0;
    int number = 0; // the terminal's number: 12 for I0.12, Q0.12 and IQ0.12

    // As the page lists it: "I0.3", "IQ0.12", "IA0.1", "Q0.2".
    std::string label() const;
    friend bool operator==(const Terminal&, const Terminal&) = default;
};

struct TerminalSetting {
    SignalType type = SignalType::Undefined;
    SignalShape shape = SignalShape::None;
    bool nonInverted = false; // non_inv
    bool noFilter = false;    // no_filt
    bool crossTalk = false;   // x_talk
    bool noTestPulse = false; // no_test_pulse, Q2 and Q3 only

    friend bool operator==(const TerminalSetting&, const TerminalSetting&) = default;
};

enum class TerminalOption { NonInverted, NoFilter, CrossTalk, NoTestPulse };

// The unit type's terminals in page order: inputs, configurable terminals,
// analogue inputs, then the safety outputs with the test-pulse option.
std::vector<Terminal> terminalsOf(const target::UnitTypeInfo& type, int station);

// The choices of each column for a terminal, given what is chosen to its left.
std::vector<SignalType> signalTypes(const target::UnitTypeInfo& type, const Terminal& terminal);
std::vector<SignalShape> signalShapes(const Terminal& terminal, SignalType signal);
std::vector<TerminalOption> terminalOptions(const target::UnitTypeInfo& type,
                                            const Terminal& terminal,
                                            const TerminalSetting& setting);

// The nearest setting the choices allow: an unknown type becomes Undefined, a
// shape missing for the type becomes the first offered, options not offered
// are cleared.
TerminalSetting legalSetting(const target::UnitTypeInfo& type, const Terminal& terminal,
                             TerminalSetting setting);

// The declaration for a setting, nothing for Undefined ("! I0.5,c_pulse,non_inv").
std::optional<lang::IoDeclaration> ioDeclaration(const Terminal& terminal,
                                                 const TerminalSetting& setting);

// What the unit's code declares for the terminal; Undefined without a declaration.
TerminalSetting terminalSetting(const Project& project, const Terminal& terminal);

// Writes the setting as the terminal's declaration in its unit's code: an
// existing one is replaced in place (its comment stays), a new one goes among
// the I/O declarations in terminal order, Undefined removes it. The setting is
// made legal first; returns the setting written.
TerminalSetting setTerminalSetting(Project& project, const Terminal& terminal,
                                   const TerminalSetting& setting);

// The terminal an I/O declaration is about, if the type has it.
std::optional<Terminal> terminalOf(const target::UnitTypeInfo& type,
                                   const lang::IoDeclaration& declaration);

// A setting read back from a declaration's words.
TerminalSetting settingOf(const Terminal& terminal, const lang::IoDeclaration& declaration);

} // namespace rs::project
