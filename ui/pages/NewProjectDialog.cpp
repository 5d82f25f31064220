// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/NewProjectDialog.h"

#include "project/ProjectProperties.h"
#include "shell/StatusColors.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace rs::ui {

NewProjectDialog::NewProjectDialog(QWidget* parent)
    : QDialog(parent), m_target(new QComboBox(this)),
      m_name(new QLineEdit(tr("New project"), this)), m_description(new QPlainTextEdit(this)),
      m_includeSource(new QCheckBox(tr("&Include source code in compiled file"), this)),
      m_problem(new QLabel(this)),
      m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this)) {
    setObjectName(QStringLiteral("newProjectDialog"));
    setWindowTitle(tr("New Project"));
    m_target->setObjectName(QStringLiteral("projectTargetCombo"));
    m_target->addItem(tr("Pluto safety PLCs (1 to 32 units on one bus)"));
    m_target->addItem(tr("Pixsys PL110 (one ladder PLC)"));
    m_name->setObjectName(QStringLiteral("projectNameEdit"));
    m_name->selectAll();
    m_description->setObjectName(QStringLiteral("projectDescriptionEdit"));
    m_description->setPlaceholderText(tr("For your own notes"));
    m_description->setTabChangesFocus(true);
    m_includeSource->setObjectName(QStringLiteral("includeSourceCheck"));
    auto* note = new QLabel(
        tr("The project name is downloaded to the units and checked when going online. With the "
           "source code included, a program uploaded from a unit can be opened again; the file "
           "grows and anyone with the password can change the program."),
        this);
    note->setWordWrap(true);
    note->setForegroundRole(QPalette::PlaceholderText);
    m_problem->setObjectName(QStringLiteral("projectNameProblem"));
    markAsError(m_problem);
    m_problem->hide();

    auto* form = new QFormLayout;
    form->addRow(tr("&Target:"), m_target);
    form->addRow(tr("Project &name:"), m_name);
    form->addRow(QString(), m_problem);
    form->addRow(tr("Project &description:"), m_description);
    form->addRow(QString(), m_includeSource);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(note);
    layout->addWidget(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_name, &QLineEdit::textChanged, this, &NewProjectDialog::validate);
    connect(m_target, &QComboBox::currentIndexChanged, this, [this, note] {
        const bool pluto = target() == Target::Pluto;
        m_description->setEnabled(pluto);
        m_includeSource->setEnabled(pluto);
        note->setVisible(pluto);
    });
    resize(520, 340);
}

NewProjectDialog::Target NewProjectDialog::target() const {
    return m_target->currentIndex() == 1 ? Target::Pl110 : Target::Pluto;
}

QString NewProjectDialog::name() const {
    return m_name->text();
}

QString NewProjectDialog::description() const {
    return m_description->toPlainText();
}

bool NewProjectDialog::includeSource() const {
    return m_includeSource->isChecked();
}

void NewProjectDialog::validate() {
    const auto problem = project::checkProjectName(m_name->text().toStdString());
    m_problem->setText(problem ? QString::fromStdString(*problem) : QString());
    m_problem->setVisible(problem.has_value());
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(!problem);
}

} // namespace rs::ui
