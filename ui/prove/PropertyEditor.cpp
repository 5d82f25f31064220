// SPDX-License-Identifier: GPL-3.0-or-later
#include "prove/PropertyEditor.h"

#include "prove/PropertyLexer.h"
#include "prove/PropertyWords.h"

#include <QChar>

namespace rs::ui {

namespace {

// Between the offered words: no name or operand holds a line break.
constexpr char kSeparator = '\n';

} // namespace

PropertyEditor::PropertyEditor(QWidget* parent) : ProgramEditor(new PropertyLexer, parent) {
    SendScintilla(SCI_AUTOCSETIGNORECASE, 1UL);
    SendScintilla(SCI_AUTOCSETCASEINSENSITIVEBEHAVIOUR, SC_CASEINSENSITIVEBEHAVIOUR_IGNORECASE);
    SendScintilla(SCI_AUTOCSETAUTOHIDE, 1UL);
    connect(this, &QsciScintillaBase::SCN_CHARADDED, this, &PropertyEditor::characterAdded);
}

void PropertyEditor::setWords(std::function<QStringList()> words) {
    m_source = std::move(words);
    m_words.reset();
}

void PropertyEditor::forgetWords() {
    m_words.reset();
}

QStringList PropertyEditor::completionsFor(const QString& prefix) {
    if (!m_words) {
        QStringList words;
        for (std::string_view keyword : propertyKeywords())
            words << QString::fromLatin1(keyword.data(), static_cast<qsizetype>(keyword.size()));
        if (m_source)
            words << m_source();
        words.removeDuplicates();
        words.sort(Qt::CaseInsensitive);
        m_words = std::move(words);
    }
    QStringList found;
    for (const QString& word : *m_words)
        if (word.startsWith(prefix, Qt::CaseInsensitive) && word.size() > prefix.size())
            found << word;
    return found;
}

QString PropertyEditor::wordBeforeCursor() const {
    const auto position = static_cast<unsigned long>(SendScintilla(SCI_GETCURRENTPOS));
    const auto start =
        static_cast<unsigned long>(SendScintilla(SCI_WORDSTARTPOSITION, position, 1L));
    return text(static_cast<int>(start), static_cast<int>(position));
}

bool PropertyEditor::complete() {
    const QString prefix = wordBeforeCursor();
    const QStringList words = completionsFor(prefix);
    if (words.isEmpty()) {
        SendScintilla(SCI_AUTOCCANCEL);
        return false;
    }
    SendScintilla(SCI_AUTOCSETSEPARATOR, static_cast<unsigned long>(kSeparator));
    SendScintilla(SCI_AUTOCSETORDER, SC_ORDER_PERFORMSORT);
    const QByteArray list = words.join(QLatin1Char(kSeparator)).toUtf8();
    SendScintilla(SCI_AUTOCSHOW, static_cast<unsigned long>(prefix.toUtf8().size()),
                  list.constData());
    return true;
}

void PropertyEditor::characterAdded(int character) {
    if (SendScintilla(SCI_AUTOCACTIVE) != 0 || isReadOnly())
        return;
    const QChar typed(character);
    if (!typed.isLetterOrNumber() && typed != QLatin1Char('_'))
        return;
    if (wordBeforeCursor().size() == kTypedBeforeOffering)
        complete();
}

} // namespace rs::ui
