// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QPointer>
#include <QWidget>

class QLabel;
class QPushButton;

namespace rs::ui {

class SignatureLabel;

class PageTitle;
class ProjectDocument;
class UnitSettingsForm;

// The page of a unit (manual Part 1, 5): its type, instruction set, IDFIX and
// description, edited in place; what its export and remanent variables take;
// how many of its timers, memories and registers are used, and how many of
// them by block instances.
class UnitPage : public QWidget {
    Q_OBJECT
public:
    explicit UnitPage(QWidget* parent = nullptr);

    void showUnit(ProjectDocument* document, int station);

signals:
    void remanentRequested(ProjectDocument* document, int station);

private:
    void refresh();
    void apply();
    void editAdvancedSettings();
    void editExternalComm();

    PageTitle* m_title;
    UnitSettingsForm* m_form;
    QLabel* m_undeclared;
    QLabel* m_exports;
    QLabel* m_remanent;
    QLabel* m_timers;
    QLabel* m_memories;
    QLabel* m_registers;
    SignatureLabel* m_signature;
    QPushButton* m_remanentButton;
    QLabel* m_canCycle;
    QPushButton* m_advancedButton;
    QLabel* m_externalComm;
    QPushButton* m_externalCommButton;
    QPointer<ProjectDocument> m_document;
    int m_station = 0;
};

} // namespace rs::ui
