// SPDX-License-Identifier: GPL-3.0-or-later
#include "ConfigOptionDialog.h"

#include "document/ProjectDocument.h"
#include "ladder/ElementText.h"
#include "lang/Printer.h"
#include "shell/DialogProblem.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>

namespace rs::ui {

ConfigOptionDialog::ConfigOptionDialog(ProjectDocument* document, int station,
                                       const ladder::ConfigOption& option, QWidget* parent)
    : QDialog(parent), m_document(document), m_station(station),
      m_description(new QLineEdit(QString::fromStdString(option.description), this)),
      m_memory(new QLineEdit(this)), m_checked(new QCheckBox(tr("&Enabled"), this)),
      m_problem(new QLabel(this)) {
    setObjectName(QStringLiteral("configOptionDialog"));
    setWindowTitle(tr("Config Option"));
    m_description->setObjectName(QStringLiteral("description"));
    m_memory->setObjectName(QStringLiteral("memory"));
    m_checked->setObjectName(QStringLiteral("checked"));
    if (option.memory.address.valid())
        m_memory->setText(QString::fromStdString(lang::printOperand(option.memory)));
    m_memory->setPlaceholderText(tr("a memory, such as M%1.5").arg(station));
    m_checked->setChecked(option.checked);
    m_problem->setObjectName(QStringLiteral("problem"));
    m_problem->setWordWrap(true);
    m_problem->hide();
    auto* about = new QLabel(tr("A config option is a check box on its network: it sets the "
                                "memory when checked and resets it when not, so that one "
                                "program serves machines with and without an option (manual "
                                "11.6)."),
                             this);
    about->setWordWrap(true);
    auto* form = new QFormLayout(this);
    form->addRow(about);
    form->addRow(tr("&Description:"), m_description);
    form->addRow(tr("&Memory:"), m_memory);
    form->addRow(QString(), m_checked);
    form->addRow(m_problem);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    form->addRow(buttons);
    // Room for a description a check box can say in full.
    m_description->setMinimumWidth(m_description->fontMetrics().averageCharWidth() * 40);
    connect(buttons, &QDialogButtonBox::accepted, this, &ConfigOptionDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &ConfigOptionDialog::reject);
}

void ConfigOptionDialog::accept() {
    if (!m_document)
        return QDialog::reject();
    const QString description = m_description->text().trimmed();
    if (description.isEmpty()) {
        sayProblem(m_problem,
                   tr("Describe the option: the description is what the check box says."));
        return;
    }
    const ladder::OutputReading read =
        ladder::readOutput(m_document->project().program, m_station,
                           QStringLiteral("S(%1)").arg(m_memory->text().trimmed()).toStdString());
    if (!read.output || read.output->target.address.kind != lang::AddressKind::Memory) {
        sayProblem(m_problem, read.output ? tr("Only memories can be options (manual 11.6).")
                                          : QString::fromStdString(read.error));
        return;
    }
    m_option = ladder::ConfigOption{description.toStdString(), read.output->target,
                                    m_checked->isChecked()};
    QDialog::accept();
}

} // namespace rs::ui
