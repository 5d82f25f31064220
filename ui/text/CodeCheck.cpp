// SPDX-License-Identifier: GPL-3.0-or-later
#include "text/CodeCheck.h"

#include "output/ProjectCompile.h"
#include "project/ProjectFile.h"

#include <QCoreApplication>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>

namespace rs::ui {

struct CodeCheck::Request {
    project::Project project; // a copy: the model goes on changing meanwhile
    QString projectPath;
    int station = 0;
    quint64 ticket = 0;
    bool warnUnconfiguredIo = true;
};

CodeCheck::CodeCheck(QObject* parent) : QObject(parent) {
    connect(&m_watcher, &QFutureWatcher<Result>::finished, this, [this] {
        const Result result = m_watcher.result();
        emit checked(result.ticket, result.diagnostics);
        startWaiting();
    });
}

CodeCheck::~CodeCheck() {
    m_watcher.waitForFinished();
}

void CodeCheck::request(const project::Project& project, const QString& projectPath, int station,
                        quint64 ticket) {
    m_waiting = std::make_unique<Request>(
        Request{project, projectPath, station, ticket, m_warnUnconfiguredIo});
    startWaiting();
}

bool CodeCheck::isBusy() const {
    return m_watcher.isRunning() || m_waiting;
}

void CodeCheck::startWaiting() {
    if (m_watcher.isRunning() || !m_waiting)
        return;
    m_watcher.setFuture(QtConcurrent::run([request = std::shared_ptr<Request>(std::move(m_waiting)),
                                           executableDir = QCoreApplication::applicationDirPath()] {
        compiler::CheckOptions options;
        options.warnUnconfiguredIo = request->warnUnconfiguredIo;
        const std::string text = project::writeProject(request->project);
        const compiler::CompileResult result =
            compileProjectText(text, executableDir, request->projectPath, options);
        lang::Diagnostics found = unitCodeDiagnostics(text, result.diagnostics, request->station);
        if (found.size() > kMostFindings) {
            std::stable_partition(found.begin(), found.end(), [](const auto& diagnostic) {
                return diagnostic.severity == lang::Severity::Error;
            });
            found.resize(kMostFindings);
            lang::sortByPlace(found);
        }
        return Result{request->ticket, std::move(found)};
    }));
}

} // namespace rs::ui
