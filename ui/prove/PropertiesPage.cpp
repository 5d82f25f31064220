// SPDX-License-Identifier: GPL-3.0-or-later
#include "prove/PropertiesPage.h"

#include "document/PermissionNote.h"
#include "document/ProjectDocument.h"
#include "project/VariableTable.h"
#include "prove/ProofResultsView.h"
#include "prove/PropertyEditor.h"
#include "shell/PageTitle.h"
#include "shell/StatusColors.h"
#include "sim/Scenario.h"

#include <QAction>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSplitter>
#include <QToolBar>
#include <QVBoxLayout>

#include <set>

namespace rs::ui {

namespace {

std::string_view view(const QByteArray& bytes) {
    return {bytes.constData(), static_cast<std::size_t>(bytes.size())};
}

// Whether any line holds more than a comment: a file without one is one to be written.
bool hasPropertyLine(const QByteArray& text) {
    for (const QByteArray& line : text.split('\n')) {
        const qsizetype comment = [&line] {
            const qsizetype semicolon = line.indexOf(';');
            const qsizetype hash = line.indexOf('#');
            return semicolon < 0 ? hash : hash < 0 ? semicolon : std::min(semicolon, hash);
        }();
        if (!line.left(comment < 0 ? line.size() : comment).trimmed().isEmpty())
            return true;
    }
    return false;
}

// The project's symbolic names and the operands its code uses, for completion.
QStringList operandWords(const project::Project& project) {
    std::set<QString> words;
    for (int station : project.stations()) {
        for (const lang::Address& address : project::namedAddresses(project, station))
            words.insert(QString::fromStdString(project::variableName(project, address)));
        for (const lang::Address& address : project::usedVariables(project, station))
            words.insert(QString::fromStdString(lang::toString(address)));
    }
    words.erase(QString());
    return {words.begin(), words.end()};
}

} // namespace

QString PropertiesPage::example() {
    return tr("; What must hold in every scan, for every input sequence: one property a line.\n"
              "; Remove the ';' before a line to use it, with the operands of this project.\n"
              "; always Q0.2 -> I0.12                 ; the output only with the stop circuit "
              "closed\n"
              "; never Q0.2 * Q0.3                    ; never both contactors at once\n"
              "; always /I0.12 -> within 20ms /Q0.2   ; the output drops within 20 ms of a stop\n"
              "; always I0.0 -> next Q0.2             ; the output follows the start in the next "
              "scan\n"
              "; assume /(I0.0 * I0.1)                ; the two sensors are never made at once\n"
              "; cover Q0.2                           ; the output can come on\n");
}

PropertiesPage::PropertiesPage(QWidget* parent)
    : QWidget(parent), m_title(new PageTitle(this)), m_toolBar(new QToolBar(this)),
      m_cancel(new QAction(tr("Cancel"), this)),
      m_openCounterexample(new QAction(tr("Open Counterexample"), this)),
      m_complete(new QAction(tr("Complete Word"), this)), m_progress(new QProgressBar(this)),
      m_note(new QWidget(this)), m_insertExample(new QPushButton(tr("Insert Example"), m_note)),
      m_status(new QLabel(this)), m_editor(new PropertyEditor(this)),
      m_results(new ProofResultsView(this)) {
    m_toolBar->setObjectName(QStringLiteral("propertiesToolBar"));
    m_toolBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_toolBar->setIconSize(QSize(20, 20));
    m_cancel->setObjectName(QStringLiteral("cancelProofAction"));
    m_cancel->setToolTip(tr("Stop proving; the properties proved so far keep their results"));
    connect(m_cancel, &QAction::triggered, this, &PropertiesPage::cancel);
    m_openCounterexample->setObjectName(QStringLiteral("openCounterexampleAction"));
    m_openCounterexample->setToolTip(
        tr("Run the chosen property's counterexample (or witness) in the simulator, with the "
           "waveform, stopped at its last scan"));
    connect(m_openCounterexample, &QAction::triggered, this, [this] {
        if (const PropertyProof* proof = m_results->currentProof();
            proof && !proof->scenario.isEmpty() && m_provedDocument)
            emit counterexampleRequested(m_provedDocument, *proof);
    });
    m_progress->setObjectName(QStringLiteral("proofProgress"));
    m_progress->setMaximumWidth(220);
    m_toolBar->addAction(m_cancel);
    m_toolBar->addSeparator();
    m_toolBar->addAction(m_openCounterexample);
    m_toolBar->addSeparator();
    // A tool bar shows and hides its widgets through their actions.
    m_progressShown = m_toolBar->addWidget(m_progress);
    m_progressShown->setVisible(false);

    m_editor->setObjectName(QStringLiteral("propertiesEditor"));
    m_editor->setProjectUndo(false);
    m_complete->setObjectName(QStringLiteral("completeWordAction"));
    m_complete->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Space));
    m_complete->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    connect(m_complete, &QAction::triggered, m_editor, &PropertyEditor::complete);
    m_editor->addAction(m_complete);

    m_note->setObjectName(QStringLiteral("propertiesNote"));
    auto* noteText = new QLabel(
        tr("<p>No properties yet. Write one a line, with conditions as in the code (operands, "
           "names, <code>/</code>, <code>*</code>, <code>+</code>, parentheses):</p>"
           "<p><code>always A</code>, <code>never A</code>, <code>always A -&gt; B</code>, "
           "<code>always A -&gt; within 20ms B</code>, <code>always A -&gt; next B</code>, "
           "<code>assume A</code>, <code>cover A</code>.</p>"
           "<p><b>Prove All</b> proves each for every input sequence, or finds one that breaks "
           "it and opens it in the simulator.</p>"),
        m_note);
    noteText->setWordWrap(true);
    noteText->setTextFormat(Qt::RichText);
    m_insertExample->setObjectName(QStringLiteral("insertExampleButton"));
    m_insertExample->setToolTip(tr("Put a commented example of every kind of line in the text"));
    connect(m_insertExample, &QPushButton::clicked, this, [this] {
        m_editor->SendScintilla(QsciScintillaBase::SCI_DOCUMENTSTART);
        m_editor->insert(example());
        m_editor->setFocus();
    });
    auto* noteLayout = new QHBoxLayout(m_note);
    noteLayout->setContentsMargins(0, 0, 0, 0);
    noteLayout->addWidget(noteText, 1);
    noteLayout->addWidget(m_insertExample, 0, Qt::AlignTop);

    m_status->setObjectName(QStringLiteral("proofStatus"));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_status->hide();

    auto* split = new QSplitter(Qt::Vertical, this);
    split->setObjectName(QStringLiteral("propertiesSplitter"));
    split->addWidget(m_editor);
    split->addWidget(m_results);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    split->setChildrenCollapsible(false);
    m_results->addAction(m_openCounterexample);
    m_results->setContextMenuPolicy(Qt::ActionsContextMenu);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_title);
    layout->addWidget(m_toolBar);
    layout->addWidget(m_note);
    layout->addWidget(m_status);
    layout->addWidget(split, 1);

    m_readTimer.setSingleShot(true);
    m_readTimer.setInterval(kReadDelayMs);
    connect(&m_readTimer, &QTimer::timeout, this, &PropertiesPage::readText);
    connect(m_editor, &QsciScintilla::textChanged, this, [this] {
        if (m_settingText || !m_document)
            return;
        m_document->setPropertiesText(m_editor->textBytes());
        m_readTimer.start();
        markOutdated();
    });
    connect(m_results, &ProofResultsView::lineActivated, this,
            [this](int line) { m_editor->goTo(line, 1); });
    connect(m_results, &QTreeWidget::currentItemChanged, this, &PropertiesPage::updateActions);
    connect(m_results, &ProofResultsView::proofChanged, this, &PropertiesPage::updateActions);
    connect(&m_run, &ProofRun::progress, this, &PropertiesPage::progress);
    connect(&m_run, &ProofRun::finished, this, &PropertiesPage::finished);
    updateActions();
}

void PropertiesPage::setProveAllAction(QAction* action) {
    m_toolBar->insertAction(m_cancel, action);
}

void PropertiesPage::showProject(ProjectDocument* document) {
    if (m_document == document)
        return;
    if (m_document)
        disconnect(m_document, nullptr, this, nullptr);
    m_readTimer.stop();
    m_document = document;
    m_settingText = true;
    m_editor->setTextBytes(document ? document->propertiesText() : QByteArray());
    m_settingText = false;
    m_editor->forgetWords();
    if (document) {
        const QPointer<ProjectDocument> source = document;
        m_editor->setWords(
            [source] { return source ? operandWords(source->project()) : QStringList(); });
        connect(document, &ProjectDocument::changed, this, [this] {
            m_editor->forgetWords();
            updateTitle();
            markOutdated();
            m_readTimer.start(); // a name may have come or gone
        });
        connect(document, &ProjectDocument::pathChanged, this, &PropertiesPage::updateTitle);
        connect(document, &ProjectDocument::permissionChanged, this, &PropertiesPage::updateTitle);
    }
    if (m_provedDocument != document) {
        // The rows, and a proof still running, are another project's.
        m_run.cancel();
        m_results->setProperties({});
        setStatus({});
    }
    updateTitle();
    readText();
    if (document && !document->propertiesError().isEmpty())
        setStatus(document->propertiesError(), errorTextColor(palette()));
}

void PropertiesPage::updateTitle() {
    if (!m_document)
        return;
    m_title->setTitle(tr("%1 — Properties").arg(m_document->displayName()));
    const QString path = m_document->propertiesPath();
    QString subtitle =
        path.isEmpty()
            ? tr("Saved with the project, beside its file, once it has one: its name with the "
                 "extension .prop.")
            : tr("Saved with the project as %1, which rungsmith-cli prove takes too.")
                  .arg(QFileInfo(path).fileName());
    const bool readOnly = m_document->permission() != project::Permission::Full;
    m_editor->setReadOnly(readOnly);
    if (readOnly)
        subtitle = permissionNote(m_document->permission());
    m_title->setSubtitle(subtitle);
    updateActions();
}

void PropertiesPage::readText() {
    m_readTimer.stop();
    m_file.reset();
    const QByteArray text = m_editor->textBytes();
    const bool written = hasPropertyLine(text);
    m_note->setVisible(m_document && !written);
    m_insertExample->setEnabled(!m_editor->isReadOnly());
    if (!m_document || !written) {
        m_diagnostics.clear();
        m_editor->setDiagnostics({});
        return;
    }
    prove::PropertyFile file =
        prove::parseProperties(view(text), sim::OperandNames(m_document->project()));
    m_diagnostics = file.diagnostics;
    m_editor->setDiagnostics(m_diagnostics);
    if (lang::errorCount(m_diagnostics) == 0)
        m_file = std::move(file);
}

bool PropertiesPage::proveAll(const compiler::CheckOptions& options) {
    if (!m_document || m_run.isRunning())
        return false;
    readText();
    if (!m_file) {
        setStatus(lang::errorCount(m_diagnostics)
                      ? tr("The properties have %n error(s), marked in the text: nothing is "
                           "proved until they read.",
                           nullptr, lang::errorCount(m_diagnostics))
                      : tr("Write a property first: there is nothing to prove."),
                  errorTextColor(palette()));
        return false;
    }
    const QString path = m_document->propertiesPath();
    const QString fileName =
        path.isEmpty()
            ? QFileInfo(m_document->displayName()).completeBaseName() + QStringLiteral(".prop")
            : QFileInfo(path).fileName();
    if (!m_run.start(m_document, *m_file, fileName, options))
        return false;
    m_provedDocument = m_document;
    m_shownProofs = 0;
    m_results->setProperties(m_run.properties());
    m_progress->setRange(0, static_cast<int>(m_run.properties().size()));
    m_progress->setValue(0);
    m_progressShown->setVisible(true);
    setStatus(tr("Compiling %1...").arg(m_document->displayName()));
    updateActions();
    emit provingChanged();
    return true;
}

void PropertiesPage::progress(int index, int total) {
    if (m_provedDocument != m_document)
        return;
    takeProofs();
    m_progress->setRange(0, total);
    m_progress->setValue(index);
    m_progress->setFormat(tr("Property %1 of %2").arg(index + 1).arg(total));
    m_results->setProving(index);
    setStatus(tr("Proving property %1 of %2...").arg(index + 1).arg(total));
}

void PropertiesPage::takeProofs() {
    const std::vector<PropertyProof>& proofs = m_run.proofs();
    for (; m_shownProofs < proofs.size(); ++m_shownProofs)
        m_results->setProof(static_cast<int>(m_shownProofs), proofs[m_shownProofs]);
}

void PropertiesPage::finished(const QString& error, bool cancelled) {
    m_progressShown->setVisible(false);
    if (m_provedDocument != m_document) { // cancelled as another project came
        updateActions();
        emit provingChanged();
        return;
    }
    takeProofs();
    const int shown = static_cast<int>(m_shownProofs);
    if (!error.isEmpty()) {
        m_results->setNotProved(0, error);
        setStatus(error, errorTextColor(palette()));
    } else {
        if (cancelled)
            m_results->setNotProved(shown, tr("cancelled"));
        int proved = 0;
        int failed = 0;
        int unknown = 0;
        for (const PropertyProof& proof : m_run.proofs())
            switch (proof.status) {
            case PropertyProof::Status::Proved:
            case PropertyProof::Status::Covered:
                ++proved;
                break;
            case PropertyProof::Status::Failed:
            case PropertyProof::Status::NeverCovered:
                ++failed;
                break;
            case PropertyProof::Status::Unknown:
                ++unknown;
                break;
            }
        QString summary =
            tr("%1 proved, %2 failed, %3 unknown").arg(proved).arg(failed).arg(unknown);
        if (cancelled)
            summary = tr("Cancelled: %1.").arg(summary);
        // The first failed row (else the first covered) is chosen, so that Open
        // Counterexample is at hand.
        const auto first = [this, shown](bool failedOnly) {
            for (int row = 0; row < shown; ++row)
                if (const PropertyProof* proof = m_results->proofAt(row);
                    proof && !proof->scenario.isEmpty() &&
                    (!failedOnly || proof->status == PropertyProof::Status::Failed))
                    return row;
            return -1;
        };
        if (const int row = first(true) >= 0 ? first(true) : first(false); row >= 0)
            m_results->setCurrentItem(m_results->topLevelItem(row));
        setStatus(summary, failed    ? errorTextColor(palette())
                           : unknown ? undecidedTextColor(palette())
                                     : passTextColor(palette()));
    }
    updateActions();
    emit provingChanged();
}

void PropertiesPage::markOutdated() {
    if (m_run.isRunning() || m_provedDocument != m_document ||
        m_results->topLevelItemCount() == 0 || m_outdated)
        return;
    setStatus(tr("The properties or the project changed since this proof; Prove All again for "
                 "results of the text as it is now."),
              undecidedTextColor(palette()));
    m_outdated = true;
}

void PropertiesPage::setStatus(const QString& text, const QColor& color) {
    m_outdated = false;
    m_status->setText(text);
    m_status->setVisible(!text.isEmpty());
    QPalette palette = this->palette();
    if (color.isValid())
        palette.setColor(QPalette::WindowText, color);
    m_status->setPalette(palette);
}

QString PropertiesPage::statusText() const {
    return m_status->text();
}

void PropertiesPage::updateActions() {
    const bool running = m_run.isRunning();
    m_cancel->setEnabled(running);
    const PropertyProof* proof = m_results->currentProof();
    m_openCounterexample->setEnabled(proof && !proof->scenario.isEmpty() && m_provedDocument);
    m_openCounterexample->setText(proof && proof->status == PropertyProof::Status::Covered
                                      ? tr("Open Witness")
                                      : tr("Open Counterexample"));
}

} // namespace rs::ui
