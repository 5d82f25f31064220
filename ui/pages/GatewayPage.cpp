// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/GatewayPage.h"

#include "compiler/SystemInstruction.h"
#include "document/PermissionNote.h"
#include "document/ProjectDocument.h"
#include "project/ProjectGateways.h"
#include "project/UnitSettings.h"
#include "shell/PageTitle.h"
#include "shell/UnitCaption.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QVBoxLayout>

namespace rs::ui {

namespace {

constexpr int kGlobalDataIoType = 111;

} // namespace

QString GatewayPage::ioTypeText(int ioType) {
    if (ioType <= 99)
        return tr("%1 (user block)").arg(ioType);
    if (ioType == kGlobalDataIoType)
        return tr("%1 Global data").arg(ioType);
    for (const auto& instruction : compiler::kSystemInstructions)
        if (compiler::standardIoType(instruction.id) == ioType)
            return QStringLiteral("%1 %2").arg(ioType).arg(QString::fromLatin1(
                instruction.name.data(), static_cast<qsizetype>(instruction.name.size())));
    return QString::number(ioType);
}

GatewayPage::GatewayPage(QWidget* parent)
    : QWidget(parent), m_title(new PageTitle(this)), m_type(new QComboBox(this)),
      m_nodeLabel(new QLabel(this)), m_remove(new QPushButton(tr("&Remove Gateway..."), this)),
      m_cycle(new QSpinBox(this)), m_timeout(new QSpinBox(this)), m_timeoutNote(new QLabel(this)) {
    auto* content = new QWidget(this);
    auto* contentLayout = new QVBoxLayout(content);
    contentLayout->setContentsMargins(0, 0, 8, 0);

    auto* general = new QGroupBox(tr("Gateway"), content);
    auto* generalForm = new QFormLayout(general);
    m_type->setObjectName(QStringLiteral("gatewayType"));
    for (project::GatewayType type : project::gatewayTypes())
        m_type->addItem(QString::fromLatin1(project::gatewayTypeName(type).data()),
                        static_cast<int>(type));
    auto* typeLabel = new QLabel(tr("&Type:"), general);
    typeLabel->setBuddy(m_type);
    auto* typeRow = new QHBoxLayout;
    typeRow->addWidget(m_type);
    typeRow->addStretch();
    generalForm->addRow(typeLabel, typeRow);
    m_nodeLabel->setObjectName(QStringLiteral("gatewayNode"));
    auto* nodeRow = new QHBoxLayout;
    nodeRow->addWidget(m_nodeLabel, 1);
    m_remove->setObjectName(QStringLiteral("removeGatewayButton"));
    nodeRow->addWidget(m_remove);
    generalForm->addRow(tr("Node address:"), nodeRow);
    contentLayout->addWidget(general);
    connect(m_type, &QComboBox::activated, this, [this] {
        const auto type = static_cast<project::GatewayType>(m_type->currentData().toInt());
        change(tr("Set Gateway %1 Type").arg(m_node),
               [type](project::Gateway& g) { g.type = type; });
    });
    connect(m_remove, &QPushButton::clicked, this,
            [this] { emit removeRequested(m_document, m_node); });

    auto* toPluto = new QGroupBox(tr("Data to Pluto"), content);
    auto* toPlutoForm = new QFormLayout(toPluto);
    auto* packetRow = new QHBoxLayout;
    for (int packet = 0; packet < project::kToPlutoPackets; ++packet) {
        auto* box = new QCheckBox(tr("Packet &%1").arg(packet), toPluto);
        box->setObjectName(QStringLiteral("toPluto%1").arg(packet));
        m_packets[static_cast<std::size_t>(packet)] = box;
        packetRow->addWidget(box);
        connect(box, &QCheckBox::toggled, this, [this, packet](bool on) {
            change(on ? tr("Enable Data to Pluto Packet %1").arg(packet)
                      : tr("Disable Data to Pluto Packet %1").arg(packet),
                   [packet, on](project::Gateway& g) {
                       if (on)
                           g.toPluto.insert(packet);
                       else
                           g.toPluto.erase(packet);
                   });
        });
    }
    packetRow->addStretch();
    toPlutoForm->addRow(tr("Enabled:"), packetRow);
    m_cycle->setObjectName(QStringLiteral("gatewayCycle"));
    m_cycle->setRange(project::kMinGatewayCycleMs, project::kMaxGatewayCycleMs);
    m_cycle->setSuffix(tr(" ms"));
    m_cycle->setKeyboardTracking(false);
    auto* cycleLabel = new QLabel(tr("&Cycle time:"), toPluto);
    cycleLabel->setBuddy(m_cycle);
    auto* cycleRow = new QHBoxLayout;
    cycleRow->addWidget(m_cycle);
    cycleRow->addStretch();
    toPlutoForm->addRow(cycleLabel, cycleRow);
    connect(m_cycle, &QSpinBox::valueChanged, this, [this](int ms) {
        change(tr("Set Gateway %1 Cycle Time").arg(m_node),
               [ms](project::Gateway& g) { g.cycleMs = ms; });
    });
    m_timeout->setObjectName(QStringLiteral("gatewayTimeout"));
    m_timeout->setRange(0, project::kMaxGatewayTimeoutMs);
    m_timeout->setSingleStep(100);
    m_timeout->setSuffix(tr(" ms"));
    m_timeout->setSpecialValueText(tr("No timeout"));
    m_timeout->setKeyboardTracking(false);
    auto* timeoutRow = new QHBoxLayout;
    timeoutRow->addWidget(m_timeout);
    m_timeoutNote->setForegroundRole(QPalette::PlaceholderText);
    timeoutRow->addWidget(m_timeoutNote, 1);
    auto* timeoutLabel = new QLabel(tr("T&imeout:"), toPluto);
    timeoutLabel->setBuddy(m_timeout);
    toPlutoForm->addRow(timeoutLabel, timeoutRow);
    connect(m_timeout, &QSpinBox::valueChanged, this, [this](int ms) {
        change(tr("Set Gateway %1 Timeout").arg(m_node),
               [ms](project::Gateway& g) { g.timeoutMs = ms; });
    });
    contentLayout->addWidget(toPluto);

    auto* expected = new QGroupBox(tr("Expected nodes"), content);
    auto* expectedGrid = new QGridLayout(expected);
    for (int node = 0; node < 32; ++node) {
        auto* box = new QCheckBox(QString::number(node), expected);
        box->setObjectName(QStringLiteral("expected%1").arg(node));
        m_expected[static_cast<std::size_t>(node)] = box;
        expectedGrid->addWidget(box, node / 8, node % 8);
        connect(box, &QCheckBox::toggled, this, [this, node](bool on) {
            change(tr("Set Gateway %1 Expected Nodes").arg(m_node),
                   [node, on](project::Gateway& g) {
                       if (on)
                           g.expectedNodes.insert(node);
                       else
                           g.expectedNodes.erase(node);
                   });
        });
    }
    contentLayout->addWidget(expected);

    auto* areas = new QGroupBox(tr("Additional data areas"), content);
    auto* areaGrid = new QGridLayout(areas);
    areaGrid->addWidget(new QLabel(tr("Area"), areas), 0, 0);
    areaGrid->addWidget(new QLabel(tr("Pluto"), areas), 0, 1);
    areaGrid->addWidget(new QLabel(tr("IO-type"), areas), 0, 2);
    for (int area = 0; area < project::kGatewayAreas; ++area) {
        AreaRow& row = m_areas[static_cast<std::size_t>(area)];
        row.pluto = new QComboBox(areas);
        row.pluto->setObjectName(QStringLiteral("areaPluto%1").arg(area));
        row.ioType = new QComboBox(areas);
        row.ioType->setObjectName(QStringLiteral("areaIoType%1").arg(area));
        for (int ioType = project::kMinIoType; ioType <= project::kMaxIoType; ++ioType)
            row.ioType->addItem(ioTypeText(ioType), ioType);
        auto* label = new QLabel(QString::number(area), areas);
        label->setBuddy(row.pluto);
        areaGrid->addWidget(label, area + 1, 0);
        areaGrid->addWidget(row.pluto, area + 1, 1);
        areaGrid->addWidget(row.ioType, area + 1, 2);
        const auto apply = [this, area] {
            const AreaRow& r = m_areas[static_cast<std::size_t>(area)];
            const int pluto = r.pluto->currentData().toInt();
            const int ioType = r.ioType->currentIndex() < 0 ? project::kMinIoType
                                                            : r.ioType->currentData().toInt();
            change(tr("Set Additional Data Area %1").arg(area),
                   [area, pluto, ioType](project::Gateway& g) {
                       if (pluto < 0)
                           g.areas.erase(area);
                       else
                           g.areas[area] = {pluto, ioType};
                   });
        };
        connect(row.pluto, &QComboBox::activated, this, apply);
        connect(row.ioType, &QComboBox::activated, this, apply);
    }
    areaGrid->setColumnStretch(3, 1);
    contentLayout->addWidget(areas);
    contentLayout->addStretch();

    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(content);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_title);
    layout->addWidget(scroll, 1);
}

void GatewayPage::showGateway(ProjectDocument* document, int node) {
    if (m_document)
        disconnect(m_document, nullptr, this, nullptr);
    m_document = document;
    m_node = node;
    if (!document)
        return;
    connect(document, &ProjectDocument::changed, this, &GatewayPage::refresh);
    connect(document, &ProjectDocument::permissionChanged, this, &GatewayPage::refresh);
    refresh();
}

void GatewayPage::refresh() {
    if (!m_document)
        return;
    const project::Project& p = m_document->project();
    const auto found = p.gateways.find(m_node);
    if (found == p.gateways.end())
        return;
    const project::Gateway& gateway = found->second;
    const QString typeName = QString::fromLatin1(project::gatewayTypeName(gateway.type).data());
    m_title->setTitle(tr("Gateway %1 (%2)").arg(m_node).arg(typeName));
    const QString note = permissionNote(m_document->permission());
    m_title->setSubtitle(note.isEmpty() ? tr("A node of the Pluto bus that passes the Plutos' data "
                                             "to a fieldbus and takes data to them back (Gateway "
                                             "manual). Project %1.")
                                              .arg(QString::fromStdString(p.name()))
                                        : note);
    const bool editable = m_document->permission() == project::Permission::Full;
    m_filling = true;
    m_type->setCurrentIndex(m_type->findData(static_cast<int>(gateway.type)));
    m_nodeLabel->setText(QString::number(m_node));
    for (int packet = 0; packet < project::kToPlutoPackets; ++packet)
        m_packets[static_cast<std::size_t>(packet)]->setChecked(gateway.toPluto.count(packet));
    m_cycle->setValue(gateway.cycleMs);
    const bool ethernet = project::servesModbusTcp(gateway.type);
    m_timeout->setValue(gateway.timeoutMs);
    m_timeoutNote->setText(ethernet ? tr("0 or %1-%2 ms on %3")
                                          .arg(project::kMinEthernetTimeoutMs)
                                          .arg(project::kMaxGatewayTimeoutMs)
                                          .arg(typeName)
                                    : tr("0-%1 ms").arg(project::kMaxGatewayTimeoutMs));
    for (int node = 0; node < 32; ++node)
        m_expected[static_cast<std::size_t>(node)]->setChecked(gateway.expectedNodes.count(node));
    for (int area = 0; area < project::kGatewayAreas; ++area) {
        AreaRow& row = m_areas[static_cast<std::size_t>(area)];
        row.pluto->clear();
        row.pluto->addItem(tr("Not used"), -1);
        for (int station = 0; station < 32; ++station) {
            const auto unit = project::unitSettings(p, station);
            row.pluto->addItem(unit ? unitCaption(*unit) : tr("Pluto %1").arg(station), station);
        }
        const auto used = gateway.areas.find(area);
        row.pluto->setCurrentIndex(
            row.pluto->findData(used == gateway.areas.end() ? -1 : used->second.pluto));
        // An area not used shows no IO-type; choosing its Pluto gives it the first.
        row.ioType->setCurrentIndex(
            used == gateway.areas.end() ? -1 : row.ioType->findData(used->second.ioType));
        row.ioType->setEnabled(editable && used != gateway.areas.end());
        row.pluto->setEnabled(editable);
    }
    m_type->setEnabled(editable);
    m_remove->setEnabled(editable);
    for (QCheckBox* box : m_packets)
        box->setEnabled(editable);
    m_cycle->setEnabled(editable);
    m_timeout->setEnabled(editable);
    for (QCheckBox* box : m_expected)
        box->setEnabled(editable);
    m_filling = false;
}

void GatewayPage::change(const QString& text, const std::function<void(project::Gateway&)>& edit) {
    if (m_filling || !m_document)
        return;
    const int node = m_node;
    auto found = m_document->project().gateways.find(node);
    if (found == m_document->project().gateways.end())
        return;
    project::Gateway changed = found->second;
    edit(changed);
    // A setting outside the manual's ranges (a GATE-E timeout under 1000 ms)
    // is not taken: the page shows the project's again.
    if (changed == found->second || project::gatewayProblem(changed) ||
        !m_document->edit(text,
                          [&](project::Project& p) { project::setGateway(p, node, changed); }))
        refresh();
}

} // namespace rs::ui
