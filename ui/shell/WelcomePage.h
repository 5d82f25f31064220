// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

#include <initializer_list>

class QAction;
class QHBoxLayout;
class QLabel;
class QListWidget;

namespace rs::ui {

// The page shown while no project is open: what can be done first, with a
// button for each of those commands, and the projects opened last.
class WelcomePage : public QWidget {
    Q_OBJECT
public:
    explicit WelcomePage(QWidget* parent = nullptr);

    // Offers the commands as buttons, in this order, each named as its menu entry.
    void offer(std::initializer_list<QAction*> commands);
    // The projects opened or saved last, newest first; Return or a double
    // click opens one.
    void showRecent(const QStringList& paths);

signals:
    void openRequested(const QString& path);

private:
    QHBoxLayout* m_buttons;
    QLabel* m_recentHeading;
    QListWidget* m_recent;
};

} // namespace rs::ui
