// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QPointer>
#include <QTimer>
#include <QWidget>

class QCheckBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;

namespace rs::ui {

class PageTitle;
class ProjectDocument;

// The page of a project (manual Part 1, 3.2, 3.3, 12): its name, description
// and the include-source option, edited in place, and what it holds.
class ProjectPage : public QWidget {
    Q_OBJECT
public:
    explicit ProjectPage(QWidget* parent = nullptr);

    void showProject(ProjectDocument* document);

private:
    void refresh();
    void applyName();
    void applyDescription();

    PageTitle* m_title;
    QLineEdit* m_name;
    QLabel* m_nameProblem;
    QPlainTextEdit* m_description;
    QCheckBox* m_includeSource;
    QLabel* m_file;
    QLabel* m_units;
    QTimer m_descriptionTimer;
    QPointer<ProjectDocument> m_document;
    bool m_refreshing = false;
};

} // namespace rs::ui
