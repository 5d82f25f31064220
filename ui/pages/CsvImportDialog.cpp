// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/CsvImportDialog.h"

#include "project/ProjectFile.h"

#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QIcon>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSplitter>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace rs::ui {

namespace {

QString separatorName(char separator) {
    switch (separator) {
    case ';':
        return CsvImportDialog::tr("semicolons");
    case '\t':
        return CsvImportDialog::tr("tabs");
    default:
        return CsvImportDialog::tr("commas");
    }
}

QString change(const std::string& before, const std::string& after) {
    if (before == after)
        return QString::fromStdString(after);
    return QStringLiteral("%1 → %2").arg(
        before.empty() ? QStringLiteral("—") : QString::fromStdString(before),
        after.empty() ? QStringLiteral("—") : QString::fromStdString(after));
}

} // namespace

CsvImportDialog::CsvImportDialog(const project::Project& project, int station, QWidget* parent)
    : QDialog(parent), m_project(project), m_station(station), m_path(new QLineEdit(this)),
      m_prefix(new QLineEdit(this)), m_summary(new QLabel(this)), m_changes(new QTreeWidget(this)),
      m_problems(new QTreeWidget(this)), m_import(nullptr) {
    setObjectName(QStringLiteral("csvImportDialog"));
    setWindowTitle(tr("Import Variable Names to Pluto %1").arg(station));
    m_path->setObjectName(QStringLiteral("csvPathEdit"));
    m_prefix->setObjectName(QStringLiteral("csvPrefixEdit"));
    m_prefix->setPlaceholderText(tr("none"));
    m_summary->setObjectName(QStringLiteral("csvImportSummary"));
    m_summary->setWordWrap(true);
    auto* browse = new QPushButton(tr("&Browse..."), this);
    auto* file = new QHBoxLayout;
    file->addWidget(m_path, 1);
    file->addWidget(browse);
    auto* form = new QFormLayout;
    // A row's label made from text has no buddy: its '&' would show, and
    // Alt+F would lead nowhere.
    auto* fileLabel = new QLabel(tr("&File:"), this);
    fileLabel->setBuddy(m_path);
    form->addRow(fileLabel, file);
    form->addRow(tr("&Remove prefix from names:"), m_prefix);

    m_changes->setObjectName(QStringLiteral("csvChanges"));
    m_changes->setHeaderLabels(
        {tr("Line"), tr("Variable"), tr("Symbolic Name"), tr("Description")});
    m_changes->setRootIsDecorated(false);
    m_changes->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_problems->setObjectName(QStringLiteral("csvProblems"));
    m_problems->setHeaderLabels({tr("Line"), tr("Left out because")});
    m_problems->setRootIsDecorated(false);
    m_problems->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    auto* split = new QSplitter(Qt::Vertical, this);
    split->addWidget(m_changes);
    split->addWidget(m_problems);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 1);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    m_import = buttons->addButton(tr("&Import"), QDialogButtonBox::AcceptRole);
    m_import->setObjectName(QStringLiteral("csvImportButton"));
    m_import->setEnabled(false);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString chosen = QFileDialog::getOpenFileName(
            this, windowTitle(), m_path->text(), tr("CSV files (*.csv *.txt);;All files (*)"));
        if (!chosen.isEmpty())
            setPath(chosen);
    });
    connect(m_path, &QLineEdit::editingFinished, this, &CsvImportDialog::preview);
    connect(m_prefix, &QLineEdit::textChanged, this, &CsvImportDialog::preview);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_summary);
    layout->addWidget(split, 1);
    layout->addWidget(buttons);
    resize(760, 520);
    m_summary->setText(tr("Choose a CSV file with the columns Variable, Symbolic Name and "
                          "Description. Nothing changes before you press Import."));
}

void CsvImportDialog::setPath(const QString& path) {
    m_path->setText(path);
    preview();
}

void CsvImportDialog::preview() {
    m_changes->clear();
    m_problems->clear();
    m_import->setEnabled(false);
    if (m_path->text().isEmpty())
        return;
    const project::FileText file = project::readTextFile(m_path->text());
    if (!file.error.isEmpty()) {
        m_summary->setText(file.error);
        return;
    }
    project::CsvImportOptions options;
    options.station = m_station;
    options.prefix = m_prefix->text().trimmed().toStdString();
    m_result = project::importVariablesCsv(m_project, file.text, options);

    for (const auto& row : m_result.changes) {
        auto* item = new QTreeWidgetItem(m_changes);
        item->setText(0, QString::number(row.line));
        item->setText(1, QString::fromStdString(lang::toString(row.address)));
        item->setText(2, change(row.oldName, row.name));
        item->setText(3, change(row.oldDescription, row.description));
    }
    const QIcon error(QStringLiteral(":/icons/error.svg"));
    for (const auto& problem : m_result.problems) {
        auto* item = new QTreeWidgetItem(m_problems);
        item->setIcon(0, error);
        item->setText(0, QString::number(problem.line));
        item->setText(1, QString::fromStdString(problem.message));
        item->setToolTip(1, item->text(1));
    }
    m_summary->setText(
        tr("Fields separated by %1. %2 to change, %3 unchanged, %4 left out.")
            .arg(separatorName(m_result.separator))
            .arg(tr("%n variable(s)", nullptr, static_cast<int>(m_result.changes.size())))
            .arg(m_result.unchanged)
            .arg(tr("%n row(s)", nullptr, static_cast<int>(m_result.problems.size()))));
    m_problems->setVisible(!m_result.problems.empty());
    m_import->setEnabled(!m_result.changes.empty());
}

} // namespace rs::ui
