// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/SignatureLabel.h"

#include "compiler/Signature.h"
#include "document/ProjectDocument.h"
#include "output/ProjectCompile.h"
#include "project/ProjectFile.h"

#include <QCoreApplication>
#include <QFutureWatcher>
#include <QtConcurrent/QtConcurrentRun>

#include <map>

namespace rs::ui {

struct SignatureLabel::Result {
    bool ok = false;
    std::map<int, std::uint32_t> units;
    std::uint32_t project = 0;
};

SignatureLabel::SignatureLabel(QWidget* parent)
    : QLabel(parent), m_watcher(std::make_unique<QFutureWatcher<Result>>()) {
    setTextInteractionFlags(Qt::TextSelectableByMouse);
    setToolTip(tr("Changes exactly when what the program does changes; formatting, comments, "
                  "names and descriptions leave it as it is"));
    m_settle.setSingleShot(true);
    m_settle.setInterval(kSettleMs);
    connect(&m_settle, &QTimer::timeout, this, &SignatureLabel::start);
    connect(m_watcher.get(), &QFutureWatcher<Result>::finished, this, &SignatureLabel::finish);
}

SignatureLabel::~SignatureLabel() {
    m_watcher->waitForFinished();
}

void SignatureLabel::setSource(ProjectDocument* document, int station) {
    if (m_document)
        disconnect(m_document, nullptr, this, nullptr);
    m_document = document;
    m_station = station;
    clear();
    if (!document)
        return;
    connect(document, &ProjectDocument::changed, this, [this] {
        setText(tr("computing..."));
        m_settle.start();
    });
    setText(tr("computing..."));
    m_settle.start();
}

bool SignatureLabel::isComputing() const {
    return m_settle.isActive() || m_watcher->isRunning() || m_again ||
           (m_waitsToShow && isVisible());
}

void SignatureLabel::showEvent(QShowEvent* event) {
    QLabel::showEvent(event);
    if (m_waitsToShow)
        m_settle.start();
}

void SignatureLabel::start() {
    if (!m_document)
        return;
    m_waitsToShow = !isVisible();
    if (m_waitsToShow)
        return;
    if (m_watcher->isRunning()) {
        m_again = true;
        return;
    }
    m_watcher->setFuture(QtConcurrent::run([text = project::writeProject(m_document->project()),
                                            executableDir = QCoreApplication::applicationDirPath(),
                                            path = m_document->path()] {
        const compiler::CompileResult compiled =
            compileProjectText(text, executableDir, path, compiler::CheckOptions{});
        Result result;
        result.ok = compiled.errors() == 0;
        for (const compiler::UnitSignature& unit : compiled.signatures)
            result.units[unit.station] = unit.value;
        result.project = compiled.projectSignature;
        return result;
    }));
}

void SignatureLabel::finish() {
    if (m_again) {
        m_again = false;
        start();
        return;
    }
    const Result result = m_watcher->result();
    const auto unit = result.units.find(m_station);
    if (!result.ok)
        setText(tr("none while the project has errors (Build > Compile shows them)"));
    else if (m_station == kProject)
        setText(QString::fromStdString(compiler::signatureText(result.project)));
    else if (unit != result.units.end())
        setText(QString::fromStdString(compiler::signatureText(unit->second)));
    else
        clear();
}

} // namespace rs::ui
