// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>
#include <QPointer>
#include <QTimer>

#include <memory>
#include <string>

class QDockWidget;
class QMainWindow;
class QProgressBar;
template <typename T> class QFutureWatcher;

namespace rs::compiler {
struct CheckOptions;
}

namespace rs::ui {

class CompileOutput;
class LadderPage;
class ProjectDocument;
class TextPage;

// Build > Compile: one compile at a time, off the window's thread. The
// project's text is taken as it is when the compile starts (with the text
// page's typing read in), checked and compiled on a worker, which also writes
// the image (.hps) beside a project that has a file of its own. A busy bar
// shows in the status bar once it has run kBusyAfterMs; then the Output dock
// shows the result and the ladder page marks the elements that the
// diagnostics of its unit concern.
class CompileRun : public QObject {
    Q_OBJECT
public:
    // The busy bar's animation repaints the window tens of times a second,
    // which slowed a large project's compile by a third; a compile that ends
    // sooner than this shows none (the status bar and the Output say it runs).
    static constexpr int kBusyAfterMs = 500;

    CompileRun(QMainWindow* window, CompileOutput* output, QDockWidget* outputDock,
               TextPage* textPage, LadderPage* ladderPage);
    // Waits for a compile still running.
    ~CompileRun() override;

    // What becomes of the image of a compile without errors.
    enum class Image {
        Write,    // written beside a project that has a file of its own
        CheckOnly // not written: the project's file is older than what is compiled
    };
    // Starts compiling the project; nothing while a compile runs.
    void start(ProjectDocument* document, const compiler::CheckOptions& options,
               Image image = Image::Write);
    // From start until the result is shown.
    bool isRunning() const { return m_running; }
    // The project compiled last, whose places the Output dock lists; null once closed.
    ProjectDocument* document() const;
    // The project is closing: its result leaves the Output dock, which goes too.
    void forget(const ProjectDocument* document);
    // The status bar's busy bar, shown while a compile runs longer than kBusyAfterMs.
    QProgressBar* progressBar() const { return m_progress; }

signals:
    // A compile started, or its result is shown.
    void runningChanged();
    // A line for the status bar.
    void message(const QString& message);

private:
    struct Compiled;
    void finish();

    QMainWindow* m_window;
    CompileOutput* m_output;
    QDockWidget* m_outputDock;
    TextPage* m_textPage;
    LadderPage* m_ladderPage;
    QProgressBar* m_progress;
    QTimer m_showBusy;
    std::unique_ptr<QFutureWatcher<Compiled>> m_watcher;
    QPointer<ProjectDocument> m_document;
    bool m_running = false;
    bool m_checkOnly = false;
    std::string m_compiledText;
};

} // namespace rs::ui
