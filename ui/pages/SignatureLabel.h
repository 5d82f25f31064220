// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QLabel>
#include <QPointer>
#include <QTimer>

#include <memory>

template <typename T> class QFutureWatcher;

namespace rs::ui {

class ProjectDocument;

// A page's line with a program signature (docs/review.md): the project's or
// one unit's, of the project as it is now, what `rungsmith-cli signature`
// prints. The compiler makes it off the window's thread once a change has
// settled, and only while the label shows: a page left behind keeps its
// document but compiles nothing until it shows again. While the project has
// errors there is none, and the line says so.
class SignatureLabel : public QLabel {
    Q_OBJECT
public:
    static constexpr int kProject = -1;
    static constexpr int kSettleMs = 300;

    explicit SignatureLabel(QWidget* parent = nullptr);
    // Waits for a computation still running.
    ~SignatureLabel() override;

    // The project's signature (kProject) or the unit's with this station.
    void setSource(ProjectDocument* document, int station);
    // A signature is being computed, or waits for the project to settle.
    bool isComputing() const;

protected:
    void showEvent(QShowEvent* event) override;

private:
    struct Result;
    void start();
    void finish();

    QPointer<ProjectDocument> m_document;
    int m_station = kProject;
    QTimer m_settle;
    std::unique_ptr<QFutureWatcher<Result>> m_watcher;
    bool m_again = false;       // the project changed while computing
    bool m_waitsToShow = false; // the project changed while hidden
};

} // namespace rs::ui
