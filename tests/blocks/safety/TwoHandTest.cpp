// SPDX-License-Identifier: GPL-3.0-or-later
#include "TwoHandTest.h"

#include "SafetyBench.h"

namespace rs::safetytest {

::testing::AssertionResult twoHandHolds(const std::string& block, const std::string& bindings,
                                        const std::string& scenario) {
    const std::string names = "! I0.0=Act\n! I0.1=Button1\n! I0.2=Button2\n! M0.0=Ready\n"
                              "! M0.1=Out\n! M0.2=Error\n! R0.0=DiagCode\n";
    const std::string record = ";@block " + block +
                               " S_Button1=\"Button1\" S_Button2=\"Button2\" Ready=\"Ready\" "
                               "S_TwoHandOut=\"Out\" Error=\"Error\" DiagCode=\"DiagCode\" " +
                               bindings + "\n;@end\n";
    return holdsOnBothInstructionSets(names, record, scenario);
}

} // namespace rs::safetytest
