// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#ifndef Q_MOC_RUN
#include "review/ProjectDiff.h"
#endif

#include <QObject>
#include <QPointer>
#include <QTimer>
#include <QWidget>

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <vector>

template <typename T> class QFutureWatcher;

namespace rs::ui {

class ProjectDocument;

// The project as it stands, compiled off the window's thread once a change
// has settled, for what the pages show of it: the program signatures
// (docs/review.md) and what changed since validation. One per document,
// shared by every page that shows any of it; it compiles only while one of
// those pages shows, so a page left behind costs nothing until it shows again.
class SettledCompile : public QObject {
    Q_OBJECT
public:
    static constexpr int kSettleMs = 300;

    struct Outcome {
        bool ok = false; // compiled without errors; nothing below is known otherwise
        std::map<int, std::uint32_t> unitSignatures; // by station
        std::uint32_t projectSignature = 0;
        // What changed since the project's baseline, when it has one.
        std::optional<review::ProjectDiff> sinceValidation;
    };

    // The document's, made when first asked for; it goes with the document.
    static SettledCompile* of(ProjectDocument* document);
    // Waits for a computation still running.
    ~SettledCompile() override;

    // Compiles while this widget shows and, if given, `wants` says it needs
    // an outcome (a ladder page only with a baseline to compare with).
    void addViewer(QWidget* viewer, std::function<bool()> wants = {});
    // Of the project as it is now; nullptr until computed after the last change.
    const Outcome* outcome() const { return m_outcome ? &*m_outcome : nullptr; }
    // An outcome is being computed, or waits for the project to settle.
    bool isComputing() const;

signals:
    // The project changed: outcome() is nullptr until computed() follows.
    void outdated();
    void computed();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    explicit SettledCompile(ProjectDocument* document);
    bool viewerShows() const;
    void start();
    void finish();

    ProjectDocument* m_document;
    struct Viewer {
        QPointer<QWidget> widget;
        std::function<bool()> wants;
    };
    std::vector<Viewer> m_viewers;
    QTimer m_settle;
    std::unique_ptr<QFutureWatcher<Outcome>> m_watcher;
    std::optional<Outcome> m_outcome;
    quint64 m_generation = 0; // of the project; a result of an older one is dropped
    quint64 m_running = 0;    // the generation being compiled
    bool m_again = false;     // settled again while compiling
    // From the start of a compile until its result is taken: the worker's
    // future ends before its finished signal is delivered.
    bool m_compiling = false;
    bool m_waitsToShow = false;
};

} // namespace rs::ui
