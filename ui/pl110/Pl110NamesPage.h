// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

class QLabel;
class QTableWidget;
class QTableWidgetItem;

#ifndef Q_MOC_RUN
#include "pl110/Address.h"
#endif

#include <vector>

namespace rs::pl110 {
class ScanEngine;
} // namespace rs::pl110

namespace rs::ui {

class Pl110Document;

// The PL110's names and memory areas: every declared name with its address
// and description, editable in place (renaming follows into the rungs), a
// last row to name another address, CSV import and export, the live value
// of each named variable while simulating, and the datasheet's areas with
// their addresses, access and Modbus addresses for reference.
class Pl110NamesPage : public QWidget {
    Q_OBJECT
public:
    explicit Pl110NamesPage(Pl110Document* document, QWidget* parent = nullptr);

    // The values of the named variables from the engine, or none.
    void showValues(const pl110::ScanEngine* engine);
    void importCsv(const QString& path);
    QString exportCsv(const QString& path, char separator) const;

Q_SIGNALS:
    void message(const QString& text);
    // While simulating, a value typed into the Value column: the keyboard's
    // way to set an input or force a variable.
    void valueEntered(const pl110::Address& address, qint64 value);

private:
    enum Column { AddressColumn, NameColumn, DescriptionColumn, ValueColumn };
    void fillNames();
    void fillAreas();
    void edited(QTableWidgetItem* item);
    void enterValue(QTableWidgetItem* item);
    void chooseImport();
    void chooseExport();
    bool canRewrite(const QString& what);

    Pl110Document* m_document;
    QTableWidget* m_names;
    QTableWidget* m_areas;
    QLabel* m_problem;
    std::vector<pl110::Address> m_addresses; // of the named rows, in order
    bool m_filling = false;
    bool m_live = false; // values are shown: the Value column takes new ones
};

} // namespace rs::ui
