// SPDX-License-Identifier: GPL-3.0-or-later
#include "text/ProgramEditor.h"

#include "lang/Lexer.h"
#include "shell/StatusColors.h"
#include "text/PlutoLexer.h"

#include <Qsci/qscicommand.h>
#include <Qsci/qscicommandset.h>
#include <Qsci/qscistyledtext.h>

#include <QApplication>
#include <QIcon>

#include <algorithm>
#include <map>
#include <string_view>
#include <vector>

namespace rs::ui {

namespace {

// Style numbers above the lexer's and Scintilla's predefined ones (32..39).
constexpr int kErrorAnnotationStyle = 64;
constexpr int kWarningAnnotationStyle = 65;

constexpr int kMarkerIconSize = 14;

QFont annotationFont() {
    QFont font = QApplication::font();
    font.setPointSizeF(font.pointSizeF() * 0.95);
    return font;
}

} // namespace

ProgramEditor::ProgramEditor(QWidget* parent) : ProgramEditor(new PlutoLexer, parent) {}

ProgramEditor::ProgramEditor(PlutoLexer* lexer, QWidget* parent)
    : QsciScintilla(parent), m_lexer(lexer),
      m_errorAnnotation(kErrorAnnotationStyle, tr("Error message"), QColor(0x82071e),
                        QColor(0xffebe9), annotationFont()),
      m_warningAnnotation(kWarningAnnotationStyle, tr("Warning message"), QColor(0x6b4400),
                          QColor(0xfff8c5), annotationFont()) {
    m_lexer->setParent(this);
    setUtf8(true);
    setLexer(m_lexer);
    SendScintilla(SCI_SETWORDCHARS, m_lexer->wordCharacters());
    setTabWidth(4);
    setIndentationsUseTabs(false);
    // The horizontal scroll bar follows the longest line instead of a fixed width.
    SendScintilla(SCI_SETSCROLLWIDTH, 1);
    SendScintilla(SCI_SETSCROLLWIDTHTRACKING, 1);
    SendScintilla(SCI_SETMARGINLEFT, 0UL, 6L);

    const QFont textFont = m_lexer->defaultFont(PlutoLexer::Default);
    setMarginsFont(textFont);
    setMarginType(MarkerMargin, SymbolMargin);
    setMarginWidth(MarkerMargin, kMarkerIconSize + 8);
    setMarginMarkerMask(MarkerMargin, (1 << ErrorMarker) | (1 << WarningMarker));
    setMarginType(LineNumberMargin, NumberMargin);
    setMarginMarkerMask(LineNumberMargin, 0);
    setMarginLineNumbers(LineNumberMargin, true);
    fitLineNumberMargin();
    connect(this, &QsciScintilla::linesChanged, this, &ProgramEditor::fitLineNumberMargin);

    setCaretLineVisible(true);
    setBraceMatching(SloppyBraceMatch);
    applyColors();

    defineMarkers();
    setAnnotationDisplay(AnnotationBoxed);
}

void ProgramEditor::applyColors() {
    // The editor's colours are its own, not the palette's: a light and a dark set.
    const bool dark = isDark(palette());
    m_lexer->setDark(dark);
    setMarginsBackgroundColor(QColor(dark ? 0x2b2d31 : 0xf6f8fa));
    setMarginsForegroundColor(QColor(dark ? 0x6e7681 : 0x8c959f));
    setCaretForegroundColor(QColor(dark ? 0xe6edf3 : 0x1f2328));
    setCaretLineBackgroundColor(QColor(dark ? 0x26282c : 0xf3f6fa));
    setMatchedBraceBackgroundColor(QColor(dark ? 0x3b5070 : 0xd8e6ff));
    setMatchedBraceForegroundColor(QColor(dark ? 0x79c0ff : 0x0550ae));
    setUnmatchedBraceForegroundColor(QColor(dark ? 0xff7b72 : 0xcf222e));
    setSelectionBackgroundColor(QColor(dark ? 0x264f78 : 0xb6d7ff));
    m_errorAnnotation.setColor(QColor(dark ? 0xffa198 : 0x82071e));
    m_errorAnnotation.setPaper(QColor(dark ? 0x3d1418 : 0xffebe9));
    m_warningAnnotation.setColor(QColor(dark ? 0xe3b341 : 0x6b4400));
    m_warningAnnotation.setPaper(QColor(dark ? 0x3a2e0f : 0xfff8c5));
}

void ProgramEditor::changeEvent(QEvent* event) {
    QsciScintilla::changeEvent(event);
    if (event->type() == QEvent::PaletteChange)
        applyColors();
}

void ProgramEditor::defineMarkers() {
    const auto image = [this](const char* path) {
        return QIcon(QString::fromLatin1(path))
            .pixmap(QSize(kMarkerIconSize, kMarkerIconSize), devicePixelRatioF())
            .toImage();
    };
    markerDefine(image(":/icons/error.svg"), ErrorMarker);
    markerDefine(image(":/icons/warning.svg"), WarningMarker);

    m_errorIndicator = indicatorDefine(SquigglePixmapIndicator);
    setIndicatorForegroundColor(QColor(0xd1242f), m_errorIndicator);
    m_warningIndicator = indicatorDefine(SquigglePixmapIndicator);
    setIndicatorForegroundColor(QColor(0xbf8700), m_warningIndicator);
}

void ProgramEditor::fitLineNumberMargin() {
    // One digit of slack so the margin does not jump while typing line 99 → 100.
    setMarginWidth(LineNumberMargin,
                   QString(QString::number(lines()).size() + 1, QLatin1Char('9')));
}

QByteArray ProgramEditor::textBytes() const {
    const auto* text = static_cast<const char*>(SendScintillaPtrResult(SCI_GETCHARACTERPOINTER));
    return QByteArray(text, length());
}

void ProgramEditor::setDiagnostics(const lang::Diagnostics& diagnostics) {
    markerDeleteAll();
    clearAnnotations();
    for (int indicator : {m_errorIndicator, m_warningIndicator}) {
        SendScintilla(SCI_SETINDICATORCURRENT, indicator);
        SendScintilla(SCI_INDICATORCLEARRANGE, 0UL, static_cast<long>(length()));
    }

    // A line may have several findings: one annotation lists them all.
    std::map<int, std::vector<const lang::Diagnostic*>> byLine;
    for (const auto& diagnostic : diagnostics) {
        if (diagnostic.line <= 0)
            continue;
        byLine[std::min(diagnostic.line, lines())].push_back(&diagnostic);
    }
    for (const auto& [line, found] : byLine) {
        QList<QsciStyledText> annotation;
        bool hasError = false;
        for (const lang::Diagnostic* diagnostic : found) {
            const bool error = diagnostic->severity == lang::Severity::Error;
            hasError = hasError || error;
            QString message = QString::fromStdString(diagnostic->message);
            if (diagnostic != found.back())
                message += QLatin1Char('\n');
            annotation.append(
                QsciStyledText(message, error ? m_errorAnnotation : m_warningAnnotation));
            underline(line, diagnostic->column, error ? m_errorIndicator : m_warningIndicator);
        }
        markerAdd(line - 1, hasError ? ErrorMarker : WarningMarker);
        annotate(line - 1, annotation);
    }
}

// Squiggles the token a finding points at, as the language's lexer reads the
// line; a column inside a token (a record's attribute) gets the word there.
void ProgramEditor::underline(int line, int column, int indicator) {
    const int lineStart = positionFromLineIndex(line - 1, 0);
    const auto lineEnd = static_cast<int>(SendScintilla(SCI_GETLINEENDPOSITION, line - 1));
    if (lineEnd == lineStart)
        return;
    int from = positionFromLineIndex(line - 1, std::max(column, 1) - 1);
    if (from >= lineEnd) // "found the end of the line": mark the last character
        from = static_cast<int>(
            SendScintilla(SCI_POSITIONBEFORE, static_cast<unsigned long>(lineEnd)));

    const auto* document =
        static_cast<const char*>(SendScintillaPtrResult(SCI_GETCHARACTERPOINTER));
    const std::string_view lineText(document + lineStart,
                                    static_cast<std::size_t>(lineEnd - lineStart));
    int to = from;
    lang::Lexer lexer(lineText);
    for (lang::Token token = lexer.next(); token.kind != lang::TokenKind::EndOfFile;
         token = lexer.next()) {
        auto begin = static_cast<int>(token.text.data() - lineText.data());
        if (token.kind == lang::TokenKind::Comment)
            --begin; // the token's text starts after the ';'
        if (lineStart + begin == from) {
            const auto end =
                static_cast<int>(token.text.data() + token.text.size() - lineText.data());
            to = lineStart + end;
            break;
        }
    }
    if (to <= from)
        to = static_cast<int>(
            SendScintilla(SCI_WORDENDPOSITION, static_cast<unsigned long>(from), 1L));
    if (to <= from)
        to = static_cast<int>(SendScintilla(SCI_POSITIONAFTER, static_cast<unsigned long>(from)));
    SendScintilla(SCI_SETINDICATORCURRENT, indicator);
    SendScintilla(SCI_INDICATORFILLRANGE, static_cast<unsigned long>(from),
                  static_cast<long>(to - from));
}

void ProgramEditor::setTextBytes(const QByteArray& text) {
    // Handed to Scintilla as bytes, not through QString, so that a file with
    // bytes that are not UTF-8 is saved back unchanged.
    SendScintilla(SCI_CLEARALL);
    SendScintilla(SCI_APPENDTEXT, static_cast<unsigned long>(text.size()), text.constData());
    setEolMode(text.contains("\r\n") ? EolWindows : EolUnix);
    SendScintilla(SCI_EMPTYUNDOBUFFER);
    setModified(false);
    SendScintilla(SCI_GOTOPOS, 0UL);
}

void ProgramEditor::setProjectUndo(bool projectUndo) {
    SendScintilla(SCI_SETUNDOCOLLECTION, projectUndo ? 0UL : 1UL);
    SendScintilla(SCI_EMPTYUNDOBUFFER);
    for (auto command : {QsciCommand::Undo, QsciCommand::Redo}) {
        QsciCommand* bound = standardCommands()->find(command);
        if (projectUndo) {
            bound->setKey(0);
            bound->setAlternateKey(0);
        } else {
            const bool undo = command == QsciCommand::Undo;
            // QScintilla's own bindings.
            bound->setKey((undo ? Qt::CTRL | Qt::Key_Z : Qt::CTRL | Qt::Key_Y).toCombined());
            bound->setAlternateKey(
                (undo ? Qt::ALT | Qt::Key_Backspace : Qt::CTRL | Qt::SHIFT | Qt::Key_Z)
                    .toCombined());
        }
    }
}

void ProgramEditor::goTo(int line, int column) {
    const int lineIndex = std::clamp(line, 1, std::max(lines(), 1)) - 1;
    // A target out of view is shown a third down the page, with its context above.
    const auto displayLine = SendScintilla(SCI_VISIBLEFROMDOCLINE, lineIndex);
    const auto firstShown = SendScintilla(SCI_GETFIRSTVISIBLELINE);
    const auto shownLines = SendScintilla(SCI_LINESONSCREEN);
    if (displayLine < firstShown || displayLine >= firstShown + shownLines)
        setFirstVisibleLine(static_cast<int>(std::max(0L, displayLine - shownLines / 3)));
    const auto lineEnd = static_cast<int>(SendScintilla(SCI_GETLINEENDPOSITION, lineIndex));
    const int position =
        std::min(positionFromLineIndex(lineIndex, std::max(column, 1) - 1), lineEnd);
    SendScintilla(SCI_GOTOPOS, static_cast<unsigned long>(position));
    setFocus(Qt::OtherFocusReason);
}

} // namespace rs::ui
