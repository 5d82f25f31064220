// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QPointer>
#include <QTimer>
#include <QWidget>

class QCheckBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QListWidget;
class QPlainTextEdit;
class QPushButton;

namespace rs::ui {

class SignatureLabel;

class PageTitle;
class ProjectDocument;
class SettledCompile;

// The page of a project (manual Part 1, 3.2, 3.3, 12): its name, description,
// the include-source option and the function libraries it uses, edited in
// place, and what it holds.
class ProjectPage : public QWidget {
    Q_OBJECT
public:
    explicit ProjectPage(QWidget* parent = nullptr);

    void showProject(ProjectDocument* document);

private:
    void refresh();
    void applyName();
    void applyDescription();
    void refreshLibraries();
    // What changed since validation, as the document's SettledCompile found it.
    void refreshSinceValidation();
    void refreshProtection();
    void addLibrary(const QString& entry);
    void addUserLibrary();
    void removeLibrary();

    PageTitle* m_title;
    QLineEdit* m_name;
    QLabel* m_nameProblem;
    QPlainTextEdit* m_description;
    QCheckBox* m_includeSource;
    QLabel* m_file;
    QLabel* m_units;
    SignatureLabel* m_signature;
    QLabel* m_validated;
    QLabel* m_sinceValidation;
    QLabel* m_protection;
    QFormLayout* m_form;
    QListWidget* m_libraries;
    QPushButton* m_addStandard;
    QPushButton* m_addUser;
    QPushButton* m_remove;
    QTimer m_descriptionTimer;
    QPointer<ProjectDocument> m_document;
    QPointer<SettledCompile> m_compile;
    bool m_refreshing = false;
};

} // namespace rs::ui
