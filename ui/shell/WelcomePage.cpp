// SPDX-License-Identifier: GPL-3.0-or-later
#include "shell/WelcomePage.h"

#include <QAction>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace rs::ui {

WelcomePage::WelcomePage(QWidget* parent) : QWidget(parent), m_buttons(new QHBoxLayout) {
    setObjectName(QStringLiteral("welcomePage"));
    auto* welcome = new QVBoxLayout(this);
    auto* heading = new QLabel(tr("<h2>No project is open</h2>"
                                  "<p>Start a new project, open one, or look at the example from "
                                  "the manual.</p>"),
                               this);
    heading->setAlignment(Qt::AlignCenter);
    welcome->addStretch();
    welcome->addWidget(heading);
    m_buttons->addStretch();
    m_buttons->addStretch();
    welcome->addLayout(m_buttons);
    welcome->addStretch();
}

void WelcomePage::offer(std::initializer_list<QAction*> commands) {
    for (QAction* action : commands) {
        auto* button =
            new QPushButton(action->icon(), action->text().remove(QLatin1Char('&')), this);
        connect(button, &QPushButton::clicked, action, &QAction::trigger);
        // between the stretches that centre the row
        m_buttons->insertWidget(m_buttons->count() - 1, button);
    }
}

} // namespace rs::ui
