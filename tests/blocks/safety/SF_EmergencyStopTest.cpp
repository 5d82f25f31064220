// SPDX-License-Identifier: GPL-3.0-or-later
#include "StopBlockTest.h"

using rs::safetytest::StopBlock;
using rs::safetytest::StopBlockTest;

// SF_EmergencyStop of Rungsmith_Safety: the scenarios of StopBlockScenarios.cpp.
INSTANTIATE_TEST_SUITE_P(SF_EmergencyStop, StopBlockTest,
                         ::testing::Values(StopBlock{"SF_EmergencyStop", "S_EStopIn",
                                                     "S_EStopOut"}));
