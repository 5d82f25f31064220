// SPDX-License-Identifier: GPL-3.0-or-later
#include "WindowTest.h"

#include "DialogDriver.h"
#include "document/ProjectDocument.h"
#include "ladder/LadderDrawing.h"
#include "ladder/LadderPage.h"
#include "ladder/LadderView.h"
#include "ladder/NetworkItem.h"
#include "ladder/StepHeaderItem.h"
#include "lang/Printer.h"
#include "project/ProjectFile.h"
#include "project/UnitText.h"
#include "shell/ProjectTree.h"
#include "shell/Theme.h"
#include "text/TextPage.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QDialog>
#include <QFile>
#include <QGraphicsScene>
#include <QGraphicsSimpleTextItem>
#include <QImage>
#include <QInputDialog>
#include <QLineEdit>
#include <QMimeData>
#include <QPlainTextEdit>
#include <QProcess>
#include <QScrollBar>
#include <QSignalSpy>
#include <QTest>
#include <QToolBar>
#include <QUndoStack>
#include <QWheelEvent>

#include "QtPrinting.h"

#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <memory>
#include <tuple>

namespace {

using rs::ui::LadderCursor;
using rs::ui::LadderPage;
using rs::ui::PageRef;

// A project with one unit and no code yet.
const QByteArray kEmptyProject = "$name Muting\n"
                                 "\n"
                                 "! id_pluto:00=000034AD4AE1\n"
                                 "! pgm_pluto:00\n";

const QByteArray kTwoUnits = "$name Two\n"
                             "\n"
                             "! id_pluto:00=000034AD4AE1\n"
                             "! id_pluto:01=000034AD4AE2\n"
                             "! pgm_pluto:00\n"
                             "S0.0_0\n"
                             "Q0.2 = I0.1 * I0.2\n"
                             "Q0.3 = I0.3 + I0.4\n"
                             "Q0.4 = /I0.5\n"
                             "! pgm_pluto:01\n"
                             "S1.0_0\n"
                             "Q1.2 = I1.1\n";

// Each statement of a unit's code with its trailing comment, step by step:
// what a program means and says, whatever its spelling and layout.
std::vector<std::string> statementsOf(const rs::project::Project& project, int station) {
    std::vector<std::string> lines;
    for (const auto& unit : project.program.units) {
        if (unit.station() != station)
            continue;
        for (const auto& step : unit.steps) {
            for (const auto& line : step.lines) {
                const auto* statement = std::get_if<rs::lang::Statement>(&line.body);
                if (!statement)
                    continue;
                std::string comment = line.comment.value_or("");
                comment.erase(0, comment.find_first_not_of(' '));
                lines.push_back(rs::lang::toString(step.address) + " " +
                                rs::lang::printStatement(*statement) + " ;" + comment);
            }
        }
    }
    return lines;
}

class LadderPageTest : public WindowTest {
protected:
    LadderPage& page() { return *window.ladderPage(); }
    QWidget* viewport() { return page().view()->viewport(); }

    void open(const QByteArray& text) {
        ASSERT_TRUE(window.loadFile(writeFile(QStringLiteral("project.sps"), text)).isEmpty());
        showWindow();
    }

    void key(int key, Qt::KeyboardModifiers modifiers = {}) {
        QTest::keyClick(page().view(), static_cast<Qt::Key>(key), modifiers);
    }

    void key(char character) { QTest::keyClick(page().view(), character); }

    // Presses the key of an element and fills in its properties dialog by keyboard.
    void insert(char keyCharacter, const QString& operand, const QString& value = {},
                const QString& comment = {}, Qt::KeyboardModifiers modifiers = {}) {
        DialogDriver driver({[&](QDialog& dialog) {
            auto typeInto = [&](const char* name, const QString& text) {
                auto* field = dialog.findChild<QLineEdit*>(QLatin1String(name));
                ASSERT_NE(field, nullptr) << name;
                field->selectAll();
                QTest::keyClick(field, Qt::Key_Backspace);
                QTest::keyClicks(field, text);
            };
            typeInto("operand", operand);
            if (!value.isEmpty())
                typeInto("value", value);
            if (!comment.isEmpty())
                typeInto("comment", comment);
            QTest::keyClick(dialog.findChild<QLineEdit*>(QStringLiteral("operand")),
                            Qt::Key_Return);
        }});
        if (modifiers)
            QTest::keyClick(page().view(),
                            static_cast<Qt::Key>(QChar(keyCharacter).toUpper().unicode()),
                            modifiers);
        else
            QTest::keyClick(page().view(), keyCharacter);
        ASSERT_TRUE(driver.done()) << "no dialog for " << keyCharacter;
        EXPECT_TRUE(page().message().isEmpty()) << page().message().toStdString();
    }

    // Where the element drawn with this address (and, if given, symbol) is on screen.
    QPoint where(const QString& address, std::optional<rs::ladder::ElementKind> symbol = {}) {
        for (int s = 0; s < page().stepCount(); ++s)
            for (int n = 0; n < page().networkCount(s); ++n) {
                rs::ui::NetworkItem* item = page().networkItem(s, n);
                for (const auto& element : item->layout().elements)
                    if (element.address == address && (!symbol || element.kind == *symbol)) {
                        const QRectF rect = item->mapRectToScene(item->elementRect(element));
                        page().view()->ensureVisible(rect);
                        return page().view()->mapFromScene(rect.center());
                    }
            }
        ADD_FAILURE() << "no element " << address.toStdString();
        return {};
    }

    void click(const QString& address, std::optional<rs::ladder::ElementKind> symbol = {}) {
        QTest::mouseClick(viewport(), Qt::LeftButton, {}, where(address, symbol));
    }

    QByteArray unitText(int station) {
        return QByteArray::fromStdString(rs::project::unitText(document()->project(), station));
    }
};

TEST_F(LadderPageTest, TheCodeNodeOpensTheLadderAndTheTextStaysReachable) {
    open(kTwoUnits);
    clickNode({PageRef::Kind::Ladder, document(), 0, 0});
    EXPECT_EQ(window.currentPage().kind, PageRef::Kind::Ladder);
    EXPECT_EQ(page().station(), 0);
    EXPECT_EQ(page().sequence(), 0);
    EXPECT_EQ(page().networkCount(0), 3);
    page().action(QStringLiteral("ladderTextAction"))->trigger();
    EXPECT_EQ(window.currentPage().kind, PageRef::Kind::Code);
    action("codeViewAction")->trigger();
    EXPECT_EQ(window.currentPage().kind, PageRef::Kind::Ladder);
    // The text page has a visible way back, as the ladder has to the text (issue 17).
    page().action(QStringLiteral("ladderTextAction"))->trigger();
    auto* back = window.findChild<QToolBar*>(QStringLiteral("textToolBar"));
    ASSERT_NE(back, nullptr);
    EXPECT_TRUE(back->isVisible());
    QAction* ladder = window.findChild<QAction*>(QStringLiteral("textLadderAction"));
    ASSERT_NE(ladder, nullptr);
    QTest::mouseClick(back->widgetForAction(ladder), Qt::LeftButton);
    EXPECT_EQ(window.currentPage().kind, PageRef::Kind::Ladder);
}

TEST_F(LadderPageTest, BuildsTheManualsMutingProgramFromAnEmptyProject) {
    open(kEmptyProject);
    clickNode({PageRef::Kind::Ladder, document(), 0, 0});
    page().view()->setFocus();
    using rs::ladder::ElementKind;

    // The empty page says how to begin.
    auto hintShown = [&] {
        for (QGraphicsItem* item : page().scene()->items())
            if (auto* text = dynamic_cast<QGraphicsSimpleTextItem*>(item))
                return text->isVisible() && text->text().contains(QStringLiteral("Ins"));
        return false;
    };
    EXPECT_TRUE(hintShown());

    // Network 1: the start circuit.
    key(Qt::Key_Insert);
    insert('L', QStringLiteral("q0.2"));
    insert('C', QStringLiteral("i0.12"));
    insert('P', QStringLiteral("i0.14"));
    EXPECT_FALSE(hintShown());
    click(QStringLiteral("I0.12"));
    insert('C', QStringLiteral("i0.13"));
    key('\\');
    insert('C', QStringLiteral("m0.0"));
    click(QStringLiteral("I0.14"));
    insert('C', QStringLiteral("q0.2"));
    click(QStringLiteral("I0.14"));
    key(']');
    insert('C', QStringLiteral("i0.02"));
    // Network 2 and 3.
    key(Qt::Key_Insert);
    insert('L', QStringLiteral("q0.3"));
    insert('C', QStringLiteral("q0.2"));
    key(Qt::Key_Insert);
    insert('L', QStringLiteral("q0.14"), {},
           QStringLiteral("Reset indication active when outputs not active"));
    insert('/', QStringLiteral("q0.2"));
    EXPECT_EQ(page().networkCount(0), 3);

    // Sequence 1, as the page's menu asks for it.
    DialogDriver sequence({[](QDialog& dialog) {
        dialog.accept();
    }});
    emit page().newSequenceRequested();
    ASSERT_EQ(window.currentPage().kind, PageRef::Kind::Ladder);
    ASSERT_EQ(page().sequence(), 1);
    page().view()->setFocus();
    key(Qt::Key_Down);
    key(Qt::Key_Insert);
    insert('J', QStringLiteral("+1"), {},
           QStringLiteral("Start condition: both sensors not active"));
    insert('/', QStringLiteral("i0.00"));
    insert('/', QStringLiteral("i0.01"));
    insert('=', QStringLiteral("sr0.43"), QStringLiteral("<100"));

    page().newStep();
    insert('L', QStringLiteral("q0.17"));
    insert('C', QStringLiteral("i0.00"));
    insert('C', QStringLiteral("i0.01"));
    insert('C', QStringLiteral("i0.13"));
    key(Qt::Key_Insert);
    insert('J', QStringLiteral("+1"), {},
           QStringLiteral("Muting start when both sensors and JSL active"));
    insert('C', QStringLiteral("q0.17"));
    insert('=', QStringLiteral("sr0.43"), QStringLiteral("<100"));

    page().newStep();
    insert('L', QStringLiteral("m0.0"), {}, QStringLiteral("M0.0, Memory muting active"));
    key(Qt::Key_Insert);
    insert('L', QStringLiteral("q0.17"), {}, QStringLiteral("Indicator muting active"));
    key(Qt::Key_Insert);
    insert('J', QStringLiteral("0"), {},
           QStringLiteral("Muting stopped by either sensor not active"));
    insert('/', QStringLiteral("i0.00"));
    key('\\');
    insert('/', QStringLiteral("i0.01"));

    QFile example(QStringLiteral(RUNGSMITH_TEST_DATA "/manual/manual_muting.sps"));
    ASSERT_TRUE(example.open(QIODevice::ReadOnly));
    const QByteArray exampleText = example.readAll();
    const auto expected = rs::project::readProject(exampleText.toStdString());
    ASSERT_TRUE(expected.ok());
    EXPECT_EQ(statementsOf(document()->project(), 0), statementsOf(expected.project, 0))
        << unitText(0).toStdString();
    // What was drawn reads back as the same program.
    const auto reread = rs::project::readProject(document()->fileText().toStdString());
    ASSERT_TRUE(reread.ok());
    EXPECT_EQ(statementsOf(reread.project, 0), statementsOf(expected.project, 0));
}

TEST_F(LadderPageTest, TheCommandLineShowsTheLadderPage) {
    QProcess process;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    environment.insert(QStringLiteral("XDG_CONFIG_HOME"), directory.path());
    process.setProcessEnvironment(environment);
    const QString picture = directory.filePath(QStringLiteral("ladder.png"));
    process.start(QStringLiteral(RUNGSMITH_GUI),
                  {QStringLiteral(RUNGSMITH_TEST_DATA "/manual/manual_muting.sps"),
                   QStringLiteral("--screenshot"), picture, QStringLiteral("--page"),
                   QStringLiteral("ladder:0")});
    ASSERT_TRUE(process.waitForFinished(60000));
    EXPECT_EQ(process.exitCode(), 0) << process.readAllStandardError().toStdString();
    EXPECT_FALSE(QImage(picture).isNull());
    process.start(QStringLiteral(RUNGSMITH_GUI),
                  {QStringLiteral(RUNGSMITH_TEST_DATA "/manual/manual_muting.sps"),
                   QStringLiteral("--screenshot"), picture, QStringLiteral("--page"),
                   QStringLiteral("ladder:7")});
    ASSERT_TRUE(process.waitForFinished(60000));
    EXPECT_EQ(process.exitCode(), 2); // no unit 7
}

TEST_F(LadderPageTest, EveryOperationIsOneUndoStepAndRedoes) {
    open(kTwoUnits);
    clickNode({PageRef::Kind::Ladder, document(), 0, 0});
    page().view()->setFocus();
    QUndoStack* stack = document()->undoStack();
    std::vector<QByteArray> texts{unitText(0)};
    auto done = [&](const char* what) {
        const QByteArray now = unitText(0);
        EXPECT_NE(now, texts.back()) << what;
        texts.push_back(now);
        EXPECT_EQ(stack->index(), static_cast<int>(texts.size()) - 1) << what;
    };
    click(QStringLiteral("I0.1"));
    insert('C', QStringLiteral("I0.7"));
    done("insert after");
    key('[');
    insert('C', QStringLiteral("I0.8"));
    done("insert before");
    key('\\');
    insert('C', QStringLiteral("M0.1"));
    done("insert in parallel");
    key(']');
    click(QStringLiteral("Q0.2"));
    insert('S', QStringLiteral("Q0.9"));
    done("add an output");
    click(QStringLiteral("I0.7"));
    DialogDriver change({[](QDialog& dialog) {
        auto* operand = dialog.findChild<QLineEdit*>(QStringLiteral("operand"));
        operand->setText(QStringLiteral("I0.10"));
        dialog.accept();
    }});
    key(Qt::Key_Return);
    done("change an element");
    click(QStringLiteral("I0.10"));
    key(Qt::Key_Delete);
    done("delete an element");
    click(QStringLiteral("Q0.9"));
    key(Qt::Key_Delete);
    done("delete an output");
    page().setCursor({0, 1, std::nullopt, std::nullopt, -1});
    page().copyNetworks();
    page().pasteNetworks();
    done("paste");
    page().setCursor({0, 0, std::nullopt, std::nullopt, -1});
    page().cutNetworks();
    done("cut");
    page().deleteNetworks();
    done("delete a network");
    page().setCursor({0, 0, std::nullopt, std::nullopt, -1});
    key('E');
    insert('C', QStringLiteral("I0.11"));
    insert('C', QStringLiteral("I0.12"));
    EXPECT_EQ(unitText(0), texts.back()); // gathered in the network until Update
    key(Qt::Key_F3);
    done("edit mode, update");
    key('E');
    insert('C', QStringLiteral("I0.13"));
    key(Qt::Key_F2);
    EXPECT_EQ(unitText(0), texts.back());
    EXPECT_FALSE(unitText(0).contains("I0.13"));

    for (std::size_t i = texts.size() - 1; i > 0; --i) {
        stack->undo();
        EXPECT_EQ(unitText(0), texts[i - 1]) << "undo to " << i - 1;
    }
    for (std::size_t i = 1; i < texts.size(); ++i) {
        stack->redo();
        EXPECT_EQ(unitText(0), texts[i]) << "redo to " << i;
    }
}

TEST_F(LadderPageTest, NetworksAreCutInOneUnitAndPastedInAnother) {
    open(kTwoUnits);
    clickNode({PageRef::Kind::Ladder, document(), 0, 0});
    const QPoint first = page().view()->mapFromScene(
        page().networkItem(0, 0)->sceneBoundingRect().topLeft() + QPointF(60, 12));
    const QPoint second = page().view()->mapFromScene(
        page().networkItem(0, 1)->sceneBoundingRect().topLeft() + QPointF(60, 12));
    QTest::mouseClick(viewport(), Qt::LeftButton, {}, first);
    QTest::mouseClick(viewport(), Qt::LeftButton, Qt::ShiftModifier, second);
    page().view()->setFocus();
    action("cutAction")->trigger();
    EXPECT_EQ(page().networkCount(0), 1);
    EXPECT_FALSE(unitText(0).contains("Q0.2 ="));

    clickNode({PageRef::Kind::Ladder, document(), 1, 0});
    page().view()->setFocus();
    page().setCursor({0, 0, std::nullopt, std::nullopt, -1});
    action("pasteAction")->trigger();
    EXPECT_EQ(page().networkCount(0), 3);
    EXPECT_TRUE(unitText(1).contains("Q1.2 = I1.1\n;@network comment=\"\"\nQ0.2 = I0.1 * I0.2\n"))
        << unitText(1).toStdString();
    EXPECT_TRUE(unitText(1).contains("Q0.3 = I0.3 + I0.4\n")) << unitText(1).toStdString();
    document()->undoStack()->undo();
    EXPECT_EQ(page().networkCount(0), 1);
}

TEST_F(LadderPageTest, ElementsMoveBetweenNetworksAndSteps) {
    open(kTwoUnits + "S1.1_0\nJ(+1) = I1.3 * I1.4\nS1.1_1\nJ(0) = I1.5\n");
    clickNode({PageRef::Kind::Ladder, document(), 0, 0});
    using rs::ladder::ElementPath;
    using rs::ladder::Side;
    // I0.2 of network 1 after /I0.5 of network 3.
    ASSERT_TRUE(page().moveElement({0, 0, ElementPath{0, {1}}, std::nullopt, -1},
                                   {0, 2, ElementPath{0, {}}, std::nullopt, -1}, Side::After));
    EXPECT_TRUE(unitText(0).contains("Q0.2 = I0.1\nQ0.3 = I0.3 + I0.4\nQ0.4 = /I0.5 * I0.2\n"))
        << unitText(0).toStdString();
    // Moving a group into itself is refused, with the reason shown.
    EXPECT_FALSE(page().moveElement({0, 1, ElementPath{0, {}}, std::nullopt, -1},
                                    {0, 1, ElementPath{0, {0}}, std::nullopt, -1}, Side::After));
    EXPECT_FALSE(page().message().isEmpty());

    clickNode({PageRef::Kind::Ladder, document(), 1, 1});
    ASSERT_EQ(page().stepCount(), 2);
    const QByteArray before = unitText(1);
    ASSERT_TRUE(page().moveElement({0, 0, ElementPath{0, {1}}, std::nullopt, -1},
                                   {1, 0, ElementPath{0, {}}, std::nullopt, -1}, Side::Before));
    EXPECT_TRUE(unitText(1).contains("S1.1_0\nJ(+1) = I1.3\nS1.1_1\nJ(0) = I1.4 * I1.5\n"))
        << unitText(1).toStdString();
    document()->undoStack()->undo();
    EXPECT_EQ(unitText(1), before);
}

TEST_F(LadderPageTest, ADoubleClickOnAStepsHeadingEditsItsComment) {
    open(kTwoUnits + "S1.1_0\nJ(+1) = I1.3\n");
    clickNode({PageRef::Kind::Ladder, document(), 1, 1});
    rs::ui::StepHeaderItem* header = nullptr;
    for (QGraphicsItem* item : page().scene()->items())
        if (auto* found = dynamic_cast<rs::ui::StepHeaderItem*>(item))
            header = found;
    ASSERT_NE(header, nullptr);
    DialogDriver driver({[](QDialog& dialog) {
        static_cast<QInputDialog&>(dialog).setTextValue(QStringLiteral("Waiting for the sensors"));
        dialog.accept();
    }});
    const QPoint where = page().view()->mapFromScene(header->sceneBoundingRect().center());
    QTest::mouseDClick(viewport(), Qt::LeftButton, {}, where);
    ASSERT_TRUE(driver.done());
    EXPECT_TRUE(unitText(1).contains("S1.1_0") && unitText(1).contains("; Waiting for the sensors"))
        << unitText(1).toStdString();
}

// Issue 17, finding 5: the network comment is typed and confirmed from the
// keyboard alone, and the canvas shows whether it has the focus.
TEST_F(LadderPageTest, ANetworkCommentIsTypedAndConfirmedFromTheKeyboard) {
    open(kTwoUnits);
    clickNode({PageRef::Kind::Ladder, document(), 0, 0});
    page().view()->setFocus();
    DialogDriver driver({[](QDialog& dialog) {
        auto* editor = dialog.findChild<QPlainTextEdit*>(QStringLiteral("commentEditor"));
        ASSERT_NE(editor, nullptr);
        editor->selectAll();
        QTest::keyClicks(editor, QStringLiteral("Guard closed"));
        QTest::keyClick(editor, Qt::Key_Return);
        QTest::keyClicks(editor, QStringLiteral("and locked"));
        QTest::keyClick(editor, Qt::Key_Return, Qt::ControlModifier);
    }});
    QTest::mouseClick(
        viewport(), Qt::LeftButton, {},
        page().view()->mapFromScene(page().networkItem(0, 1)->sceneBoundingRect().center()));
    page().findChild<QAction*>(QStringLiteral("networkCommentAction"))->trigger();
    ASSERT_TRUE(driver.done());
    EXPECT_TRUE(unitText(0).contains("Guard closed")) << unitText(0).toStdString();
    EXPECT_TRUE(unitText(0).contains("and locked"));
}

TEST_F(LadderPageTest, TheCanvasShowsWhetherItHasTheFocus) {
    open(kTwoUnits);
    clickNode({PageRef::Kind::Ladder, document(), 0, 0});
    activate();
    auto band = [&] {
        const QImage image = page().view()->grab().toImage();
        return image.pixelColor(0, image.height() / 2);
    };
    const QColor highlight = page().view()->palette().color(QPalette::Highlight);
    page().view()->setFocus();
    ASSERT_TRUE(QTest::qWaitFor([&] { return page().view()->hasFocus(); }, 2000));
    EXPECT_EQ(band(), highlight);
    window.findChild<QWidget*>(QStringLiteral("projectTree"))->setFocus();
    ASSERT_TRUE(QTest::qWaitFor([&] { return !page().view()->hasFocus(); }, 2000));
    EXPECT_NE(band(), highlight);
}

// Issue 17, finding 4: a drag copies (manual 11.5), Shift+drag moves, and
// the place of the drop is drawn while dragging.
TEST_F(LadderPageTest, DraggingAnElementCopiesItShiftMovesItAndTheDropPlaceIsDrawn) {
    open(kTwoUnits);
    clickNode({PageRef::Kind::Ladder, document(), 0, 0});
    auto dragOnto = [&](const QString& dragged, const QString& onto, Qt::KeyboardModifiers keys) {
        std::unique_ptr<QMimeData> data(
            page().elementDragData(page().view()->mapToScene(where(dragged))));
        ASSERT_NE(data, nullptr);
        // Onto the right half of the element: after it.
        const QPoint target = where(onto) + QPoint(6, 0);
        const Qt::DropActions offered = Qt::CopyAction | Qt::MoveAction;
        QDragEnterEvent enter(target, offered, data.get(), Qt::LeftButton, keys);
        QApplication::sendEvent(viewport(), &enter);
        QDragMoveEvent hover(target, offered, data.get(), Qt::LeftButton, keys);
        QApplication::sendEvent(viewport(), &hover);
        EXPECT_TRUE(hover.isAccepted());
        EXPECT_EQ(hover.dropAction(), keys & Qt::ShiftModifier ? Qt::MoveAction : Qt::CopyAction);
        EXPECT_TRUE(page().isDropPlaceShown());
        EXPECT_TRUE(page().message().contains(keys & Qt::ShiftModifier ? QStringLiteral("Moving")
                                                                       : QStringLiteral("Copying")))
            << page().message().toStdString();
        QDropEvent drop(target, offered, data.get(), Qt::LeftButton, keys);
        QApplication::sendEvent(viewport(), &drop);
        EXPECT_FALSE(page().isDropPlaceShown());
    };
    dragOnto(QStringLiteral("I0.1"), QStringLiteral("I0.5"), Qt::NoModifier);
    EXPECT_TRUE(unitText(0).contains("Q0.2 = I0.1 * I0.2\n")) << unitText(0).toStdString();
    EXPECT_TRUE(unitText(0).contains("Q0.4 = /I0.5 * I0.1\n")) << unitText(0).toStdString();
    dragOnto(QStringLiteral("I0.2"), QStringLiteral("I0.1"), Qt::ShiftModifier);
    EXPECT_TRUE(unitText(0).contains("Q0.2 = I0.1 * I0.2\n")) << unitText(0).toStdString();
    dragOnto(QStringLiteral("I0.3"), QStringLiteral("I0.5"), Qt::ShiftModifier);
    EXPECT_TRUE(unitText(0).contains("Q0.3 = I0.4\n")) << unitText(0).toStdString();
    EXPECT_TRUE(unitText(0).contains("Q0.4 = /I0.5 * I0.3 * I0.1\n")) << unitText(0).toStdString();
    // Each drop is one undo step.
    document()->undoStack()->undo();
    EXPECT_TRUE(unitText(0).contains("Q0.3 = I0.3 + I0.4\n")) << unitText(0).toStdString();
}

// Issue 17, finding 3: every command of the page shows at 1,280 px, and at
// 1,024 px the contacts, boxes, coil, S and R still do.
TEST_F(LadderPageTest, EveryToolBarCommandShowsAt1280AndTheEssentialOnesAt1024) {
    open(kTwoUnits);
    clickNode({PageRef::Kind::Ladder, document(), 0, 0});
    auto* elements = page().findChild<QToolBar*>(QStringLiteral("ladderToolBar"));
    auto* network = page().findChild<QToolBar*>(QStringLiteral("ladderNetworkBar"));
    ASSERT_TRUE(elements && network);
    auto shown = [](QToolBar* bar, QAction* action) {
        QWidget* button = bar->widgetForAction(action);
        return button && button->isVisible() &&
               button->geometry().right() < bar->contentsRect().right();
    };
    window.resize(1280, 800);
    QApplication::processEvents();
    ASSERT_LE(window.minimumSizeHint().width(), 1024);
    for (QToolBar* bar : {elements, network})
        for (QAction* action : bar->actions()) {
            if (!action->isSeparator()) {
                EXPECT_TRUE(shown(bar, action)) << action->objectName().toStdString();
            }
        }

    window.resize(1024, 700);
    QApplication::processEvents();
    EXPECT_EQ(window.width(), 1024);
    using rs::ladder::ElementKind;
    for (const ElementKind kind :
         {ElementKind::NormallyOpen, ElementKind::NormallyClosed, ElementKind::PositiveEdge,
          ElementKind::OnDelayTimer, ElementKind::Comparison, ElementKind::Coil, ElementKind::Set,
          ElementKind::Reset}) {
        QAction* action =
            page().action(QStringLiteral("insert%1Action").arg(static_cast<int>(kind)));
        ASSERT_NE(action, nullptr);
        EXPECT_TRUE(shown(elements, action)) << static_cast<int>(kind);
    }
    for (const char* name :
         {"ladderTextAction", "placeAfterAction", "placeBeforeAction", "placeParallelAction",
          "editNetworkAction", "updateNetworkAction", "undoNetworkAction"})
        EXPECT_TRUE(shown(network, page().action(QLatin1String(name)))) << name;
}

// Issue 17, live view: the preference colours are applied at once or
// removed, and by default the page draws exactly the theme's colours.
TEST_F(LadderPageTest, PreferenceColoursAreAppliedAtOnceAndTheDefaultsAreTheTheme) {
    open(kTwoUnits);
    clickNode({PageRef::Kind::Ladder, document(), 0, 0});
    const rs::ui::LadderDrawing theme = rs::ui::drawingFor(page().palette());
    EXPECT_EQ(page().drawing().style.background, theme.style.background);
    EXPECT_EQ(page().drawing().style.ink, theme.style.ink);
    EXPECT_EQ(page().drawing().style.powered, theme.style.powered);
    EXPECT_FALSE(page().drawing().style.body.isValid()); // as the background
    EXPECT_EQ(page().drawing().selection, theme.selection);

    auto backgroundPixel = [&] {
        const QImage image = viewport()->grab().toImage();
        return image.pixelColor(image.width() - 3, image.height() - 3);
    };
    rs::ui::LadderColours chosen;
    chosen.background = QColor(0x20, 0x30, 0x40);
    chosen.lines = QColor(0xff, 0xee, 0x00);
    chosen.linesOff = QColor(0x00, 0xee, 0xff);
    page().setColours(chosen);
    EXPECT_EQ(backgroundPixel(), chosen.background);
    EXPECT_EQ(page().drawing().style.ink, chosen.lines);

    page().setColours({});
    EXPECT_EQ(backgroundPixel(), theme.style.background);
    EXPECT_EQ(page().drawing().style.ink, theme.style.ink);
}

TEST_F(LadderPageTest, ATextEditLaysTheLadderOutAgain) {
    open(kTwoUnits);
    clickNode({PageRef::Kind::Ladder, document(), 0, 0});
    EXPECT_EQ(page().networkCount(0), 3);
    rs::project::Project edited = document()->project();
    const auto read =
        rs::project::readUnitText(edited, 0, unitText(0).toStdString() + "Q0.7 = I0.7\n");
    ASSERT_TRUE(read.ok());
    document()->replace(QStringLiteral("typing"), read.project);
    EXPECT_EQ(page().networkCount(0), 4);
    EXPECT_EQ(page().networkItem(0, 3)->layout().elements.size(), 2U);
}

TEST_F(LadderPageTest, LiveStateColoursElementsAndReportsClicks) {
    open(kTwoUnits);
    clickNode({PageRef::Kind::Ladder, document(), 0, 0});
    const QColor ink = page().elementColor(0, 1);
    rs::ui::LadderLiveState live;
    live.power.statements[0].conducting = {1, 2};
    live.power.statements[0].energised = true;
    page().setLiveState(&live);
    EXPECT_NE(page().elementColor(0, 1), ink); // I0.1 conducts
    EXPECT_EQ(page().elementColor(0, 3), ink); // I0.2 does not
    QSignalSpy clicks(&page(), &LadderPage::operandClicked);
    click(QStringLiteral("I0.2"));
    ASSERT_EQ(clicks.size(), 1);
    EXPECT_EQ(clicks.front().front().toString(), QStringLiteral("I0.2"));
    // The keyboard does the same: arrows select, Space clicks, Shift+F10 asks for the menu.
    QSignalSpy menus(&page(), &LadderPage::operandMenuRequested);
    key(Qt::Key_Left);
    key(Qt::Key_Space);
    ASSERT_EQ(clicks.size(), 2);
    EXPECT_EQ(clicks.back().front().toString(), QStringLiteral("I0.1"));
    key(Qt::Key_F10, Qt::ShiftModifier);
    ASSERT_EQ(menus.size(), 1);
    EXPECT_EQ(menus.front().front().toString(), QStringLiteral("I0.1"));
    // Live, the page is still for reading: networks expand and collapse.
    rs::ui::NetworkItem* first = page().networkItem(0, 0);
    const QPointF box = first->mapToScene(first->collapseBox().center());
    QTest::mouseClick(viewport(), Qt::LeftButton, {}, page().view()->mapFromScene(box));
    EXPECT_TRUE(first->collapsed());
    EXPECT_TRUE(page().action(QStringLiteral("expandAllAction"))->isEnabled());
    page().action(QStringLiteral("expandAllAction"))->trigger();
    EXPECT_FALSE(first->collapsed());
    // Live, the page does not edit.
    const QByteArray before = unitText(0);
    key(Qt::Key_Delete);
    EXPECT_EQ(unitText(0), before);
    page().setLiveState(nullptr);
    EXPECT_EQ(page().elementColor(0, 1), ink);
}

TEST_F(LadderPageTest, DiagnosticsLandOnTheirElements) {
    open(kTwoUnits);
    clickNode({PageRef::Kind::Ladder, document(), 0, 0});
    // Line 3 of the unit's text is "Q0.3 = I0.3 + I0.4": I0.4 is at column 15.
    page().setDiagnostics({{rs::lang::Severity::Error, 4, 15, "I0.4 is not an input here"}});
    ASSERT_EQ(page().problems().size(), 1U) << unitText(0).toStdString();
    EXPECT_EQ(page().problems().begin()->first, std::make_pair(std::uint32_t{1}, std::uint16_t{3}));
    ASSERT_TRUE(page().selectElement(1, 3));
    EXPECT_EQ(page().message(), QStringLiteral("I0.4 is not an input here"));
}

TEST_F(LadderPageTest, AConfigOptionIsACheckBoxThatSetsOrResetsAMemory) {
    open(kTwoUnits);
    clickNode({PageRef::Kind::Ladder, document(), 0, 0});
    page().view()->setFocus();
    DialogDriver driver({[](QDialog& dialog) {
        dialog.findChild<QLineEdit*>(QStringLiteral("description"))
            ->setText(QStringLiteral("Door switch fitted"));
        dialog.findChild<QLineEdit*>(QStringLiteral("memory"))->setText(QStringLiteral("m0.5"));
        dialog.findChild<QCheckBox*>(QStringLiteral("checked"))->setChecked(true);
        dialog.accept();
    }});
    page().newConfigOption();
    EXPECT_TRUE(unitText(0).startsWith(
        "! pgm_pluto:00\nS0.0_0\n;@network comment=\"Door switch fitted\" option=\"on\"\n"
        "S(M0.5)\n"))
        << unitText(0).toStdString();
    ASSERT_TRUE(page().networkItem(0, 0)->option().has_value());
    EXPECT_EQ(page().cursor().network, 0);
    key(Qt::Key_Space);
    EXPECT_TRUE(unitText(0).contains("option=\"off\"\nR(M0.5)\n")) << unitText(0).toStdString();
    EXPECT_FALSE(page().networkItem(0, 0)->option()->checked);
    document()->undoStack()->undo();
    EXPECT_TRUE(page().networkItem(0, 0)->option()->checked);
    // Options are ordinary code to the compiler and read back as options.
    const auto reread = rs::project::readProject(document()->fileText().toStdString());
    EXPECT_TRUE(reread.ok());
}

TEST_F(LadderPageTest, AWheelNotchGlidesOneStepDown) {
    QByteArray text = kEmptyProject + "S0.0_0\n";
    for (int i = 0; i < 40; ++i)
        text += QStringLiteral("M0.%1 = I0.%2\n").arg(i).arg(i % 16).toUtf8();
    open(text);
    clickNode({PageRef::Kind::Ladder, document(), 0, 0});
    QScrollBar* bar = page().view()->verticalScrollBar();
    ASSERT_GT(bar->maximum(), 1000);
    const QPointF at(100, 100);
    QWheelEvent notch(at, page().view()->viewport()->mapToGlobal(at), QPoint(), QPoint(0, -120),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(page().view()->viewport(), &notch);
    EXPECT_LT(bar->value(), 120); // on its way
    EXPECT_TRUE(QTest::qWaitFor([&] { return bar->value() == 120; }, 2000)) << bar->value();
}

TEST_F(LadderPageTest, ZoomsWithTheKeysAndExportsPdf) {
    open(kTwoUnits);
    clickNode({PageRef::Kind::Ladder, document(), 0, 0});
    page().view()->setFocus();
    QTest::keyClick(page().view(), Qt::Key_Plus, Qt::ControlModifier);
    EXPECT_GT(page().view()->zoom(), 1);
    QTest::keyClick(page().view(), Qt::Key_0, Qt::ControlModifier);
    EXPECT_EQ(page().view()->zoom(), 1);
    page().setAllCollapsed(true);
    EXPECT_TRUE(page().networkItem(0, 2)->collapsed());
    EXPECT_LT(page().networkItem(0, 2)->boundingRect().height(), 60);
    page().setAllCollapsed(false);
    const QString pdf = directory.filePath(QStringLiteral("ladder.pdf"));
    ASSERT_TRUE(page().exportPdf(pdf));
    EXPECT_TRUE(readFile(pdf).startsWith("%PDF"));
}

} // namespace

namespace {

// Pixels of exactly this colour in the image.
int pixelsOf(const QImage& image, const QColor& colour) {
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    int count = 0;
    for (int y = 0; y < rgb.height(); ++y) {
        const auto* line = reinterpret_cast<const QRgb*>(rgb.constScanLine(y));
        for (int x = 0; x < rgb.width(); ++x)
            count += (line[x] & 0xffffff) == (colour.rgb() & 0xffffff);
    }
    return count;
}

class LadderEditingStates : public LadderPageTest,
                            public ::testing::WithParamInterface<rs::ui::Preferences::Theme> {
protected:
    void TearDown() override {
        rs::ui::applyTheme(rs::ui::Preferences::Theme::Light);
        LadderPageTest::TearDown();
    }

    // Writes the window's picture for the documentation when
    // RUNGSMITH_LADDER_SCREENSHOTS names a folder.
    void keep(const QString& name) {
        const QString folder = qEnvironmentVariable("RUNGSMITH_LADDER_SCREENSHOTS");
        if (folder.isEmpty())
            return;
        const QString theme = GetParam() == rs::ui::Preferences::Theme::Dark ? "dark" : "light";
        window.grab().save(QStringLiteral("%1/ladder-%2-%3.png").arg(folder, name, theme));
    }
};

TEST_P(LadderEditingStates, SelectionEditModeAndProblemsAreDrawn) {
    rs::ui::applyTheme(GetParam());
    QFile example(QStringLiteral(RUNGSMITH_TEST_DATA "/manual/manual_muting.sps"));
    ASSERT_TRUE(example.open(QIODevice::ReadOnly));
    open(example.readAll());
    window.resize(1280, 800);
    clickNode({PageRef::Kind::Ladder, document(), 0, 0});
    page().view()->setFocus();
    // Network 2 in edit mode with a contact added, a problem on network 3's contact.
    page().setCursor({0, 1, std::nullopt, std::nullopt, -1});
    key('E');
    click(QStringLiteral("Q0.3"));
    {
        DialogDriver driver({[&](QDialog& dialog) {
            auto* operand = dialog.findChild<QLineEdit*>(QStringLiteral("operand"));
            QTest::keyClicks(operand, QStringLiteral("I0.1"));
            const QString folder = qEnvironmentVariable("RUNGSMITH_LADDER_SCREENSHOTS");
            if (!folder.isEmpty())
                dialog.grab().save(QStringLiteral("%1/ladder-properties-%2.png")
                                       .arg(folder, GetParam() == rs::ui::Preferences::Theme::Dark
                                                        ? QStringLiteral("dark")
                                                        : QStringLiteral("light")));
            QTest::keyClick(operand, Qt::Key_Return);
        }});
        key('C');
        ASSERT_TRUE(driver.done());
    }
    // A diagnostic at I0.12 of network 1, by line and column of the unit's text.
    const QList<QByteArray> lines = unitText(0).split('\n');
    int line = 0;
    while (line < lines.size() && !lines[line].startsWith("Q0.2 = "))
        ++line;
    ASSERT_LT(line, lines.size());
    page().setDiagnostics(
        {{rs::lang::Severity::Error, line + 1, static_cast<int>(lines[line].indexOf("I0.12")) + 1,
          "I0.12 has no I/O declaration"}});
    click(QStringLiteral("I0.12"));
    EXPECT_EQ(page().message(), QStringLiteral("I0.12 has no I/O declaration"));
    const rs::ui::LadderDrawing colours = rs::ui::drawingFor(page().palette());
    QImage picture = page().view()->viewport()->grab().toImage();
    EXPECT_GT(pixelsOf(picture, colours.editing), 50);
    EXPECT_GT(pixelsOf(picture, colours.selection), 50);
    EXPECT_GT(pixelsOf(picture, colours.problem), 20);
    EXPECT_GT(pixelsOf(picture, colours.style.background), picture.width() * picture.height() / 3);
    keep(QStringLiteral("editing"));

    // A sequence page: steps with their networks, jumps as outputs.
    key(Qt::Key_F3);
    clickNode({PageRef::Kind::Ladder, document(), 0, 1});
    EXPECT_EQ(page().stepCount(), 3);
    click(QStringLiteral("step +1"));
    picture = page().view()->viewport()->grab().toImage();
    EXPECT_GT(pixelsOf(picture, colours.selection), 50);
    keep(QStringLiteral("sequence"));
}

TEST_P(LadderEditingStates, OptionsAndCollapsedNetworksAreDrawn) {
    rs::ui::applyTheme(GetParam());
    open(kTwoUnits);
    window.resize(1280, 800);
    clickNode({PageRef::Kind::Ladder, document(), 0, 0});
    for (const auto& option : {std::tuple{"Door switch fitted", "M0.5", true},
                               {"Second light curtain", "M0.6", false}}) {
        // Not a structured binding: clang 14 cannot capture one.
        const char* text = std::get<0>(option);
        const char* memory = std::get<1>(option);
        const bool on = std::get<2>(option);
        DialogDriver driver({[&](QDialog& dialog) {
            dialog.findChild<QLineEdit*>(QStringLiteral("description"))
                ->setText(QString::fromUtf8(text));
            dialog.findChild<QLineEdit*>(QStringLiteral("memory"))
                ->setText(QString::fromUtf8(memory));
            dialog.findChild<QCheckBox*>(QStringLiteral("checked"))->setChecked(on);
            dialog.accept();
        }});
        page().newConfigOption();
    }
    ASSERT_EQ(page().networkCount(0), 5);
    page().toggleCollapsed(0, 3);
    page().toggleCollapsed(0, 4);
    page().setCursor({0, 0, std::nullopt, std::nullopt, -1});
    const rs::ui::LadderDrawing colours = rs::ui::drawingFor(page().palette());
    const QImage picture = page().view()->viewport()->grab().toImage();
    EXPECT_GT(pixelsOf(picture, colours.style.powered), 5); // the tick of the option that is on
    keep(QStringLiteral("options"));
}

INSTANTIATE_TEST_SUITE_P(Themes, LadderEditingStates,
                         ::testing::Values(rs::ui::Preferences::Theme::Light,
                                           rs::ui::Preferences::Theme::Dark));

TEST_F(LadderPageTest, EveryKeyIsOneActionAndTheToolbarNamesIt) {
    open(kTwoUnits);
    clickNode({PageRef::Kind::Ladder, document(), 0, 0});
    std::map<QString, QString> owners; // key -> action
    for (QAction* action : page().findChildren<QAction*>()) {
        for (const QKeySequence& key : action->shortcuts()) {
            const QString name = key.toString(QKeySequence::PortableText);
            EXPECT_FALSE(owners.count(name))
                << name.toStdString() << " twice: " << owners[name].toStdString() << ", "
                << action->objectName().toStdString();
            owners[name] = action->objectName();
        }
    }
    EXPECT_EQ(owners[QStringLiteral("F3")], QStringLiteral("updateNetworkAction"));
    EXPECT_EQ(owners[QStringLiteral("Del")], QStringLiteral("ladderDeleteAction"));
    EXPECT_EQ(owners[QStringLiteral("Left")], QStringLiteral("moveLeftAction"));
    auto* toolBar = page().findChild<QToolBar*>(QStringLiteral("ladderToolBar"));
    ASSERT_NE(toolBar, nullptr);
    for (QAction* action : toolBar->actions()) {
        if (action->shortcut().isEmpty())
            continue;
        EXPECT_TRUE(
            action->toolTip().contains(action->shortcut().toString(QKeySequence::NativeText)))
            << action->objectName().toStdString() << ": " << action->toolTip().toStdString();
    }
}

} // namespace
