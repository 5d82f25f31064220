// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/AsiProfileDialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QVBoxLayout>

namespace rs::ui {

namespace {

// The meanings the manual gives (Part 1, 7.1.4); other digits are plain.
QString digitText(int part, int digit) {
    const QString hex = QString::number(digit, 16).toUpper();
    if (part == 0 && digit == 7)
        return AsiProfileDialog::tr("%1 (Outputs)").arg(hex);
    if (part == 1 && digit == 0xB)
        return AsiProfileDialog::tr("%1 (Safe slave)").arg(hex);
    if (part == 1 && digit == 0)
        return AsiProfileDialog::tr("%1 (Standard slave)").arg(hex);
    return hex;
}

} // namespace

AsiProfileDialog::AsiProfileDialog(const QString& slave, const project::AsiProfile& profile,
                                   QWidget* parent)
    : QDialog(parent), m_slave(slave), m_summary(new QLabel(this)) {
    setWindowTitle(tr("AS-i Profile"));
    setMinimumWidth(fontMetrics().averageCharWidth() * 56);
    auto* layout = new QVBoxLayout(this);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_summary);
    auto* form = new QFormLayout;
    const QString labels[4] = {tr("&I/O configuration:"), tr("I&D code:"), tr("ID&2:"),
                               tr("ID&1:")};
    const int values[4] = {profile.io, profile.id, profile.id2, profile.id1};
    for (int part = 0; part < 4; ++part) {
        m_digits[part] = new QComboBox(this);
        m_digits[part]->setObjectName(QStringLiteral("profileDigit%1").arg(part));
        for (int digit = 0; digit <= 0xF; ++digit)
            m_digits[part]->addItem(digitText(part, digit), digit);
        m_digits[part]->setCurrentIndex(values[part]);
        connect(m_digits[part], &QComboBox::currentIndexChanged, this,
                &AsiProfileDialog::showProfile);
        form->addRow(labels[part], m_digits[part]);
    }
    layout->addLayout(form);
    auto* examples =
        new QLabel(tr("Examples from the manual: S-0.B… a safe slave; S-7.B… a safe slave with "
                      "outputs; S-7.0… a standard non-safe slave with 4 inputs and 4 outputs. "
                      "The slave's own manual gives its profile."),
                   this);
    examples->setWordWrap(true);
    examples->setForegroundRole(QPalette::PlaceholderText);
    layout->addWidget(examples);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    showProfile();
}

project::AsiProfile AsiProfileDialog::profile() const {
    return {m_digits[0]->currentIndex(), m_digits[1]->currentIndex(), m_digits[2]->currentIndex(),
            m_digits[3]->currentIndex()};
}

QComboBox* AsiProfileDialog::digitBox(int part) const {
    return m_digits[part];
}

void AsiProfileDialog::showProfile() {
    m_summary->setText(tr("Profile for %1 = %2")
                           .arg(m_slave, QString::fromStdString(project::profileText(profile()))));
}

} // namespace rs::ui
