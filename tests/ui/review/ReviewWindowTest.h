// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "WindowTest.h"

// A main window with the press-line example open, for the review features:
// marking it as validated and changing one unit after.
class ReviewWindowTest : public WindowTest {
protected:
    void SetUp() override;

    // Project > Mark as Validated, by "A. Reviewer"; returns the baseline's date.
    QString markValidated();
    // Unit 01's second network changed (Q1.3 = /Q1.2) and a third one added (M1.0 = I1.1).
    void changeUnitOne();
};
