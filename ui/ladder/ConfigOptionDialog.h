// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#ifndef Q_MOC_RUN
#include "ladder/ConfigOption.h"
#endif

#include <QDialog>
#include <QPointer>

#include <optional>

class QCheckBox;
class QLabel;
class QLineEdit;

namespace rs::ui {

class ProjectDocument;

// A Config Option's description, memory and check box (manual 11.6).
class ConfigOptionDialog : public QDialog {
    Q_OBJECT
public:
    ConfigOptionDialog(ProjectDocument* document, int station, const ladder::ConfigOption& option,
                       QWidget* parent = nullptr);

    const std::optional<ladder::ConfigOption>& option() const { return m_option; }
    void accept() override;

private:
    QPointer<ProjectDocument> m_document;
    int m_station;
    QLineEdit* m_description;
    QLineEdit* m_memory;
    QCheckBox* m_checked;
    QLabel* m_problem;
    std::optional<ladder::ConfigOption> m_option;
};

} // namespace rs::ui
