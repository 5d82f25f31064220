// SPDX-License-Identifier: GPL-3.0-or-later
#include "ReviewWindowTest.h"

#include "DialogDriver.h"
#include "document/ProjectDocument.h"
#include "project/UnitText.h"

#include <QAction>
#include <QDialog>
#include <QLineEdit>

void ReviewWindowTest::SetUp() {
    WindowTest::SetUp();
    ASSERT_TRUE(
        window.loadFile(QStringLiteral(RUNGSMITH_SOURCE_DIR "/resources/examples/press-line.sps"))
            .isEmpty());
    showWindow();
}

QString ReviewWindowTest::markValidated() {
    DialogDriver driver({[](QDialog& dialog) {
        dialog.findChild<QLineEdit*>(QStringLiteral("validatedBy"))
            ->setText(QStringLiteral("A. Reviewer"));
        dialog.accept();
    }});
    action("markValidatedAction")->trigger();
    EXPECT_TRUE(driver.done());
    const auto& baseline = document()->project().baseline;
    EXPECT_TRUE(baseline.has_value());
    return baseline ? QString::fromStdString(baseline->date) : QString();
}

void ReviewWindowTest::changeUnitOne() {
    rs::project::Project edited = document()->project();
    std::string code = rs::project::unitText(edited, 1);
    const std::string::size_type at = code.find("Q1.3 = Q1.2");
    ASSERT_NE(at, std::string::npos) << code;
    code.replace(at, 11, "Q1.3 = /Q1.2");
    const auto read = rs::project::readUnitText(edited, 1, code + "M1.0 = I1.1\n");
    ASSERT_TRUE(read.ok());
    document()->replace(QStringLiteral("typing"), read.project);
}
