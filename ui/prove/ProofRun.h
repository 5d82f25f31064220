// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Holds core types by value; Qt 6.4's moc cannot parse the C++20 standard
// headers they bring in and needs only the names.
#ifndef Q_MOC_RUN
#include "compiler/ProgramCheck.h"
#include "prove/PropertyFile.h"
#endif

#include <QFutureWatcher>
#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>
#include <vector>

namespace rs::ui {

class ProjectDocument;

// What the prover found for one property (a line of the file that is not an assumption).
struct PropertyProof {
    enum class Status {
        Proved,       // for every input sequence
        Failed,       // `scenario` breaks it
        Unknown,      // neither, `reason` says why
        Covered,      // a cover: `scenario` reaches it
        NeverCovered, // a cover proved unreachable
    };
    int line = 0;
    QString text; // as written, without its comment
    Status status = Status::Unknown;
    int depth = 0;    // scans: of the counterexample, the witness, or the proof
    QString reason;   // Unknown: why, for the user
    QString scenario; // Failed, Covered: the scenario file's text, replayed by the simulator
};

// Prove All: the project compiled as Build > Compile compiles it, then every
// property proved on a worker thread, each result shown as soon as it is
// known, so that the window stays usable, tells how far it got, and a cancel
// stops the solver. A counterexample is turned into a scenario and
// replayed by the simulator there too; one that does not replay is reported
// as unknown, as the command line does.
class ProofRun : public QObject {
    Q_OBJECT
public:
    explicit ProofRun(QObject* parent = nullptr);
    // Cancels a run and waits for it.
    ~ProofRun() override;

    // Starts proving the properties of `file` (read without errors) over the
    // document's project; false while a run goes on. `fileName` names the
    // properties in the scenarios' first lines.
    bool start(ProjectDocument* document, const prove::PropertyFile& file, const QString& fileName,
               const compiler::CheckOptions& options);
    void cancel();
    bool isRunning() const { return m_job != nullptr; }
    // The properties to prove, in file order, and what was found of them so far.
    const std::vector<prove::Property>& properties() const { return m_properties; }
    const std::vector<PropertyProof>& proofs() const { return m_proofs; }

signals:
    // Property `index` (from 0) of `total` is being proved; proofs() has the ones before.
    void progress(int index, int total);
    // The run ended: every property proved, or cancelled, or the project has
    // errors (`error` says so; nothing was proved).
    void finished(const QString& error, bool cancelled);

private:
    struct Job;
    void takeProofs();
    void done();

    std::shared_ptr<Job> m_job;
    QFutureWatcher<void> m_watcher;
    QTimer m_poll;
    std::vector<prove::Property> m_properties;
    std::vector<PropertyProof> m_proofs;
};

} // namespace rs::ui
