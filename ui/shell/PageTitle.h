// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QLabel>

namespace rs::ui {

// The heading above a page: which project, unit and page it is, in a larger
// bold font, with an optional line of explanation under it.
class PageTitle : public QWidget {
    Q_OBJECT
public:
    explicit PageTitle(QWidget* parent = nullptr);

    void setTitle(const QString& title);
    void setSubtitle(const QString& subtitle);

private:
    QLabel* m_title;
    QLabel* m_subtitle;
};

} // namespace rs::ui
