// SPDX-License-Identifier: GPL-3.0-or-later
#include "output/SettledCompile.h"

#include "blocks/ProjectInstances.h"
#include "document/ProjectDocument.h"
#include "project/ProjectFile.h"
#include "review/Validation.h"

#include <QCoreApplication>
#include <QEvent>
#include <QFutureWatcher>
#include <QtConcurrent/QtConcurrentRun>

namespace rs::ui {

namespace {

SettledCompile::Outcome compileSettled(const std::string& text, const QString& executableDir,
                                       const QString& projectPath) {
    // As Mark as Validated and `rungsmith-cli validate` read it: with its instances expanded.
    const blocks::ProjectWithInstances read = blocks::readProjectWithInstances(
        text, blocks::LibraryPlaces{executableDir, projectPath, {}});
    const compiler::CompileResult compiled =
        blocks::compileProject(read.read.project, read.read.diagnostics, {}, text);
    SettledCompile::Outcome outcome;
    outcome.ok = compiled.errors() == 0;
    if (!outcome.ok)
        return outcome;
    for (const compiler::UnitSignature& unit : compiled.signatures)
        outcome.unitSignatures[unit.station] = unit.value;
    outcome.projectSignature = compiled.projectSignature;
    if (read.read.project.baseline)
        outcome.sinceValidation = review::changesSinceValidation(read.read.project, compiled);
    return outcome;
}

} // namespace

SettledCompile* SettledCompile::of(ProjectDocument* document) {
    if (auto* existing =
            document->findChild<SettledCompile*>(QString(), Qt::FindDirectChildrenOnly))
        return existing;
    return new SettledCompile(document);
}

SettledCompile::SettledCompile(ProjectDocument* document)
    : QObject(document), m_document(document),
      m_watcher(std::make_unique<QFutureWatcher<Outcome>>()) {
    m_settle.setSingleShot(true);
    m_settle.setInterval(kSettleMs);
    connect(&m_settle, &QTimer::timeout, this, &SettledCompile::start);
    connect(m_watcher.get(), &QFutureWatcher<Outcome>::finished, this, &SettledCompile::finish);
    connect(document, &ProjectDocument::changed, this, [this] {
        ++m_generation;
        m_outcome.reset();
        emit outdated();
        m_settle.start();
    });
    m_settle.start();
}

SettledCompile::~SettledCompile() {
    m_watcher->waitForFinished();
}

void SettledCompile::addViewer(QWidget* viewer, std::function<bool()> wants) {
    for (const Viewer& known : m_viewers)
        if (known.widget == viewer)
            return;
    m_viewers.push_back({viewer, std::move(wants)});
    viewer->installEventFilter(this);
    if (m_waitsToShow && viewer->isVisible())
        m_settle.start();
}

bool SettledCompile::viewerShows() const {
    for (const Viewer& viewer : m_viewers)
        if (viewer.widget && viewer.widget->isVisible() && (!viewer.wants || viewer.wants()))
            return true;
    return false;
}

bool SettledCompile::isComputing() const {
    return m_settle.isActive() || m_compiling || m_again || (m_waitsToShow && viewerShows());
}

bool SettledCompile::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::Show && m_waitsToShow)
        m_settle.start();
    return QObject::eventFilter(watched, event);
}

void SettledCompile::start() {
    m_waitsToShow = !viewerShows();
    if (m_waitsToShow)
        return;
    if (m_compiling) {
        m_again = true;
        return;
    }
    m_compiling = true;
    m_running = m_generation;
    m_watcher->setFuture(
        QtConcurrent::run(compileSettled, project::writeProject(m_document->project()),
                          QCoreApplication::applicationDirPath(), m_document->path()));
}

void SettledCompile::finish() {
    m_compiling = false;
    if (m_running == m_generation) {
        m_outcome = m_watcher->result();
        emit computed();
    }
    if (m_again) {
        m_again = false;
        start();
    }
}

} // namespace rs::ui
