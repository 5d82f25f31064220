// SPDX-License-Identifier: GPL-3.0-or-later
#include "PasswordProtectDialog.h"

#include "shell/DialogProblem.h"

#include <QApplication>
#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QRadioButton>
#include <QVBoxLayout>

namespace rs::ui {

namespace {

QLineEdit* passwordField(const char* name, QWidget* parent) {
    auto* field = new QLineEdit(parent);
    field->setObjectName(QLatin1String(name));
    field->setEchoMode(QLineEdit::Password);
    field->setMinimumWidth(field->fontMetrics().averageCharWidth() * 24);
    return field;
}

} // namespace

PasswordProtectDialog::PasswordProtectDialog(const std::optional<project::Protection>& current,
                                             QWidget* parent)
    : QDialog(parent), m_protect(new QCheckBox(tr("&Password protect source file"), this)),
      m_password(passwordField("password", this)), m_repeat(passwordField("repeat", this)),
      m_optionsBox(new QGroupBox(tr("Change of config options"), this)),
      m_main(new QRadioButton(tr("Only possible with &main password"), m_optionsBox)),
      m_free(new QRadioButton(tr("Possible &without password"), m_optionsBox)),
      m_own(new QRadioButton(tr("Config &options password required"), m_optionsBox)),
      m_optionsPassword(passwordField("optionsPassword", this)),
      m_optionsRepeat(passwordField("optionsRepeat", this)), m_problem(new QLabel(this)) {
    setObjectName(QStringLiteral("passwordProtectDialog"));
    setWindowTitle(tr("Password Protect"));
    m_protect->setObjectName(QStringLiteral("protect"));
    m_main->setObjectName(QStringLiteral("optionsMain"));
    m_free->setObjectName(QStringLiteral("optionsFree"));
    m_own->setObjectName(QStringLiteral("optionsOwn"));
    m_problem->setObjectName(QStringLiteral("problem"));
    m_problem->setWordWrap(true);
    m_problem->hide();

    m_protect->setChecked(current.has_value());
    const project::OptionsAccess options =
        current ? current->options : project::OptionsAccess::Main;
    m_main->setChecked(options == project::OptionsAccess::Main);
    m_free->setChecked(options == project::OptionsAccess::Free);
    m_own->setChecked(options == project::OptionsAccess::Own);

    auto* about = new QLabel(tr("The file keeps no password: it keeps a signature only the "
                                "password can make, so a change made outside Rungsmith shows. "
                                "Anybody can still open and read the file."),
                             this);
    about->setWordWrap(true);
    auto* passwords = new QFormLayout;
    passwords->addRow(tr("Ma&in password:"), m_password);
    passwords->addRow(tr("&Repeat:"), m_repeat);
    auto* choices = new QVBoxLayout(m_optionsBox);
    choices->addWidget(m_main);
    choices->addWidget(m_free);
    choices->addWidget(m_own);
    auto* optionsPasswords = new QFormLayout;
    optionsPasswords->addRow(tr("Config options pa&ssword:"), m_optionsPassword);
    optionsPasswords->addRow(tr("R&epeat:"), m_optionsRepeat);
    choices->addLayout(optionsPasswords);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(about);
    layout->addWidget(m_protect);
    layout->addLayout(passwords);
    layout->addWidget(m_optionsBox);
    layout->addWidget(m_problem);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    layout->addWidget(buttons);

    for (QAbstractButton* choice :
         {static_cast<QAbstractButton*>(m_protect), static_cast<QAbstractButton*>(m_own)})
        connect(choice, &QAbstractButton::toggled, this, &PasswordProtectDialog::updateFields);
    connect(buttons, &QDialogButtonBox::accepted, this, &PasswordProtectDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &PasswordProtectDialog::reject);
    updateFields();
}

void PasswordProtectDialog::updateFields() {
    const bool protect = m_protect->isChecked();
    m_password->setEnabled(protect);
    m_repeat->setEnabled(protect);
    m_optionsBox->setEnabled(protect);
    m_optionsPassword->setEnabled(protect && m_own->isChecked());
    m_optionsRepeat->setEnabled(protect && m_own->isChecked());
}

void PasswordProtectDialog::accept() {
    if (!m_protect->isChecked()) {
        m_protection.reset();
        return QDialog::accept();
    }
    if (m_password->text().isEmpty())
        return sayProblem(m_problem, tr("Give the main password."));
    if (m_password->text() != m_repeat->text())
        return sayProblem(m_problem, tr("The main password and its repetition differ."));
    const project::OptionsAccess options = m_own->isChecked()    ? project::OptionsAccess::Own
                                           : m_free->isChecked() ? project::OptionsAccess::Free
                                                                 : project::OptionsAccess::Main;
    if (options == project::OptionsAccess::Own) {
        if (m_optionsPassword->text().isEmpty())
            return sayProblem(m_problem, tr("Give the config options password."));
        if (m_optionsPassword->text() != m_optionsRepeat->text())
            return sayProblem(m_problem,
                              tr("The config options password and its repetition differ."));
        if (m_optionsPassword->text() == m_password->text())
            return sayProblem(m_problem, tr("The config options password must differ from the "
                                            "main password, or it would give full permission."));
    }
    QApplication::setOverrideCursor(Qt::WaitCursor);
    m_protection = project::protectWith(m_password->text().toStdString(), options,
                                        m_optionsPassword->text().toStdString());
    QApplication::restoreOverrideCursor();
    QDialog::accept();
}

} // namespace rs::ui
