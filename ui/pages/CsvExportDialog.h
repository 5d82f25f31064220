// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>

class QButtonGroup;
class QComboBox;
class QLineEdit;

namespace rs::project {
struct CsvExportOptions;
}

namespace rs::ui {

// Export Variable Names (manual Part 1, 10.4): global and/or local
// variables, a prefix for the names, the sort order, the separator a
// spreadsheet expects, and the file.
class CsvExportDialog : public QDialog {
    Q_OBJECT
public:
    CsvExportDialog(int station, const QString& suggestedPath, QWidget* parent = nullptr);

    project::CsvExportOptions options() const;
    QString path() const;
    void setPath(const QString& path);

private:
    int m_station;
    QButtonGroup* m_scope;
    QLineEdit* m_prefix;
    QButtonGroup* m_order;
    QComboBox* m_separator;
    QLineEdit* m_path;
};

} // namespace rs::ui
