// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/Diagnostic.h"

#include <Qsci/qsciscintilla.h>
#include <Qsci/qscistyle.h>

namespace rs::ui {

class PlutoLexer;

// The text view of a project: Pluto syntax colouring, line numbers, and the
// checker's findings shown where they are (margin icon, squiggle under the
// offending token, message below the line).
class ProgramEditor : public QsciScintilla {
    Q_OBJECT
public:
    enum Marker { ErrorMarker = 0, WarningMarker = 1 };
    enum Margin { MarkerMargin = 0, LineNumberMargin = 1 };

    explicit ProgramEditor(QWidget* parent = nullptr);
    // Colours the text with another lexer (a property file's); the editor owns it.
    ProgramEditor(PlutoLexer* lexer, QWidget* parent);

    // Replaces the shown findings. Lines and columns are 1-based, as the
    // checker reports them.
    void setDiagnostics(const lang::Diagnostics& diagnostics);

    // Puts the cursor at a 1-based line and column and scrolls it into view.
    void goTo(int line, int column);

    // The whole text, byte for byte as a file holds it.
    QByteArray textBytes() const;

    // Replaces the text with a file's bytes; undo history starts afresh and
    // the text counts as unmodified.
    void setTextBytes(const QByteArray& text);

    // With the project's undo, the editor keeps no undo history of its own and
    // leaves the undo and redo keys to the window's Edit menu.
    void setProjectUndo(bool projectUndo);

protected:
    void changeEvent(QEvent* event) override;

private:
    void applyColors();
    void defineMarkers();
    void fitLineNumberMargin();
    void underline(int line, int column, int indicator);

    PlutoLexer* m_lexer;
    QsciStyle m_errorAnnotation;
    QsciStyle m_warningAnnotation;
    int m_errorIndicator = -1;
    int m_warningIndicator = -1;
};

} // namespace rs::ui
