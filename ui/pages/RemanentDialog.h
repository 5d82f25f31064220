// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// lupdate misreads a forward-declared enum with a base type, and moc cannot
// parse the C++20 headers lang/Address.h brings in; both need only the names.
#ifndef Q_MOC_RUN
#include "lang/Address.h"
#endif

#include <QDialog>

#include <set>
#include <vector>

class QCheckBox;
class QLabel;

namespace rs::ui {

// Remanent Variables (manual Part 1, 10.3): which of R100..R131 and
// M100..M131 keep their value at power off. When every register is chosen
// the memories cannot be, so their boxes are cleared and disabled.
class RemanentDialog : public QDialog {
    Q_OBJECT
public:
    RemanentDialog(int station, const std::set<lang::Address>& selection,
                   QWidget* parent = nullptr);

    std::set<lang::Address> selection() const;
    QCheckBox* box(lang::AddressKind kind, int index) const;

private:
    void applyRule();

    int m_station;
    std::vector<QCheckBox*> m_registers;
    std::vector<QCheckBox*> m_memories;
    QLabel* m_rule;
};

} // namespace rs::ui
