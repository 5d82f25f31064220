// SPDX-License-Identifier: GPL-3.0-or-later
#include "pl110/Pl110LineDialog.h"

#include "shell/StatusColors.h"

#include <QDialogButtonBox>
#include <QFontDatabase>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace rs::ui {

Pl110LineDialog::Pl110LineDialog(const QString& title, const QString& label, const QString& text,
                                 std::function<QString(const QString&)> problem, QWidget* parent)
    : QDialog(parent), m_problem(std::move(problem)), m_line(new QLineEdit(text, this)),
      m_message(new QLabel(this)),
      m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this)) {
    setObjectName(QStringLiteral("pl110LineDialog"));
    setWindowTitle(title);
    m_line->setObjectName(QStringLiteral("pl110LineEdit"));
    m_line->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_line->setMinimumWidth(520);
    m_message->setObjectName(QStringLiteral("pl110LineProblem"));
    m_message->setWordWrap(true);
    markAsError(m_message);
    auto* caption = new QLabel(label, this);
    caption->setBuddy(m_line);
    caption->setWordWrap(true);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(caption);
    layout->addWidget(m_line);
    layout->addWidget(m_message);
    layout->addWidget(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_line, &QLineEdit::textChanged, this, &Pl110LineDialog::check);
    check();
}

QString Pl110LineDialog::text() const {
    return m_line->text();
}

void Pl110LineDialog::check() {
    const QString problem = m_problem(m_line->text());
    m_message->setText(problem);
    m_message->setVisible(!problem.isEmpty());
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(problem.isEmpty());
}

} // namespace rs::ui
