// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/RemanentDialog.h"

#include "lang/Address.h"
#include "project/RemanentVariables.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>

namespace rs::ui {

namespace {

constexpr int kColumns = 4;
constexpr int kCount = project::kLastRemanent - project::kFirstRemanent + 1;

} // namespace

RemanentDialog::RemanentDialog(int station, const std::set<lang::Address>& selection,
                               QWidget* parent)
    : QDialog(parent), m_station(station), m_rule(new QLabel(this)) {
    setObjectName(QStringLiteral("remanentDialog"));
    setWindowTitle(tr("Remanent Variables of Pluto %1").arg(station));
    auto* intro =
        new QLabel(tr("Remanent variables keep their value when the power is off. "
                      "Registers R100-R131 and memories M100-M131 can be remanent in any "
                      "combination, except that with all the registers no memory can be."),
                   this);
    intro->setWordWrap(true);
    m_rule->setWordWrap(true);
    m_rule->setForegroundRole(QPalette::PlaceholderText);

    auto column = [&](lang::AddressKind kind, const QString& title,
                      std::vector<QCheckBox*>& boxes) {
        auto* group = new QGroupBox(title, this);
        auto* grid = new QGridLayout(group);
        const QString prefix = kind == lang::AddressKind::Register ? QStringLiteral("R%1.%2")
                                                                   : QStringLiteral("M%1.%2");
        for (int i = 0; i < kCount; ++i) {
            const int index = project::kFirstRemanent + i;
            auto* box = new QCheckBox(prefix.arg(station).arg(index), group);
            box->setObjectName(prefix.arg(station).arg(index));
            box->setChecked(selection.count({kind, station, index}) > 0);
            grid->addWidget(box, i / kColumns, i % kColumns);
            boxes.push_back(box);
            connect(box, &QCheckBox::toggled, this, &RemanentDialog::applyRule);
        }
        auto* all = new QPushButton(tr("All"), group);
        auto* none = new QPushButton(tr("None"), group);
        grid->addWidget(all, kCount / kColumns, kColumns - 2);
        grid->addWidget(none, kCount / kColumns, kColumns - 1);
        connect(all, &QPushButton::clicked, this, [&boxes] {
            for (QCheckBox* box : boxes)
                if (box->isEnabled())
                    box->setChecked(true);
        });
        connect(none, &QPushButton::clicked, this, [&boxes] {
            for (QCheckBox* box : boxes)
                box->setChecked(false);
        });
        return group;
    };
    auto* columns = new QHBoxLayout;
    columns->addWidget(column(lang::AddressKind::Register, tr("Registers"), m_registers));
    columns->addWidget(column(lang::AddressKind::Memory, tr("Memories"), m_memories));

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(columns);
    layout->addWidget(m_rule);
    layout->addWidget(buttons);
    applyRule();
}

QCheckBox* RemanentDialog::box(lang::AddressKind kind, int index) const {
    const auto& boxes = kind == lang::AddressKind::Register ? m_registers : m_memories;
    const int i = index - project::kFirstRemanent;
    return i >= 0 && i < kCount ? boxes[static_cast<std::size_t>(i)] : nullptr;
}

std::set<lang::Address> RemanentDialog::selection() const {
    std::set<lang::Address> selected;
    for (int i = 0; i < kCount; ++i) {
        const int index = project::kFirstRemanent + i;
        if (m_registers[static_cast<std::size_t>(i)]->isChecked())
            selected.insert({lang::AddressKind::Register, m_station, index});
        if (m_memories[static_cast<std::size_t>(i)]->isChecked())
            selected.insert({lang::AddressKind::Memory, m_station, index});
    }
    return selected;
}

void RemanentDialog::applyRule() {
    const bool allRegisters = std::all_of(m_registers.begin(), m_registers.end(),
                                          [](QCheckBox* box) { return box->isChecked(); });
    for (QCheckBox* box : m_memories) {
        const QSignalBlocker blocker(box);
        if (allRegisters)
            box->setChecked(false);
        box->setEnabled(!allRegisters);
    }
    m_rule->setText(allRegisters ? tr("All 32 registers are remanent, so no memory can be.")
                                 : QString());
    m_rule->setVisible(allRegisters);
}

} // namespace rs::ui
