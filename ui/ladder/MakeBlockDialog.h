// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#ifndef Q_MOC_RUN
#include "blocks/BlockDraft.h"
#endif

#include <QDialog>
#include <QString>
#include <QStringList>

#include <set>
#include <vector>

class QComboBox;
class QLabel;
class QLineEdit;
class QTableWidget;

namespace rs::ui {

// Make Block…: names a block made of the selected networks, the user
// library it goes to (a file in the project's folder) and its pins, which
// are drafted from the operands the networks use (blocks::draftBlock).
class MakeBlockDialog : public QDialog {
    Q_OBJECT
public:
    // `libraryFiles`: the file names of the user libraries in the project's
    // folder, the first the one offered.
    MakeBlockDialog(std::vector<lang::Line> lines, std::set<lang::Address> usedElsewhere,
                    const QStringList& libraryFiles, QWidget* parent = nullptr);

    // Once accepted: the block (version 1.0, with its description) and the
    // instance that stands for the networks.
    const blocks::BlockDraft& draft() const { return m_draft; }
    // The library's file name, in the project's folder, and the name a new
    // library gets.
    QString libraryFile() const;
    std::string newLibraryName() const;

    void accept() override;

private:
    void fillPins();

    std::vector<lang::Line> m_lines;
    std::set<lang::Address> m_usedElsewhere;
    blocks::BlockDraft m_draft;
    QLineEdit* m_name;
    QComboBox* m_library;
    QLineEdit* m_description;
    QTableWidget* m_pins;
    QLabel* m_problem;
};

} // namespace rs::ui
