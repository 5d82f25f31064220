// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Holds core types by value; Qt 6.4's moc cannot parse the C++20 headers
// they bring in and needs only the names.
#ifndef Q_MOC_RUN
#include "project/Project.h"
#endif

#include <QDialog>

#include <array>

class QCheckBox;
class QComboBox;
class QSpinBox;

namespace rs::ui {

// A unit's External communication setting (manual Part 1, 5.3; Gateway
// manual 4.5): for each of its four External Comm Blocks, whether it
// receives, from which gateway, which packet, and the timeout after which
// its data is cleared.
class ExternalCommDialog : public QDialog {
    Q_OBJECT
public:
    ExternalCommDialog(const project::Project& project, int station, QWidget* parent = nullptr);

    project::ExternalComm setting() const;

private:
    struct Row {
        QCheckBox* used = nullptr;
        QComboBox* gateway = nullptr;
        QSpinBox* packet = nullptr;
        QSpinBox* timeout = nullptr;
    };
    std::array<Row, project::kExternalCommBlocks> m_rows;
};

} // namespace rs::ui
