// SPDX-License-Identifier: GPL-3.0-or-later
#include "StopBlockTest.h"

#include "SafetyBench.h"

namespace rs::safetytest {

::testing::AssertionResult StopBlockTest::holds(const std::string& bindings,
                                                const std::string& scenario) const {
    const StopBlock& block = GetParam();
    const std::string names = "! I0.0=Act\n! I0.1=SafeIn\n! I0.2=StartReset\n! I0.3=AutoReset\n"
                              "! I0.4=ResetButton\n! M0.0=Ready\n! M0.1=Out\n! M0.2=Error\n"
                              "! R0.0=DiagCode\n";
    const std::string record =
        ";@block " + block.name + " " + block.input + "=\"SafeIn\" " + block.output +
        "=\"Out\" Ready=\"Ready\" Error=\"Error\" DiagCode=\"DiagCode\" " + bindings + "\n;@end\n";
    return holdsOnBothInstructionSets(names, record, scenario);
}

} // namespace rs::safetytest
