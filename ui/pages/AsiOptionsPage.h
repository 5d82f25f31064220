// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Holds core types by value; Qt 6.4's moc cannot parse the C++20 headers
// they bring in and needs only the names.
#ifndef Q_MOC_RUN
#include "project/AsiOptions.h"
#endif

#include <QPointer>
#include <QWidget>

#include <functional>
#include <vector>

class QButtonGroup;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QScrollArea;
class QSpinBox;

namespace rs::ui {

class PageTitle;
class ProjectDocument;

// The AS-i Options page of a Pluto AS-i or B42 AS-i (manual Part 1,
// 7.1.2-7.1.4): the bus working mode, the unit's own slave address and what
// to optimise for, and the table of the 31 slave addresses and their B
// addresses with each slave's type, model, parameter, profile, channel
// monitoring and time limit. As on the I/O Options page, only what the slave
// can take is offered and a cell that does not apply stays empty. Each
// change is one undo step.
class AsiOptionsPage : public QWidget {
    Q_OBJECT
public:
    explicit AsiOptionsPage(QWidget* parent = nullptr);

    void showUnit(ProjectDocument* document, int station);

    static QString modeName(project::AsiMode mode);
    static QString slaveTypeName(project::AsiSlaveType type, bool bAddress);
    static QString monitoringName(project::ChannelMonitoring monitoring);

private:
    struct Row {
        project::AsiSlaveAddress address;
        QLabel* label = nullptr;
        QComboBox* type = nullptr;
        QComboBox* model = nullptr;
        QComboBox* parameter = nullptr;
        QPushButton* profile = nullptr;
        QComboBox* monitoring = nullptr;
        QDoubleSpinBox* timeLimit = nullptr;
    };

    void build();
    void refresh();
    void fill(Row& row, const project::AsiOptions& options);
    void changeBus(const QString& text, const std::function<void(project::AsiOptions&)>& change);
    void changeSlave(project::AsiSlaveAddress address,
                     const std::function<void(project::AsiSlave&)>& change);
    void editProfile(project::AsiSlaveAddress address);
    QString slaveLabel(project::AsiSlaveAddress address) const;

    PageTitle* m_title;
    QScrollArea* m_scroll;
    QWidget* m_content = nullptr;
    QButtonGroup* m_modes = nullptr;
    QSpinBox* m_slaveAddress = nullptr;
    QButtonGroup* m_optimisation = nullptr;
    QLabel* m_blockSlaves = nullptr;
    std::vector<Row> m_rows;
    QPointer<ProjectDocument> m_document;
    int m_station = 0;
    bool m_filling = false;
};

} // namespace rs::ui
