// SPDX-License-Identifier: GPL-3.0-or-later
#include "text/ProgramEditor.h"
#include "shell/Theme.h"

#include <QCoreApplication>

#include <Qsci/qscilexer.h>

#include "QtPrinting.h"

#include <gtest/gtest.h>

namespace {

using rs::lang::Diagnostic;
using rs::lang::Severity;
using rs::ui::ProgramEditor;

const QString kText = QStringLiteral("S0.0_0\n"
                                     "Q0.2 = I0.1 * DR0.4.Lo\n"
                                     "Q0.3 = I0.2\n"
                                     "Q0.4 = I0.3\n");

bool hasMarker(const ProgramEditor& editor, int line, ProgramEditor::Marker marker) {
    return (editor.markersAtLine(line - 1) & (1u << marker)) != 0;
}

bool underlined(ProgramEditor& editor, int line, int column) {
    const int position = editor.positionFromLineIndex(line - 1, column - 1);
    return editor.SendScintilla(QsciScintillaBase::SCI_INDICATORALLONFOR,
                                static_cast<unsigned long>(position)) != 0;
}

TEST(ProgramEditor, FindingsGetMarkerAndMessageOnTheirLine) {
    ProgramEditor editor;
    editor.setText(kText);
    editor.setDiagnostics({{Severity::Error, 2, 15, "DR0.4.Lo holds a number"},
                           {Severity::Warning, 3, 1, "Q0.3 is never read"}});
    EXPECT_TRUE(hasMarker(editor, 2, ProgramEditor::ErrorMarker));
    EXPECT_FALSE(hasMarker(editor, 2, ProgramEditor::WarningMarker));
    EXPECT_TRUE(hasMarker(editor, 3, ProgramEditor::WarningMarker));
    EXPECT_EQ(editor.markersAtLine(0), 0u);
    EXPECT_EQ(editor.markersAtLine(3), 0u);
    EXPECT_EQ(editor.annotation(1), QStringLiteral("DR0.4.Lo holds a number"));
    EXPECT_EQ(editor.annotation(2), QStringLiteral("Q0.3 is never read"));
    EXPECT_TRUE(editor.annotation(0).isEmpty());
}

TEST(ProgramEditor, TheOffendingTokenIsUnderlinedWhole) {
    ProgramEditor editor;
    editor.setText(kText);
    editor.setDiagnostics({{Severity::Error, 2, 15, "DR0.4.Lo holds a number"}});
    EXPECT_FALSE(underlined(editor, 2, 14));
    EXPECT_TRUE(underlined(editor, 2, 15));
    EXPECT_TRUE(underlined(editor, 2, 22)) << "the last letter of DR0.4.Lo";
    EXPECT_FALSE(underlined(editor, 3, 1));
}

TEST(ProgramEditor, SeveralFindingsOnALineShareOneAnnotationAndTheWorstMarker) {
    ProgramEditor editor;
    editor.setText(kText);
    editor.setDiagnostics({{Severity::Warning, 2, 1, "first"}, {Severity::Error, 2, 8, "second"}});
    EXPECT_TRUE(hasMarker(editor, 2, ProgramEditor::ErrorMarker));
    EXPECT_EQ(editor.annotation(1), QStringLiteral("first\nsecond"));
}

TEST(ProgramEditor, NewFindingsReplaceTheOldOnes) {
    ProgramEditor editor;
    editor.setText(kText);
    editor.setDiagnostics({{Severity::Error, 2, 1, "old"}});
    editor.setDiagnostics({{Severity::Error, 4, 1, "new"}});
    EXPECT_EQ(editor.markersAtLine(1), 0u);
    EXPECT_TRUE(editor.annotation(1).isEmpty());
    EXPECT_FALSE(underlined(editor, 2, 1));
    EXPECT_TRUE(hasMarker(editor, 4, ProgramEditor::ErrorMarker));
    editor.setDiagnostics({});
    EXPECT_EQ(editor.markersAtLine(3), 0u);
}

TEST(ProgramEditor, FindingsPastTheLastLineShowOnTheLastLine) {
    ProgramEditor editor;
    editor.setText(QStringLiteral("S0.0_0\nQ0.1 = I0.1"));
    editor.setDiagnostics({{Severity::Error, 9, 1, "expected more"}});
    EXPECT_TRUE(hasMarker(editor, 2, ProgramEditor::ErrorMarker));
}

TEST(ProgramEditor, GoToPutsTheCursorAtLineAndColumn) {
    ProgramEditor editor;
    editor.setText(kText);
    editor.goTo(2, 15);
    int line = -1;
    int index = -1;
    editor.getCursorPosition(&line, &index);
    EXPECT_EQ(line, 1);
    EXPECT_EQ(index, 14);
    editor.goTo(3, 99);
    editor.getCursorPosition(&line, &index);
    EXPECT_EQ(line, 2) << "a column past the end stays on its line";
    EXPECT_EQ(index, 11);
}

TEST(ProgramEditor, TextBytesComeBackExactly) {
    ProgramEditor editor;
    // Windows line ends, a tab, trailing spaces and a byte that is not UTF-8.
    const QByteArray bytes("S0.0_0\r\nQ0.1 =\tI0.1   \r\n; caf\xe9\r\n");
    editor.setTextBytes(bytes);
    EXPECT_EQ(editor.textBytes(), bytes);
    EXPECT_FALSE(editor.isModified());
    EXPECT_FALSE(editor.isUndoAvailable());
    EXPECT_EQ(editor.eolMode(), QsciScintilla::EolWindows);
}

TEST(ProgramEditor, ADarkPaletteGivesTheTextADarkBackground) {
    ProgramEditor editor;
    EXPECT_GT(editor.lexer()->paper(0).lightness(), 128);
    rs::ui::applyTheme(rs::ui::Preferences::Theme::Dark);
    QCoreApplication::processEvents(); // palette changes reach widgets as posted events
    EXPECT_LT(editor.lexer()->paper(0).lightness(), 64);
    EXPECT_GT(editor.lexer()->color(0).lightness(), 192);
    rs::ui::applyTheme(rs::ui::Preferences::Theme::Light);
    QCoreApplication::processEvents();
    EXPECT_GT(editor.lexer()->paper(0).lightness(), 128);
}

} // namespace
