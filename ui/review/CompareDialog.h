// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "review/ProjectComparison.h"

#include <QDialog>
#include <QFutureWatcher>
#include <QStringList>

#include <optional>

class QLabel;
class QListWidget;
class QPushButton;

namespace rs::ui {

class ProjectDocument;

// Project > Compare With... and Compare With Validated (issue 18,
// docs/review.md): what `rungsmith-cli diff` says of another version and the
// project as it is now, or what changed since validation, in the window's
// language. The comparison runs off the window's thread. A network's line
// opens it in the ladder; a comparison with a file is saved as the review PDF
// `diff --pdf` writes.
class CompareDialog : public QDialog {
    Q_OBJECT
public:
    // `oldPath` empty: with the document's baseline, which it must have.
    CompareDialog(ProjectDocument* document, const QString& oldPath, QWidget* parent = nullptr);
    // Waits for a comparison still running.
    ~CompareDialog() override;

    bool isComparing() const { return m_watcher.isRunning(); }
    // The lines shown, then the verdict (or why nothing could be compared).
    QStringList lines() const;
    QString verdict() const;
    // Writes the review; returns the error message, empty on success.
    QString savePdf(const QString& path);

signals:
    // A network's line was opened (Enter or a double click); number from 1.
    void networkChosen(int station, int sequence, int step, int number);

private:
    void showComparison();
    void choosePdf();

    QLabel* m_heading;
    QListWidget* m_lines;
    QLabel* m_verdict;
    QPushButton* m_pdf;
    QFutureWatcher<ProjectComparison> m_watcher;
    std::optional<ProjectComparison> m_comparison;
};

} // namespace rs::ui
