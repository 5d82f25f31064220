// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/Diagnostic.h"
#include "project/TextPlace.h"

#include <QAbstractTableModel>
#include <QIcon>

#include <optional>
#include <string>
#include <vector>

namespace rs::ui {

// The rows of the Output dock: the lines around a compile ("Compiling ...",
// "Wrote ...", the closing line) and a row per finding. A finding's texts
// are made when a view asks for them: a large project has tens of
// thousands, of which a view shows a few dozen.
class CompileOutputModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { PlaceColumn = 0, MessageColumn = 1 };

    struct Row {
        bool finding = false;
        std::optional<lang::Severity> severity; // a finding's, or an error line's
        project::TextPlace place;               // a finding's
        int column = 0;                         // a finding's, in its line
        int fileLine = 0;                       // a finding's, in the project file
        std::string message;                    // a finding's, as the compiler gave it
        QString text;                           // a line that is no finding
        QString toolTip;                        // a line that is no finding
        bool bold = false;
    };

    explicit CompileOutputModel(QObject* parent = nullptr);

    void setRows(std::vector<Row> rows);
    const Row& row(int index) const { return m_rows[static_cast<std::size_t>(index)]; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

private:
    std::vector<Row> m_rows;
    QIcon m_errorIcon;
    QIcon m_warningIcon;
};

} // namespace rs::ui
