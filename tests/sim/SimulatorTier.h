// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

namespace rs::test {

// The three ways the simulator runs a unit's code: the machine code, the
// unmarked interpreter and the marking interpreter.
enum class SimulatorTier { MachineCode, Interpreter, MarkingInterpreter };

// The environment variable that rules the machine code out
// (RUNGSMITH_NO_JIT, docs/simulator.md), for as long as the setting lives,
// and as it was afterwards.
class MachineCodeSetting {
public:
    explicit MachineCodeSetting(bool on) {
        if (const char* before = std::getenv("RUNGSMITH_NO_JIT"))
            m_before = before;
        if (on)
            unsetenv("RUNGSMITH_NO_JIT");
        else
            setenv("RUNGSMITH_NO_JIT", "1", 1);
    }
    ~MachineCodeSetting() {
        if (m_before)
            setenv("RUNGSMITH_NO_JIT", m_before->c_str(), 1);
        else
            unsetenv("RUNGSMITH_NO_JIT");
    }
    MachineCodeSetting(const MachineCodeSetting&) = delete;
    MachineCodeSetting& operator=(const MachineCodeSetting&) = delete;

private:
    std::optional<std::string> m_before;
};

// Test names for INSTANTIATE_TEST_SUITE_P over every tier.
inline std::string tierName(const testing::TestParamInfo<SimulatorTier>& info) {
    switch (info.param) {
    case SimulatorTier::MachineCode:
        return "MachineCode";
    case SimulatorTier::Interpreter:
        return "Interpreter";
    case SimulatorTier::MarkingInterpreter:
        return "MarkingInterpreter";
    }
    return "";
}

inline const auto kEveryTier = testing::Values(
    SimulatorTier::MachineCode, SimulatorTier::Interpreter, SimulatorTier::MarkingInterpreter);

} // namespace rs::test
