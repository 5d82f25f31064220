// SPDX-License-Identifier: GPL-3.0-or-later
#include "shell/WelcomePage.h"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace rs::ui {

WelcomePage::WelcomePage(QWidget* parent)
    : QWidget(parent), m_buttons(new QHBoxLayout), m_recentHeading(new QLabel(this)),
      m_recent(new QListWidget(this)) {
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
    m_recentHeading->setText(tr("<b>&Recent projects</b>"));
    m_recentHeading->setBuddy(m_recent);
    m_recentHeading->setAlignment(Qt::AlignCenter);
    m_recentHeading->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
    m_recent->setObjectName(QStringLiteral("recentProjects"));
    m_recent->setMaximumWidth(640);
    auto* recent = new QVBoxLayout;
    recent->addSpacing(24);
    recent->addWidget(m_recentHeading);
    recent->addWidget(m_recent);
    auto* centred = new QHBoxLayout;
    centred->addStretch();
    centred->addLayout(recent, 1);
    centred->addStretch();
    welcome->addLayout(centred);
    welcome->addStretch();
    connect(m_recent, &QListWidget::itemActivated, this, [this](QListWidgetItem* item) {
        emit openRequested(item->data(Qt::UserRole).toString());
    });
    showRecent({});
}

void WelcomePage::showRecent(const QStringList& paths) {
    m_recent->clear();
    for (const QString& path : paths) {
        auto* item = new QListWidgetItem(
            QStringLiteral("%1 — %2").arg(QFileInfo(path).fileName(),
                                          QDir::toNativeSeparators(QFileInfo(path).path())),
            m_recent);
        item->setData(Qt::UserRole, path);
        item->setToolTip(QDir::toNativeSeparators(path));
    }
    m_recent->setCurrentRow(0);
    // As tall as its entries (ten at most), so the page stays one block.
    if (!paths.isEmpty())
        m_recent->setFixedHeight(m_recent->sizeHintForRow(0) * static_cast<int>(paths.size()) +
                                 2 * m_recent->frameWidth() + 4);
    m_recentHeading->setVisible(!paths.isEmpty());
    m_recent->setVisible(!paths.isEmpty());
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
