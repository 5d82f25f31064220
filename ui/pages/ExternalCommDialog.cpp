// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/ExternalCommDialog.h"

#include "project/ProjectGateways.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QGridLayout>
#include <QLabel>
#include <QSpinBox>
#include <QVBoxLayout>

namespace rs::ui {

ExternalCommDialog::ExternalCommDialog(const project::Project& project, int station,
                                       QWidget* parent)
    : QDialog(parent) {
    setObjectName(QStringLiteral("externalCommDialog"));
    setWindowTitle(tr("External Communication of Pluto %1").arg(station));
    auto* layout = new QVBoxLayout(this);
    auto* intro = new QLabel(tr("Which gateway data this unit receives: each External Comm Block "
                                "takes one Data to Pluto packet of one gateway. A block that "
                                "receives nothing for its timeout is cleared, and the Ext blocks "
                                "of the code read it as not valid. The timeout must be greater "
                                "than the gateway's cycle time (Gateway manual 4.5.1)."),
                             this);
    intro->setWordWrap(true);
    layout->addWidget(intro);

    auto* grid = new QGridLayout;
    grid->addWidget(new QLabel(tr("Block"), this), 0, 0);
    grid->addWidget(new QLabel(tr("Gateway"), this), 0, 1);
    grid->addWidget(new QLabel(tr("Packet"), this), 0, 2);
    grid->addWidget(new QLabel(tr("Timeout"), this), 0, 3);
    const project::ExternalComm current = project::externalCommOf(project, station);
    for (int block = 0; block < project::kExternalCommBlocks; ++block) {
        Row& row = m_rows[static_cast<std::size_t>(block)];
        row.used = new QCheckBox(tr("Block &%1").arg(block), this);
        row.used->setObjectName(QStringLiteral("extBlock%1").arg(block));
        row.gateway = new QComboBox(this);
        row.gateway->setObjectName(QStringLiteral("extGateway%1").arg(block));
        for (const auto& [node, gateway] : project.gateways)
            row.gateway->addItem(
                tr("Gateway %1 (%2)")
                    .arg(node)
                    .arg(QString::fromLatin1(project::gatewayTypeName(gateway.type).data())),
                node);
        row.packet = new QSpinBox(this);
        row.packet->setObjectName(QStringLiteral("extPacket%1").arg(block));
        row.packet->setRange(0, project::kToPlutoPackets - 1);
        row.timeout = new QSpinBox(this);
        row.timeout->setObjectName(QStringLiteral("extTimeout%1").arg(block));
        row.timeout->setRange(0, project::kMaxExternalTimeoutMs);
        row.timeout->setSingleStep(100);
        row.timeout->setSuffix(tr(" ms"));
        row.timeout->setSpecialValueText(tr("No timeout"));
        row.timeout->setValue(project::kDefaultExternalTimeoutMs);
        const auto found = current.find(block);
        if (found != current.end()) {
            const auto& setting = found->second;
            if (row.gateway->findData(setting.gateway) < 0) // a gateway the project lacks
                row.gateway->addItem(tr("Gateway %1 (not in the project)").arg(setting.gateway),
                                     setting.gateway);
            row.gateway->setCurrentIndex(row.gateway->findData(setting.gateway));
            row.packet->setValue(setting.packet);
            row.timeout->setValue(setting.timeoutMs);
        }
        row.used->setChecked(found != current.end());
        // A block can receive only from a gateway of the project (or the one it names).
        row.used->setEnabled(row.gateway->count() > 0);
        const auto enable = [row](bool on) {
            row.gateway->setEnabled(on);
            row.packet->setEnabled(on);
            row.timeout->setEnabled(on);
        };
        enable(row.used->isChecked());
        connect(row.used, &QCheckBox::toggled, this, enable);
        grid->addWidget(row.used, block + 1, 0);
        grid->addWidget(row.gateway, block + 1, 1);
        grid->addWidget(row.packet, block + 1, 2);
        grid->addWidget(row.timeout, block + 1, 3);
    }
    grid->setColumnStretch(1, 1);
    layout->addLayout(grid);
    if (project.gateways.empty()) {
        auto* none = new QLabel(tr("The project has no gateway: add one with Project > New "
                                   "Gateway first."),
                                this);
        none->setWordWrap(true);
        none->setForegroundRole(QPalette::PlaceholderText);
        layout->addWidget(none);
    }
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
}

project::ExternalComm ExternalCommDialog::setting() const {
    project::ExternalComm comm;
    for (int block = 0; block < project::kExternalCommBlocks; ++block) {
        const Row& row = m_rows[static_cast<std::size_t>(block)];
        if (row.used->isChecked() && row.gateway->currentIndex() >= 0)
            comm[block] = {row.gateway->currentData().toInt(), row.packet->value(),
                           row.timeout->value()};
    }
    return comm;
}

} // namespace rs::ui
