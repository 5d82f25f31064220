// SPDX-License-Identifier: GPL-3.0-or-later
#include "output/CompileRun.h"

#include "compiler/Compiler.h"
#include "compiler/ImageCodec.h"
#include "document/ProjectDocument.h"
#include "document/ProjectPaths.h"
#include "ladder/LadderPage.h"
#include "output/CompileOutput.h"
#include "output/ProjectCompile.h"
#include "project/ProjectFile.h"
#include "text/TextPage.h"

#include <QCoreApplication>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QMainWindow>
#include <QMessageBox>
#include <QProgressBar>
#include <QStatusBar>
#include <QtConcurrent/QtConcurrentRun>

namespace rs::ui {

// What the worker gives back: the findings, and the image written beside the
// project (its path; or why it could not be).
struct CompileRun::Compiled {
    compiler::CompileResult result;
    QString imagePath;
    QString imageError;
};

CompileRun::CompileRun(QMainWindow* window, CompileOutput* output, QDockWidget* outputDock,
                       TextPage* textPage, LadderPage* ladderPage)
    : QObject(window), m_window(window), m_output(output), m_outputDock(outputDock),
      m_textPage(textPage), m_ladderPage(ladderPage), m_progress(new QProgressBar(window)),
      m_watcher(std::make_unique<QFutureWatcher<Compiled>>()) {
    m_progress->setObjectName(QStringLiteral("compileProgress"));
    m_progress->setRange(0, 0); // the compiler reports no steps: busy, not a percentage
    m_progress->setMaximumWidth(140);
    m_progress->setFormat(tr("Compiling"));
    m_progress->hide();
    m_showBusy.setSingleShot(true);
    m_showBusy.setInterval(kBusyAfterMs);
    connect(&m_showBusy, &QTimer::timeout, m_progress, &QWidget::show);
    connect(m_watcher.get(), &QFutureWatcher<Compiled>::finished, this, &CompileRun::finish);
}

CompileRun::~CompileRun() {
    m_watcher->waitForFinished();
}

ProjectDocument* CompileRun::document() const {
    return m_document;
}

void CompileRun::forget(const ProjectDocument* document) {
    if (m_document != document)
        return;
    m_document = nullptr;
    m_output->clear();
    m_outputDock->hide();
}

void CompileRun::start(ProjectDocument* document, const compiler::CheckOptions& options,
                       Image image) {
    if (!document || isRunning())
        return;
    if (m_textPage->document() == document)
        m_textPage->applyNow();
    m_document = document;
    m_running = true;
    m_compiledText = document->isDamaged() ? document->damagedText().toStdString()
                                           : project::writeProject(document->project());
    m_output->showRunning(document->displayName());
    m_outputDock->show();
    m_outputDock->raise();
    m_showBusy.start();
    m_window->statusBar()->showMessage(tr("Compiling %1...").arg(document->displayName()));
    // The image goes beside a project that has a file of its own; it is made
    // and written on the worker too, as a large one takes a while.
    QString imagePath;
    m_checkOnly = image == Image::CheckOnly;
    if (hasOwnFile(*document) && !m_checkOnly) {
        const QFileInfo info(document->path());
        imagePath = info.dir().filePath(info.completeBaseName() + QStringLiteral(".hps"));
    }
    m_watcher->setFuture(QtConcurrent::run([text = m_compiledText, options, imagePath,
                                            executableDir = QCoreApplication::applicationDirPath(),
                                            projectPath = document->path()] {
        Compiled compiled{compileProjectText(text, executableDir, projectPath, options), {}, {}};
        if (compiled.result.errors() == 0 && !imagePath.isEmpty()) {
            try {
                compiled.imageError =
                    project::writeTextFile(imagePath, [&](const project::TextSink& sink) {
                        compiler::writeHps(compiled.result.images, sink);
                    });
            } catch (const std::exception& e) {
                // An image the Intel HEX writer refuses (issue 13): said, not a crash.
                compiled.imageError = QString::fromUtf8(e.what());
            }
            if (compiled.imageError.isEmpty())
                compiled.imagePath = imagePath;
        }
        return compiled;
    }));
    emit runningChanged();
}

void CompileRun::finish() {
    m_running = false;
    m_showBusy.stop();
    m_progress->hide();
    const Compiled compiled = m_watcher->result();
    const compiler::CompileResult& result = compiled.result;
    ProjectDocument* document = m_document;
    if (!document) {
        // Closed while compiling: its result belongs to no open project.
        m_output->clear();
        emit runningChanged();
        return;
    }
    const QString written = QDir::toNativeSeparators(compiled.imagePath);
    m_output->showResult(document->displayName(), m_compiledText, result, written,
                         compiled.imageError);
    if (!compiled.imageError.isEmpty())
        QMessageBox::warning(m_window, tr("Compile"), compiled.imageError);
    if (m_ladderPage->document() == document) {
        // The ladder marks the elements the diagnostics of its unit concern.
        m_ladderPage->setDiagnostics(
            unitCodeDiagnostics(m_compiledText, result.diagnostics, m_ladderPage->station()));
    }
    if (result.errors() == 0 && m_checkOnly)
        emit message(tr("Checked without errors. The compiled file is not written, as the "
                        "project has unsaved changes."));
    else if (result.errors() == 0 && written.isEmpty() && compiled.imageError.isEmpty())
        emit message(tr("Compiled without errors. Save the project to write the compiled file."));
    else
        emit message(m_output->closingLine());
    emit runningChanged();
}

} // namespace rs::ui
