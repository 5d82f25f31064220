// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/Diagnostic.h"

#include <QTreeWidget>

namespace rs::ui {

// The list of the checker's findings, one row each: severity icon,
// line:column, message. Activating a row (double-click, Enter) asks for the
// place to be shown.
class ProblemsView : public QTreeWidget {
    Q_OBJECT
public:
    enum Column { LocationColumn = 0, MessageColumn = 1 };

    explicit ProblemsView(QWidget* parent = nullptr);

    void setDiagnostics(const lang::Diagnostics& diagnostics);

signals:
    void problemActivated(int line, int column);

protected:
    // An empty list says so, rather than looking like nothing was checked.
    void paintEvent(QPaintEvent* event) override;
};

} // namespace rs::ui
