// SPDX-License-Identifier: GPL-3.0-or-later
#include "review/CompareDialog.h"

#include "compiler/Signature.h"
#include "document/ProjectDocument.h"
#include "project/ProjectFile.h"
#include "shell/DialogProblem.h"
#include "shell/StatusColors.h"

#include <QApplication>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QLabel>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <map>
#include <string>

namespace rs::ui {

namespace {

constexpr int kStationRole = Qt::UserRole;
constexpr int kSequenceRole = Qt::UserRole + 1;
constexpr int kStepRole = Qt::UserRole + 2;
constexpr int kNumberRole = Qt::UserRole + 3;

QString signature(std::uint32_t value) {
    return QString::fromStdString(compiler::signatureText(value));
}

// The difference as `diff` names it, in the window's language.
QString unitChange(const std::string& what) {
    static const std::map<std::string, const char*> names{
        {"unit: added", QT_TRANSLATE_NOOP("rs::ui::CompareDialog", "unit added")},
        {"unit: removed", QT_TRANSLATE_NOOP("rs::ui::CompareDialog", "unit removed")},
        {"type: changed", QT_TRANSLATE_NOOP("rs::ui::CompareDialog", "type changed")},
        {"ID code: changed", QT_TRANSLATE_NOOP("rs::ui::CompareDialog", "ID code changed")},
        {"I/O options: changed", QT_TRANSLATE_NOOP("rs::ui::CompareDialog", "I/O options changed")},
        {"exported and remanent variables: changed",
         QT_TRANSLATE_NOOP("rs::ui::CompareDialog", "exported and remanent variables changed")},
        {"names and descriptions: changed",
         QT_TRANSLATE_NOOP("rs::ui::CompareDialog", "names and descriptions changed")},
        {"comments: changed", QT_TRANSLATE_NOOP("rs::ui::CompareDialog", "comments changed")},
    };
    const auto found = names.find(what);
    return found == names.end()
               ? QString::fromStdString(what)
               : QCoreApplication::translate("rs::ui::CompareDialog", found->second);
}

} // namespace

CompareDialog::CompareDialog(ProjectDocument* document, const QString& oldPath, QWidget* parent)
    : QDialog(parent), m_heading(new QLabel(this)), m_lines(new QListWidget(this)),
      m_verdict(new QLabel(this)), m_pdf(new QPushButton(tr("Save Review as &PDF..."), this)) {
    setObjectName(QStringLiteral("compareDialog"));
    const bool withBaseline = oldPath.isEmpty();
    setWindowTitle(withBaseline ? tr("Changes Since Validation") : tr("Compare With"));
    if (withBaseline) {
        const project::Baseline& baseline = *document->project().baseline;
        m_heading->setText(tr("%1 as it is now, against the version validated on %2 by %3")
                               .arg(document->displayName(), QString::fromStdString(baseline.date),
                                    QString::fromStdString(baseline.by)));
    } else {
        m_heading->setText(tr("%1 as it is now (new), against %2 (old)")
                               .arg(document->displayName(), QDir::toNativeSeparators(oldPath)));
    }
    m_heading->setWordWrap(true);
    m_lines->setObjectName(QStringLiteral("comparisonLines"));
    m_lines->setToolTip(tr("Enter or a double click opens a network in the ladder"));
    m_verdict->setObjectName(QStringLiteral("comparisonVerdict"));
    m_verdict->setWordWrap(true);
    m_verdict->setTextInteractionFlags(Qt::TextSelectableByMouse);
    QFont bold = m_verdict->font();
    bold.setBold(true);
    m_verdict->setFont(bold);
    m_verdict->setText(tr("Comparing..."));
    m_pdf->setObjectName(QStringLiteral("saveReviewPdfButton"));
    m_pdf->setEnabled(false);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    buttons->addButton(m_pdf, QDialogButtonBox::ActionRole);
    m_pdf->setVisible(!withBaseline); // the baseline keeps no networks to draw
    // Enter opens the list's network; no button may take it.
    for (QAbstractButton* button : buttons->buttons())
        if (auto* push = qobject_cast<QPushButton*>(button))
            push->setAutoDefault(false);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_pdf, &QPushButton::clicked, this, &CompareDialog::choosePdf);
    auto open = [this](QListWidgetItem* item) {
        if (item && item->data(kNumberRole).isValid())
            emit networkChosen(item->data(kStationRole).toInt(), item->data(kSequenceRole).toInt(),
                               item->data(kStepRole).toInt(), item->data(kNumberRole).toInt());
    };
    connect(m_lines, &QListWidget::itemActivated, this, open);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_heading);
    layout->addWidget(m_lines, 1);
    layout->addWidget(m_verdict);
    layout->addWidget(buttons);
    resize(640, 420);

    connect(&m_watcher, &QFutureWatcher<ProjectComparison>::finished, this,
            &CompareDialog::showComparison);
    QApplication::setOverrideCursor(Qt::BusyCursor);
    const std::string text = project::writeProject(document->project());
    const QString executableDir = QCoreApplication::applicationDirPath();
    const QString path = document->path();
    m_watcher.setFuture(
        withBaseline ? QtConcurrent::run(compareWithBaseline, text, path, executableDir)
                     : QtConcurrent::run(compareWithFile, oldPath, text, path, executableDir));
}

CompareDialog::~CompareDialog() {
    if (m_watcher.isRunning())
        QApplication::restoreOverrideCursor();
    m_watcher.waitForFinished();
}

void CompareDialog::showComparison() {
    QApplication::restoreOverrideCursor();
    m_comparison = m_watcher.result();
    if (!m_comparison->diff) {
        sayProblem(m_verdict, m_comparison->error);
        return;
    }
    const review::ProjectDiff& diff = *m_comparison->diff;
    for (const review::UnitDifference& unit : diff.units)
        m_lines->addItem(tr("Pluto %1: %2")
                             .arg(unit.station, 2, 10, QLatin1Char('0'))
                             .arg(unitChange(unit.what)));
    for (const review::NetworkDifference& network : diff.networks) {
        const QString step = QString::fromStdString(lang::toString(network.step));
        QString line;
        switch (network.change) {
        case review::Pairing::Added:
            line = tr("Pluto %1 %2 network %3: added");
            break;
        case review::Pairing::Removed:
            line = tr("Pluto %1 %2 network %3: removed");
            break;
        default:
            line = tr("Pluto %1 %2 network %3: changed");
            break;
        }
        auto* item = new QListWidgetItem(
            line.arg(network.station, 2, 10, QLatin1Char('0')).arg(step).arg(network.number),
            m_lines);
        if (network.change != review::Pairing::Removed) {
            item->setData(kStationRole, network.station);
            item->setData(kSequenceRole, network.step.sequence);
            item->setData(kStepRole, network.step.step);
            item->setData(kNumberRole, network.number);
        }
    }
    if (m_lines->count() == 0)
        m_lines->addItem(tr("No network, unit or option differs."));
    else
        m_lines->setCurrentRow(0);
    QString verdict;
    if (!diff.behaviourChanged()) {
        verdict = diff.textChanged ? tr("No change in behaviour; only the text changed.")
                                   : tr("No change in behaviour.");
    } else {
        QStringList units;
        for (const int station : diff.changedStations)
            units << tr("Pluto %1").arg(station, 2, 10, QLatin1Char('0'));
        verdict = tr("Behaviour changed in %1 (project signature %2, was %3).")
                      .arg(units.join(QStringLiteral(", ")), signature(diff.newSignature),
                           signature(diff.oldSignature));
        markAsError(m_verdict);
    }
    m_verdict->setText(verdict);
    m_pdf->setEnabled(m_comparison->review.has_value());
    m_lines->setFocus();
}

QStringList CompareDialog::lines() const {
    QStringList shown;
    for (int row = 0; row < m_lines->count(); ++row)
        shown << m_lines->item(row)->text();
    return shown;
}

QString CompareDialog::verdict() const {
    return m_verdict->text();
}

QString CompareDialog::savePdf(const QString& path) {
    if (!m_comparison || !m_comparison->review)
        return tr("There is nothing to save yet.");
    return render::writeReviewPdf(path, *m_comparison->review);
}

void CompareDialog::choosePdf() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Save Review as PDF"), QString(),
                                                      tr("PDF files (*.pdf)"));
    if (path.isEmpty())
        return;
    if (const QString error = savePdf(path); !error.isEmpty())
        QMessageBox::warning(this, windowTitle(), error);
}

} // namespace rs::ui
