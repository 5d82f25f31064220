// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "SimulationSession.h"

#include <QWidget>

class QTreeWidget;

namespace rs::ui {

// The Scenarios dock: each scenario run from the IDE with its count of
// passed and failed expectations, and its failures and syntax errors;
// double-clicking one asks to show its line.
class ScenarioResultsView : public QWidget {
    Q_OBJECT
public:
    explicit ScenarioResultsView(QWidget* parent = nullptr);

    void addResult(const SimulationSession::ScenarioResult& result);
    QTreeWidget* tree() const { return m_tree; }

signals:
    void lineActivated(const QString& path, int line);

private:
    QTreeWidget* m_tree;
};

} // namespace rs::ui
