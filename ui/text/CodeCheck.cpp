// SPDX-License-Identifier: GPL-3.0-or-later
#include "text/CodeCheck.h"

#include "output/ProjectCompile.h"
#include "project/ProjectFile.h"
#include "project/UnitText.h"

#include <QCoreApplication>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>

namespace rs::ui {

struct CodeCheck::Request {
    // A copy, as the model goes on changing meanwhile: the whole project
    // when what the other units use is not known yet, else all of it but
    // the other units' code.
    project::Project project;
    std::shared_ptr<const std::vector<lang::Address>> usedByOtherUnits; // none: not known
    quint64 generation = 0;
    QString projectPath;
    int station = 0;
    quint64 ticket = 0;
    bool warnUnconfiguredIo = true;
};

CodeCheck::CodeCheck(QObject* parent) : QObject(parent) {
    connect(&m_watcher, &QFutureWatcher<Result>::finished, this, [this] {
        Result result = m_watcher.result();
        if (result.generation == m_generation && !m_otherUnits)
            m_otherUnits = OtherUnits{result.station, result.warnUnconfiguredIo,
                                      std::move(result.usedByOtherUnits)};
        emit checked(result.ticket, result.diagnostics);
        startWaiting();
    });
}

CodeCheck::~CodeCheck() {
    m_watcher.waitForFinished();
}

void CodeCheck::request(const project::Project& project, const QString& projectPath, int station,
                        quint64 ticket) {
    const bool known = m_otherUnits && m_otherUnits->station == station &&
                       m_otherUnits->warnUnconfiguredIo == m_warnUnconfiguredIo;
    if (!known)
        otherCodeChanged();
    m_waiting = std::make_unique<Request>(
        Request{known ? project::withOnlyCodeOf(project, station) : project,
                known ? m_otherUnits->used : nullptr, m_generation, projectPath, station, ticket,
                m_warnUnconfiguredIo});
    startWaiting();
}

void CodeCheck::otherCodeChanged() {
    m_otherUnits.reset();
    ++m_generation;
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
        const int station = request->station;
        const bool known = request->usedByOtherUnits != nullptr;
        const auto used =
            known ? request->usedByOtherUnits
                  : std::make_shared<const std::vector<lang::Address>>(
                        compiler::unitScope(request->project, station, options).usedByOtherUnits);
        const std::string text = project::writeProject(
            known ? request->project : project::withOnlyCodeOf(request->project, station));
        options.onlyUnit = compiler::UnitScope{station, *used};
        const compiler::CompileResult result = compileProjectText(
            text, executableDir, request->projectPath, options, compiler::Output::DiagnosticsOnly);
        lang::Diagnostics found = unitCodeDiagnostics(text, result.diagnostics, station);
        if (found.size() > kMostFindings) {
            std::stable_partition(found.begin(), found.end(), [](const auto& diagnostic) {
                return diagnostic.severity == lang::Severity::Error;
            });
            found.resize(kMostFindings);
            lang::sortByPlace(found);
        }
        return Result{request->ticket,
                      std::move(found),
                      station,
                      request->generation,
                      request->warnUnconfiguredIo,
                      used};
    }));
}

} // namespace rs::ui
