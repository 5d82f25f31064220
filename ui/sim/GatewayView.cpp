// SPDX-License-Identifier: GPL-3.0-or-later
#include "sim/GatewayView.h"

#include "document/ProjectDocument.h"
#include "shell/UnitCaption.h"
#include "sim/ModbusService.h"
#include "sim/SimulationSession.h"

#include <QAction>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QToolButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace rs::ui {

namespace {

struct Row {
    int gateway = -1; // -1: the gateway's own row
    QString data;
    std::uint32_t value = 0;
    bool hasValue = true;
    QString note; // instead of bits
};

QString hex(std::uint32_t value) {
    return QStringLiteral("%1").arg(value, 8, 16, QLatin1Char('0')).toUpper();
}

// Bits 31..0 in groups of four, most significant first.
QString bits(std::uint32_t value) {
    QString text;
    for (int bit = 31; bit >= 0; --bit) {
        text += (value >> bit) & 1u ? QLatin1Char('1') : QLatin1Char('0');
        if (bit % 4 == 0 && bit > 0)
            text += QLatin1Char(' ');
    }
    return text;
}

std::uint32_t udint(const gateway::DataFromPluto& table, int address) {
    return std::uint32_t{table[static_cast<std::size_t>(address)]} << 16 |
           table[static_cast<std::size_t>(address) + 1];
}

} // namespace

GatewayView::GatewayView(SimulationSession* session, ModbusService* service, QAction* serve,
                         QWidget* parent)
    : QWidget(parent), m_session(session), m_service(service), m_serving(new QLabel(this)),
      m_tree(new QTreeWidget(this)) {
    auto* serveButton = new QToolButton(this);
    serveButton->setDefaultAction(serve);
    serveButton->setToolButtonStyle(Qt::ToolButtonTextOnly);
    m_serving->setObjectName(QStringLiteral("modbusServing"));
    m_serving->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_serving->setWordWrap(true);
    auto* top = new QHBoxLayout;
    top->addWidget(serveButton);
    top->addWidget(m_serving, 1);
    m_tree->setObjectName(QStringLiteral("gatewayTree"));
    m_tree->setHeaderLabels({tr("Data"), tr("Hex"), tr("Bits 31..0")});
    m_tree->setRootIsDecorated(true);
    m_tree->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 0);
    layout->addLayout(top);
    layout->addWidget(m_tree, 1);
    connect(m_session, &SimulationSession::updated, this, &GatewayView::refresh);
    connect(m_session, &SimulationSession::stateChanged, this, &GatewayView::refresh);
    connect(m_service, &ModbusService::servingChanged, this, &GatewayView::showService);
    connect(m_service, &ModbusService::clientsChanged, this, &GatewayView::showService);
    showService();
}

void GatewayView::showService() {
    if (!m_service->isServing()) {
        m_serving->setText(tr("Modbus TCP is not served."));
        return;
    }
    const QStringList clients = m_service->clients();
    m_serving->setText(
        clients.isEmpty()
            ? tr("Serving Modbus TCP on %1; no client is connected.").arg(m_service->address())
            : tr("Serving Modbus TCP on %1; clients: %2.")
                  .arg(m_service->address(), clients.join(QStringLiteral(", "))));
}

void GatewayView::refresh() {
    std::vector<Row> rows;
    const ProjectDocument* document = m_session->document();
    if (m_session->simulation() && document) {
        const project::Project& project = document->project();
        std::lock_guard lock(m_session->gatewayMutex());
        for (const auto& node : m_session->gateways()) {
            const project::Gateway& settings = node->settings();
            const int parent = static_cast<int>(rows.size());
            rows.push_back(
                {-1,
                 tr("Gateway %1 (%2)")
                     .arg(node->node())
                     .arg(QString::fromLatin1(project::gatewayTypeName(settings.type).data())),
                 0,
                 false,
                 {}});
            const gateway::DataFromPluto& table = node->dataFromPluto();
            rows.push_back({parent, tr("Node status"), udint(table, 1), true, {}});
            for (int station : project.stations())
                rows.push_back({parent,
                                unitCaption(project, station),
                                udint(table, 3 + 2 * station),
                                true,
                                {}});
            for (const auto& [area, source] : settings.areas)
                rows.push_back({parent,
                                tr("Additional data %1 (Pluto %2, IO-type %3)")
                                    .arg(area)
                                    .arg(source.pluto)
                                    .arg(source.ioType),
                                node->additionalData(area),
                                true,
                                {}});
            const gateway::DataToPluto& toPluto = node->dataToPluto();
            for (int packet : settings.toPluto) {
                const auto at = static_cast<std::size_t>(2 + 3 * packet);
                const bool valid = (toPluto[1] >> packet) & 1u;
                rows.push_back({parent, tr("Data to Pluto %1").arg(packet), toPluto[at], true,
                                valid ? tr("valid; register 0 = %1, register 1 = %2")
                                            .arg(static_cast<std::int16_t>(toPluto[at + 1]))
                                            .arg(static_cast<std::int16_t>(toPluto[at + 2]))
                                      : tr("not valid")});
            }
        }
    }
    QStringList shape;
    for (const Row& row : rows)
        shape << QStringLiteral("%1/%2").arg(row.gateway).arg(row.data);
    if (shape != m_shape) {
        m_tree->clear();
        std::vector<QTreeWidgetItem*> parents;
        for (const Row& row : rows) {
            QTreeWidgetItem* item =
                row.gateway < 0
                    ? new QTreeWidgetItem(m_tree)
                    : new QTreeWidgetItem(parents[static_cast<std::size_t>(row.gateway)]);
            parents.push_back(item);
            item->setText(DataColumn, row.data);
            item->setExpanded(true);
            const QFont fixed = QFontDatabase::systemFont(QFontDatabase::FixedFont);
            item->setFont(HexColumn, fixed);
            item->setFont(BitsColumn, fixed);
        }
        m_shape = shape;
    }
    int index = 0;
    for (QTreeWidgetItemIterator it(m_tree); *it; ++it, ++index) {
        const Row& row = rows[static_cast<std::size_t>(index)];
        if (!row.hasValue)
            continue;
        (*it)->setText(HexColumn, hex(row.value));
        (*it)->setText(BitsColumn, row.note.isEmpty() ? bits(row.value) : row.note);
    }
}

} // namespace rs::ui
