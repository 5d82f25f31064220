// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Holds core types by value; Qt 6.4's moc cannot parse the C++20 headers
// they bring in and needs only the names.
#ifndef Q_MOC_RUN
#include "project/Gateway.h"
#endif

#include <QPointer>
#include <QWidget>

#include <array>
#include <functional>

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace rs::ui {

class PageTitle;
class ProjectDocument;

// A gateway of the project's bus (Gateway manual): its type, what it sends
// to the Plutos (the Data to Pluto packets, cycle time and timeout), the
// Plutos it expects, and the 32 additional data areas with the Pluto and
// IO-type each takes. Only the manual's ranges are offered; each change is
// one undo step.
class GatewayPage : public QWidget {
    Q_OBJECT
public:
    explicit GatewayPage(QWidget* parent = nullptr);

    void showGateway(ProjectDocument* document, int node);

    // "100 ToGateway_ErrorCode", "5 (user block)": how an IO-type reads.
    static QString ioTypeText(int ioType);

signals:
    void removeRequested(ProjectDocument* document, int node);

private:
    struct AreaRow {
        QComboBox* pluto = nullptr;
        QComboBox* ioType = nullptr;
    };

    void refresh();
    void change(const QString& text, const std::function<void(project::Gateway&)>& edit);

    PageTitle* m_title;
    QComboBox* m_type;
    QLabel* m_nodeLabel;
    QPushButton* m_remove;
    std::array<QCheckBox*, project::kToPlutoPackets> m_packets{};
    QSpinBox* m_cycle;
    QSpinBox* m_timeout;
    QLabel* m_timeoutNote;
    std::array<QCheckBox*, 32> m_expected{};
    std::array<AreaRow, project::kGatewayAreas> m_areas{};
    QPointer<ProjectDocument> m_document;
    int m_node = 0;
    bool m_filling = false;
};

} // namespace rs::ui
