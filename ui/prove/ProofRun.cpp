// SPDX-License-Identifier: GPL-3.0-or-later
#include "prove/ProofRun.h"

#include "document/ProjectDocument.h"
#include "output/ProjectCompile.h"
#include "project/ProjectFile.h"
#include "prove/Counterexample.h"
#include "prove/Prover.h"
#include "sim/Scenario.h"

#include <QCoreApplication>
#include <QtConcurrent/QtConcurrentRun>

#include <atomic>
#include <mutex>

namespace rs::ui {

namespace {

// How often the window hears how far the run got.
constexpr int kPollMs = 100;

// The prover's reason for the user, in the window's language where it is one
// the prover gives every time.
QString reasonOf(const prove::Verdict& verdict, const prove::ProofOptions& options) {
    switch (verdict.why) {
    case prove::Verdict::Why::Cancelled:
        return ProofRun::tr("cancelled");
    case prove::Verdict::Why::TimeLimit:
        return ProofRun::tr("the time limit of %n s per property ran out", nullptr,
                            static_cast<int>(options.timeLimit.count() / 1000));
    case prove::Verdict::Why::DepthReached:
        return ProofRun::tr("no counterexample within %n scans", nullptr, verdict.depth);
    case prove::Verdict::Why::NotRepeated:
    case prove::Verdict::Why::None:
        break;
    }
    return QString::fromStdString(verdict.reason);
}

PropertyProof::Status statusOf(prove::Verdict::Status status) {
    switch (status) {
    case prove::Verdict::Status::Proved:
        return PropertyProof::Status::Proved;
    case prove::Verdict::Status::Failed:
        return PropertyProof::Status::Failed;
    case prove::Verdict::Status::Covered:
        return PropertyProof::Status::Covered;
    case prove::Verdict::Status::Unreachable:
        return PropertyProof::Status::NeverCovered;
    case prove::Verdict::Status::Unknown:
        break;
    }
    return PropertyProof::Status::Unknown;
}

} // namespace

// What the worker needs, made on the window's thread, and what it finds.
struct ProofRun::Job {
    explicit Job(sim::OperandNames operandNames) : names(std::move(operandNames)) {}

    std::string projectText;
    QString executableDir;
    QString projectPath;
    compiler::CheckOptions checkOptions;
    prove::PropertyFile file;
    std::string fileName;
    sim::OperandNames names;
    std::atomic<bool> cancel = false;
    std::atomic<int> current = 0; // the property being proved: how many are done
    int total = 0;
    int compileErrors = 0;
    std::mutex mutex; // guards proofs
    std::vector<PropertyProof> proofs;

    void run();
    PropertyProof proof(const std::vector<compiler::UnitImage>& images,
                        const prove::Verdict& verdict, const prove::ProofOptions& options);
};

void ProofRun::Job::run() {
    const compiler::CompileResult compiled =
        compileProjectText(projectText, executableDir, projectPath, checkOptions);
    if (compiled.errors()) {
        compileErrors = compiled.errors();
        return;
    }
    prove::ProofOptions options;
    options.cancelled = [this] {
        return cancel.load(std::memory_order_relaxed);
    };
    options.verdictFound = [&](const prove::Verdict& verdict) {
        if (cancel) // the solver stopped early: what it says is no finding
            return;
        PropertyProof proof = this->proof(compiled.images, verdict, options);
        const std::lock_guard lock(mutex);
        proofs.push_back(std::move(proof));
        current = static_cast<int>(proofs.size());
    };
    prove::proveProperties(compiled.images, file, options);
}

PropertyProof ProofRun::Job::proof(const std::vector<compiler::UnitImage>& images,
                                   const prove::Verdict& verdict,
                                   const prove::ProofOptions& options) {
    const prove::Property& property = *verdict.property;
    PropertyProof proof;
    proof.line = property.line;
    proof.text = QString::fromStdString(property.text).trimmed();
    proof.status = statusOf(verdict.status);
    proof.depth = verdict.depth;
    if (proof.status == PropertyProof::Status::Unknown)
        proof.reason = reasonOf(verdict, options);
    if (proof.status == PropertyProof::Status::Failed ||
        proof.status == PropertyProof::Status::Covered) {
        const prove::CounterexampleScenario scenario =
            prove::writeCounterexample(images, file, verdict, names, fileName);
        if (scenario.reproduced) {
            proof.scenario = QString::fromStdString(scenario.text);
        } else {
            proof.reason =
                (proof.status == PropertyProof::Status::Failed
                     ? ProofRun::tr(
                           "internal error: the prover's counterexample of %n scans does not "
                           "replay (%1); please report it",
                           nullptr, verdict.depth)
                     : ProofRun::tr(
                           "internal error: the prover's witness of %n scans does not replay "
                           "(%1); please report it",
                           nullptr, verdict.depth))
                    .arg(QString::fromStdString(scenario.problem));
            proof.status = PropertyProof::Status::Unknown;
        }
    }
    return proof;
}

ProofRun::ProofRun(QObject* parent) : QObject(parent) {
    m_poll.setInterval(kPollMs);
    connect(&m_poll, &QTimer::timeout, this, [this] {
        takeProofs();
        if (m_job)
            emit progress(m_job->current, m_job->total);
    });
    connect(&m_watcher, &QFutureWatcher<void>::finished, this, &ProofRun::done);
}

ProofRun::~ProofRun() {
    if (m_job) {
        m_job->cancel = true;
        m_watcher.waitForFinished();
    }
}

bool ProofRun::start(ProjectDocument* document, const prove::PropertyFile& file,
                     const QString& fileName, const compiler::CheckOptions& options) {
    if (m_job || !document)
        return false;
    auto job = std::make_shared<Job>(sim::OperandNames(document->project()));
    job->projectText = project::writeProject(document->project());
    job->executableDir = QCoreApplication::applicationDirPath();
    job->projectPath = document->path();
    job->checkOptions = options;
    job->file = file;
    job->fileName = fileName.toStdString();
    m_properties.clear();
    for (const prove::Property& property : file.properties)
        if (property.kind != prove::Property::Kind::Assume)
            m_properties.push_back(property);
    job->total = static_cast<int>(m_properties.size());
    m_proofs.clear();
    m_job = job;
    m_watcher.setFuture(QtConcurrent::run([job] { job->run(); }));
    m_poll.start();
    return true;
}

void ProofRun::cancel() {
    if (m_job)
        m_job->cancel = true;
}

void ProofRun::takeProofs() {
    if (!m_job)
        return;
    const std::lock_guard lock(m_job->mutex);
    for (std::size_t i = m_proofs.size(); i < m_job->proofs.size(); ++i)
        m_proofs.push_back(m_job->proofs[i]);
}

void ProofRun::done() {
    if (!m_job || !m_watcher.isFinished())
        return;
    m_poll.stop();
    takeProofs();
    const std::shared_ptr<Job> job = std::exchange(m_job, nullptr);
    const QString error = job->compileErrors
                              ? tr("The project has %n error(s); compile it (F7) to see them.",
                                   nullptr, job->compileErrors)
                              : QString();
    emit finished(error, job->cancel && error.isEmpty());
}

} // namespace rs::ui
