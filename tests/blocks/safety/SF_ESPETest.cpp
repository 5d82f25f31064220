// SPDX-License-Identifier: GPL-3.0-or-later
#include "StopBlockTest.h"

using rs::safetytest::StopBlock;
using rs::safetytest::StopBlockTest;

// SF_ESPE of Rungsmith_Safety: the scenarios of StopBlockScenarios.cpp, the
// public model's SF_ESPE being SF_EmergencyStop with other pin names.
INSTANTIATE_TEST_SUITE_P(SF_ESPE, StopBlockTest,
                         ::testing::Values(StopBlock{"SF_ESPE", "S_ESPE_In", "S_ESPE_Out"}));
