// SPDX-License-Identifier: GPL-3.0-or-later
#include "BusStatusView.h"

#include "SimulationSession.h"
#include "compiler/Signature.h"
#include "document/ProjectDocument.h"
#include "shell/StatusColors.h"
#include "shell/UnitCaption.h"

#include <QHeaderView>
#include <QTableWidget>
#include <QVBoxLayout>

#include <map>

namespace rs::ui {

namespace {

constexpr int kErrorCodeRegister = 11; // SR_ErrorCode

} // namespace

QString unitCodeText(int station, int code) {
    return code == 0 ? BusStatusView::tr("Pluto %1: E0=No Error").arg(station)
                     : BusStatusView::tr("Pluto %1: Er%2").arg(station).arg(code);
}

BusStatusView::BusStatusView(SimulationSession* session, QWidget* parent)
    : QWidget(parent), m_session(session), m_table(new QTableWidget(0, 5, this)) {
    m_table->setObjectName(QStringLiteral("busStatusTable"));
    m_table->setHorizontalHeaderLabels(
        {tr("Station"), tr("Pluto"), tr("State"), tr("Code"), tr("Signature")});
    m_table->horizontalHeaderItem(SignatureColumn)
        ->setToolTip(tr("The program signature of the unit's compiled code, as "
                        "rungsmith-cli signature prints it; it changes exactly when what "
                        "the unit does changes"));
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_table);
    connect(m_session, &SimulationSession::updated, this, &BusStatusView::refresh);
    connect(m_session, &SimulationSession::stateChanged, this, &BusStatusView::refresh);
}

void BusStatusView::setRow(int row, const QStringList& cells, bool failing) {
    for (int column = 0; column < cells.size(); ++column) {
        QTableWidgetItem* item = m_table->item(row, column);
        if (!item) {
            item = new QTableWidgetItem;
            m_table->setItem(row, column, item);
        }
        item->setText(cells[column]);
        const bool state = column == CodeColumn || column == StateColumn;
        item->setForeground(state && failing ? errorTextColor(palette())
                                             : palette().color(QPalette::Text));
    }
}

void BusStatusView::refresh() {
    const sim::Simulation* simulation = m_session->simulation();
    const ProjectDocument* document = m_session->document();
    const std::vector<int> stations =
        simulation && document ? document->project().stations() : std::vector<int>{};
    std::vector<std::pair<int, project::GatewayType>> gateways;
    if (simulation && document)
        for (const auto& [node, gateway] : document->project().gateways)
            gateways.emplace_back(node, gateway.type);
    m_table->setRowCount(static_cast<int>(stations.size() + gateways.size()));
    const bool running = m_session->state() == SimulationSession::State::Running;
    const std::vector<compiler::UnitImage>& images = m_session->images();
    if (images.empty()) {
        m_signatures.clear();
    } else if (m_signatures.empty() || images.front().projectSignature != m_signedProject) {
        m_signatures.clear();
        for (const compiler::UnitImage& image : images)
            m_signatures[image.station] =
                QString::fromStdString(compiler::signatureText(compiler::unitSignature(image)));
        m_signedProject = images.front().projectSignature;
    }
    for (int row = 0; row < static_cast<int>(stations.size()); ++row) {
        const int station = stations[static_cast<std::size_t>(row)];
        const bool present = simulation->unit(station) != nullptr;
        const int code =
            present ? static_cast<int>(simulation->value(
                          {lang::AddressKind::SystemRegister, station, kErrorCodeRegister}))
                    : 0;
        const QStringList cells{QString::number(station), unitCaption(document->project(), station),
                                !present  ? tr("Missing")
                                : running ? tr("Ok, running")
                                          : tr("Ok, stopped"),
                                present ? (code == 0 ? tr("E0=No Error") : tr("Er%1").arg(code))
                                        : QString(),
                                m_signatures.count(station) ? m_signatures[station] : QString()};
        setRow(row, cells, code != 0 || !present);
    }
    // The gateways are nodes of the bus too (Gateway manual 3.4), by node address.
    for (std::size_t i = 0; i < gateways.size(); ++i) {
        const int row = static_cast<int>(stations.size() + i);
        const QStringList cells{
            tr("G%1").arg(gateways[i].first),
            tr("Gateway %1 (%2)")
                .arg(gateways[i].first)
                .arg(QString::fromLatin1(project::gatewayTypeName(gateways[i].second).data())),
            running ? tr("Ok, running") : tr("Ok, stopped"), QString(), QString()};
        setRow(row, cells, false);
    }
}

} // namespace rs::ui
