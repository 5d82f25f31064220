// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Holds core types by value, so their headers come in here; Qt 6.4's moc cannot
// parse the C++20 standard headers they bring in (<concepts>) and needs only the names.
#ifndef Q_MOC_RUN
#include "project/Project.h"
#include "project/VariableCsv.h"
#endif

#include <QDialog>

class QLabel;
class QLineEdit;
class QPushButton;
class QTreeWidget;

namespace rs::ui {

// Import Variable Names (manual Part 1, 10.4): reads a CSV file against the
// project and shows, before anything changes, which names and descriptions
// it sets and which rows it leaves out and why, by line. Only Import changes
// the project.
class CsvImportDialog : public QDialog {
    Q_OBJECT
public:
    CsvImportDialog(const project::Project& project, int station, QWidget* parent = nullptr);

    void setPath(const QString& path);
    // The project with the good rows in; valid after a preview with changes.
    const project::CsvImport& result() const { return m_result; }
    QTreeWidget* changesView() const { return m_changes; }
    QTreeWidget* problemsView() const { return m_problems; }

private:
    void preview();

    const project::Project& m_project;
    int m_station;
    QLineEdit* m_path;
    QLineEdit* m_prefix;
    QLabel* m_summary;
    QTreeWidget* m_changes;
    QTreeWidget* m_problems;
    QPushButton* m_import;
    project::CsvImport m_result;
};

} // namespace rs::ui
