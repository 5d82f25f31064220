// SPDX-License-Identifier: GPL-3.0-or-later
// A block's documentation page, reached as a user reaches it: from a block
// network on the ladder page and from the description in the block chooser.
#include "WindowTest.h"

#include "DialogDriver.h"
#include "document/ProjectDocument.h"
#include "ladder/BlockDocumentation.h"
#include "ladder/BlockDocumentationDialog.h"
#include "ladder/LadderPage.h"
#include "ladder/LadderView.h"
#include "shell/PageRef.h"

#include <QAction>
#include <QApplication>
#include <QLineEdit>
#include <QPushButton>
#include <QTest>
#include <QTextBrowser>

#include <gtest/gtest.h>

namespace {

using rs::ui::BlockDocumentationDialog;
using rs::ui::LadderPage;
using rs::ui::PageRef;

const QByteArray kStop = "! id_pluto:00=000000000000\n"
                         "! type_pluto:00=A20,is3\n"
                         "! I0.0=EStop\n"
                         "! I0.1=ResetButton\n"
                         "! pgm_pluto:00\n"
                         "S0.0_0\n"
                         ";@block SF_EmergencyStop S_EStopIn=\"EStop\" Reset=\"ResetButton\" "
                         "S_EStopOut=\"Q0.2\"\n"
                         ";@end\n";

BlockDocumentationDialog* openDocumentation() {
    for (QWidget* widget : QApplication::topLevelWidgets())
        if (auto* dialog = qobject_cast<BlockDocumentationDialog*>(widget);
            dialog && dialog->isVisible())
            return dialog;
    return nullptr;
}

class BlockDocumentationTest : public WindowTest {
protected:
    LadderPage& page() { return *window.ladderPage(); }

    void openLadder() {
        ASSERT_TRUE(window.loadFile(writeFile(QStringLiteral("stop.sps"), kStop)).isEmpty());
        showWindow();
        clickNode({PageRef::Kind::Ladder, document(), 0, 0});
        page().view()->setFocus();
    }
};

TEST_F(BlockDocumentationTest, ABlockNetworkOpensItsBlocksPageWithStatesAndATimingDiagram) {
    openLadder();
    page().setCursor({0, 0, std::nullopt, std::nullopt, -1});
    auto* action = page().findChild<QAction*>(QStringLiteral("blockDocumentationAction"));
    ASSERT_NE(action, nullptr);
    action->trigger();
    BlockDocumentationDialog* dialog = openDocumentation();
    ASSERT_NE(dialog, nullptr);
    const QString text = dialog->page()->toPlainText();
    EXPECT_TRUE(text.contains(QStringLiteral("SF_EmergencyStop"))) << text.toStdString();
    // A state with the library's meaning and a transition read from the body.
    EXPECT_TRUE(text.contains(QStringLiteral("start: waiting for a press of Reset")));
    EXPECT_TRUE(text.contains(QStringLiteral("Reset * /resetEdge")));
    EXPECT_FALSE(text.contains(QStringLiteral("No timing diagram"))) << text.toStdString();
    const QVariant diagram = dialog->page()->document()->resource(
        QTextDocument::ImageResource, rs::ui::BlockDocumentation::timingDiagramUrl());
    ASSERT_TRUE(diagram.canConvert<QImage>());
    const QImage image = diagram.value<QImage>();
    EXPECT_GT(image.height(), 8 * 28) << "a row per bound pin of the example";
    dialog->close();
}

TEST_F(BlockDocumentationTest, TheChoosersDescriptionLinksToThePage) {
    openLadder();
    page().setCursor({0, 0, std::nullopt, std::nullopt, -1});
    bool shown = false;
    DialogDriver driver({[&shown](QDialog& chooser) {
        auto* filter = chooser.findChild<QLineEdit*>(QStringLiteral("filter"));
        QTest::keyClicks(filter, QStringLiteral("SF_EDM"));
        auto* description = chooser.findChild<QTextBrowser*>(QStringLiteral("description"));
        ASSERT_NE(description, nullptr);
        EXPECT_TRUE(description->toHtml().contains(QStringLiteral("href=\"documentation\"")));
        emit description->anchorClicked(QUrl(QStringLiteral("documentation")));
        BlockDocumentationDialog* dialog = openDocumentation();
        shown = dialog && dialog->windowTitle().startsWith(QStringLiteral("SF_EDM"));
        if (dialog)
            dialog->close();
        auto* button = chooser.findChild<QPushButton*>(QStringLiteral("documentation"));
        ASSERT_NE(button, nullptr);
        EXPECT_TRUE(button->isEnabled());
        chooser.reject();
    }});
    QTest::keyClick(page().view(), Qt::Key_F, Qt::ShiftModifier);
    ASSERT_TRUE(driver.done());
    EXPECT_TRUE(shown);
}

TEST_F(BlockDocumentationTest, StatesAreMeantInTheWindowsLanguage) {
    openLadder();
    const rs::blocks::LibrarySet& libraries = document()->libraries();
    const rs::blocks::LoadedLibrary* safety = libraries.findLibrary("Rungsmith_Safety");
    ASSERT_NE(safety, nullptr);
    const rs::blocks::BlockDefinition* block = safety->library.findBlock("SF_Equivalent");
    ASSERT_NE(block, nullptr);
    const QLocale before;
    QLocale::setDefault(QLocale(QLocale::German));
    const QString german =
        rs::ui::BlockDocumentation::html(*safety, *block, rs::blockdoc::TimingExample{});
    QLocale::setDefault(before);
    std::string meaning;
    for (const auto& state : block->states)
        if (state.code == 0x8000)
            meaning = state.meaning.german;
    ASSERT_FALSE(meaning.empty());
    EXPECT_TRUE(german.contains(QString::fromStdString(meaning).toHtmlEscaped()))
        << german.toStdString();
}

} // namespace
