// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Holds core types by value, so their headers come in here; Qt 6.4's moc cannot
// parse the C++20 standard headers they bring in (<concepts>) and needs only the names.
#ifndef Q_MOC_RUN
#include "lang/Address.h"
#endif

#include <QWidget>

#include <vector>

class QCompleter;
class QLabel;
class QLineEdit;
class QTableWidget;
class QTableWidgetItem;

namespace rs::ui {

class SimulationSession;

// The Watch dock: variables the user chose, by symbolic name or address
// (completed from the project), with their live values. Typing a value in
// the Value column sets an input or forces any other variable.
class WatchView : public QWidget {
    Q_OBJECT
public:
    enum Column { VariableColumn, NameColumn, ValueColumn };

    // A watched variable, or one channel (1 or 2) of a safe AS-i input slave.
    struct Entry {
        lang::Address address;
        int channel = 0;
        friend bool operator==(const Entry&, const Entry&) = default;
    };

    explicit WatchView(SimulationSession* session, QWidget* parent = nullptr);

    // Adds the variable by name or address, or NAME.ch1 for a channel of a
    // safe AS-i slave; the reason when it cannot.
    QString add(const QString& word);
    void remove(const Entry& entry);
    const std::vector<Entry>& variables() const { return m_variables; }

    QLineEdit* input() const { return m_input; }
    QTableWidget* table() const { return m_table; }
    void refresh();

private:
    void rebuild();
    void valueEdited(QTableWidgetItem* item);
    void showMenu(const QPoint& at);

    SimulationSession* m_session;
    QLineEdit* m_input;
    QCompleter* m_completer;
    QLabel* m_message;
    QTableWidget* m_table;
    std::vector<Entry> m_variables;
    bool m_refreshing = false;
};

} // namespace rs::ui
