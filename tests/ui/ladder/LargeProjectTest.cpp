// SPDX-License-Identifier: GPL-3.0-or-later
#include "WindowTest.h"

#include "document/ProjectDocument.h"
#include "ladder/LadderPage.h"
#include "ladder/LadderView.h"
#include "ladder/NetworkItem.h"
#include "shell/MainWindow.h"
#include "text/ProgramEditor.h"

#include <QAction>
#include <QGraphicsScene>
#include <QGraphicsSimpleTextItem>

#include <gtest/gtest.h>

namespace {

using rs::ui::PageRef;

QByteArray projectOf(const QByteArray& code) {
    return "! id_pluto:00=000000000000\n! pgm_pluto:00\n\nS0.0_0\n" + code;
}

class LargeProjectTest : public WindowTest {
protected:
    void open(const QByteArray& text) {
        ASSERT_TRUE(window.loadFile(writeFile(QStringLiteral("large.sps"), text)).isEmpty());
        showWindow();
    }
    rs::ui::LadderPage& page() { return *window.ladderPage(); }
};

TEST_F(LargeProjectTest, CodeTooLongToDrawOpensWithItsLadderPageSayingSoAndItsTextWhole) {
    constexpr int kStatements = 200'000;
    open(projectOf(QByteArray("M0.1 = I0.0\n").repeated(kStatements)));
    ASSERT_EQ(window.currentPage().kind, PageRef::Kind::Ladder);
    EXPECT_EQ(page().stepCount(), 0);
    EXPECT_FALSE(page().view()->isEnabled());
    EXPECT_FALSE(page().action(QStringLiteral("newNetworkAction"))->isEnabled());
    EXPECT_TRUE(page().action(QStringLiteral("ladderTextAction"))->isEnabled());
    bool said = false;
    for (QGraphicsItem* item : page().scene()->items())
        if (auto* text = dynamic_cast<QGraphicsSimpleTextItem*>(item))
            said =
                said || (text->isVisible() && text->text().contains(QString::number(kStatements)));
    EXPECT_TRUE(said);

    action("codeViewAction")->trigger();
    ASSERT_EQ(window.currentPage().kind, PageRef::Kind::Code);
    EXPECT_GT(window.editor()->lines(), kStatements);
}

TEST_F(LargeProjectTest, ACommentOfTenMegabytesIsDrawnShortenedAndKeptWholeInTheText) {
    const QByteArray comment = "; " + QByteArray(10'000'000, 'x');
    open(projectOf("M0.1 = I0.0\n" + comment + "\nM0.2 = I0.1\n"));
    ASSERT_EQ(window.currentPage().kind, PageRef::Kind::Ladder);
    ASSERT_GT(page().stepCount(), 0);
    qsizetype longest = 0;
    for (int n = 0; n < page().networkCount(0); ++n)
        for (const auto& text : page().networkItem(0, n)->layout().texts)
            longest = std::max(longest, text.text.size());
    EXPECT_EQ(longest, rs::ladder::kLongestDrawnText + 1); // and the ellipsis

    action("codeViewAction")->trigger();
    ASSERT_EQ(window.currentPage().kind, PageRef::Kind::Code);
    EXPECT_TRUE(window.editor()->text().contains(QString::fromLatin1(comment)));
}

} // namespace
