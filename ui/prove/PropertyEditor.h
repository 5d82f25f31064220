// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "text/ProgramEditor.h"

#include <QStringList>

#include <functional>
#include <optional>

namespace rs::ui {

// The text of a project's properties: the program editor with the property
// files' colouring, and completion of their keywords and of the project's
// symbolic names and operands, offered as a word's second character is
// typed and whenever complete() is asked for (Ctrl+Space on the page).
class PropertyEditor : public ProgramEditor {
    Q_OBJECT
public:
    static constexpr int kTypedBeforeOffering = 2;

    explicit PropertyEditor(QWidget* parent = nullptr);

    // The project's names and operands, asked for when first needed after
    // forgetWords(): the project changed.
    void setWords(std::function<QStringList()> words);
    void forgetWords();
    // The keywords and words that start as `prefix` does, case aside, sorted.
    QStringList completionsFor(const QString& prefix);
    // Offers the completions of the word before the cursor; false when there are none.
    bool complete();

private:
    void characterAdded(int character);
    QString wordBeforeCursor() const;

    std::function<QStringList()> m_source;
    std::optional<QStringList> m_words;
};

} // namespace rs::ui
