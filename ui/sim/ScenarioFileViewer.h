// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>

class QLabel;
class QPlainTextEdit;

namespace rs::ui {

// A scenario file shown read-only with one line marked: where a failure of a
// run points. Scenarios are written in a text editor of the user's choice, so
// this only shows them; "Open in Editor" hands the file to the system's editor.
class ScenarioFileViewer : public QDialog {
    Q_OBJECT
public:
    explicit ScenarioFileViewer(QWidget* parent = nullptr);

    // Loads the file (again) and marks the line; the error message when it cannot be read.
    QString showLine(const QString& path, int line);
    int currentLine() const;
    QPlainTextEdit* text() const { return m_text; }

private:
    QPlainTextEdit* m_text;
    QLabel* m_where;
    QString m_path;
};

} // namespace rs::ui
