// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProtectedOpenDialog.h"

#include "shell/DialogProblem.h"

#include <QApplication>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QVBoxLayout>

namespace rs::ui {

ProtectedOpenDialog::ProtectedOpenDialog(const QString& fileName,
                                         const project::Protection& protection, QWidget* parent)
    : QDialog(parent), m_protection(protection),
      m_full(new QRadioButton(tr("Open with &full permission"), this)),
      m_configure(new QRadioButton(tr("Open with permission to &configure"), this)),
      m_readOnly(new QRadioButton(tr("Open in &read only mode"), this)),
      m_password(new QLineEdit(this)), m_problem(new QLabel(this)) {
    setObjectName(QStringLiteral("protectedOpenDialog"));
    setWindowTitle(tr("Open Protected Project"));
    m_full->setObjectName(QStringLiteral("full"));
    m_configure->setObjectName(QStringLiteral("configure"));
    m_readOnly->setObjectName(QStringLiteral("readOnly"));
    m_password->setObjectName(QStringLiteral("password"));
    m_password->setEchoMode(QLineEdit::Password);
    m_problem->setObjectName(QStringLiteral("problem"));
    m_problem->setWordWrap(true);
    m_problem->hide();

    auto* about = new QLabel(tr("“%1” is password protected. It opens without a password, but "
                                "then nothing in it can change.")
                                 .arg(fileName.toHtmlEscaped()),
                             this);
    about->setWordWrap(true);
    m_full->setToolTip(tr("Takes the main password; everything can change."));
    m_configure->setToolTip(
        protection.options == project::OptionsAccess::Free
            ? tr("Takes no password; only the Config Options can change.")
            : tr("Takes the config options password, or the main one; only the Config Options "
                 "can change."));
    m_readOnly->setToolTip(tr("Takes no password; nothing can change."));
    m_full->setChecked(true);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(about);
    layout->addWidget(m_full);
    layout->addWidget(m_configure);
    layout->addWidget(m_readOnly);
    auto* form = new QFormLayout;
    form->addRow(tr("&Password:"), m_password);
    layout->addLayout(form);
    layout->addWidget(m_problem);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    m_ok = buttons->button(QDialogButtonBox::Ok);
    layout->addWidget(buttons);
    m_password->setMinimumWidth(m_password->fontMetrics().averageCharWidth() * 30);

    for (QRadioButton* choice : {m_full, m_configure, m_readOnly})
        connect(choice, &QRadioButton::toggled, this, &ProtectedOpenDialog::updateFields);
    connect(buttons, &QDialogButtonBox::accepted, this, &ProtectedOpenDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &ProtectedOpenDialog::reject);
    m_wait.setInterval(1000);
    connect(&m_wait, &QTimer::timeout, this, &ProtectedOpenDialog::tick);
    updateFields();
}

void ProtectedOpenDialog::askForFullPermissionOnly() {
    setWindowTitle(tr("Accept the Change"));
    m_full->setChecked(true);
    m_configure->setEnabled(false);
    m_readOnly->setEnabled(false);
    updateFields();
}

project::Permission ProtectedOpenDialog::chosen() const {
    if (m_full->isChecked())
        return project::Permission::Full;
    if (m_configure->isChecked())
        return project::Permission::Configure;
    return project::Permission::ReadOnly;
}

void ProtectedOpenDialog::updateFields() {
    const bool needed = project::needsPassword(m_protection, chosen());
    m_password->setEnabled(needed);
    if (needed)
        m_password->setFocus();
    m_ok->setEnabled(m_secondsLeft == 0 || !needed);
}

void ProtectedOpenDialog::tick() {
    if (--m_secondsLeft <= 0) {
        m_secondsLeft = 0;
        m_wait.stop();
        sayProblem(m_problem, tr("The password does not open the project with this permission."));
    } else {
        sayProblem(m_problem,
                   tr("The password does not open the project with this permission. Try again "
                      "in %n second(s).",
                      nullptr, m_secondsLeft));
    }
    updateFields();
}

void ProtectedOpenDialog::accept() {
    const project::Permission permission = chosen();
    if (m_secondsLeft > 0 && project::needsPassword(m_protection, permission))
        return;
    QApplication::setOverrideCursor(Qt::WaitCursor);
    std::optional<project::Keyring> keys =
        project::unlock(m_protection, permission, m_password->text().toStdString());
    QApplication::restoreOverrideCursor();
    if (!keys) {
        m_password->selectAll();
        m_secondsLeft = project::waitAfterRefusal(++m_refusals) + 1;
        m_wait.start();
        tick();
        return;
    }
    m_permission = permission;
    m_keys = std::move(*keys);
    QDialog::accept();
}

} // namespace rs::ui
