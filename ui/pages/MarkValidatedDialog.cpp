// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/MarkValidatedDialog.h"

#include "blocks/ProjectInstances.h"
#include "document/ProjectDocument.h"
#include "project/ProjectFile.h"
#include "review/Validation.h"

#include <QApplication>
#include <QCoreApplication>
#include <QDate>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QVBoxLayout>

namespace rs::ui {

namespace {

const QString kLastNameKey = QStringLiteral("review/validatedBy");

} // namespace

MarkValidatedDialog::MarkValidatedDialog(ProjectDocument* document, QWidget* parent)
    : QDialog(parent), m_document(document), m_by(new QLineEdit(this)),
      m_comment(new QLineEdit(this)) {
    setObjectName(QStringLiteral("markValidatedDialog"));
    setWindowTitle(tr("Mark as Validated"));
    m_by->setObjectName(QStringLiteral("validatedBy"));
    m_comment->setObjectName(QStringLiteral("validationComment"));
    m_by->setText(QSettings().value(kLastNameKey).toString());
    auto* about = new QLabel(tr("Records this version's program signatures as the validated "
                                "baseline: from now on the review says what changed since. It "
                                "changes nothing the units do."),
                             this);
    about->setWordWrap(true);
    auto* form = new QFormLayout;
    form->addRow(tr("Validated &by:"), m_by);
    form->addRow(tr("&Comment:"), m_comment);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    m_ok = buttons->button(QDialogButtonBox::Ok);
    m_ok->setText(tr("&Mark as Validated"));
    m_ok->setEnabled(!m_by->text().trimmed().isEmpty());
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(about);
    layout->addLayout(form);
    layout->addWidget(buttons);
    m_by->setMinimumWidth(m_by->fontMetrics().averageCharWidth() * 32);
    connect(m_by, &QLineEdit::textChanged, this,
            [this](const QString& text) { m_ok->setEnabled(!text.trimmed().isEmpty()); });
    connect(buttons, &QDialogButtonBox::accepted, this, &MarkValidatedDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
}

void MarkValidatedDialog::accept() {
    const QString by = m_by->text().trimmed();
    if (by.isEmpty())
        return;
    // What `validate` does: the baseline is of the project its instances expand to.
    QApplication::setOverrideCursor(Qt::WaitCursor);
    const std::string text = project::writeProject(m_document->project());
    const blocks::ProjectWithInstances read = blocks::readProjectWithInstances(
        text,
        blocks::LibraryPlaces{QCoreApplication::applicationDirPath(), m_document->path(), {}});
    const compiler::CompileResult compiled =
        blocks::compileProject(read.read.project, read.read.diagnostics);
    QApplication::restoreOverrideCursor();
    if (compiled.errors()) {
        QMessageBox::warning(this, windowTitle(),
                             tr("The project has %n error(s) and cannot be validated. Build > "
                                "Compile (F7) lists them.",
                                nullptr, compiled.errors()));
        return;
    }
    const project::Baseline baseline = review::validatedBaseline(
        read.read.project, compiled, QDate::currentDate().toString(Qt::ISODate).toStdString(),
        by.toStdString(), m_comment->text().trimmed().toStdString());
    m_document->edit(tr("Mark as Validated"), [&](project::Project& p) { p.baseline = baseline; });
    QSettings().setValue(kLastNameKey, by);
    QDialog::accept();
}

} // namespace rs::ui
