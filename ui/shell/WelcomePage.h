// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

#include <initializer_list>

class QAction;
class QHBoxLayout;

namespace rs::ui {

// The page shown while no project is open: what can be done first, with a
// button for each of those commands.
class WelcomePage : public QWidget {
    Q_OBJECT
public:
    explicit WelcomePage(QWidget* parent = nullptr);

    // Offers the commands as buttons, in this order, each named as its menu entry.
    void offer(std::initializer_list<QAction*> commands);

private:
    QHBoxLayout* m_buttons;
};

} // namespace rs::ui
