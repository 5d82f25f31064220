// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/GatewayCommands.h"

#include "document/ProjectDocument.h"
#include "project/ProjectGateways.h"

#include <QAction>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QMessageBox>
#include <QVBoxLayout>

namespace rs::ui {

GatewayCommands::GatewayCommands(QWidget* window, std::function<PageRef()> current)
    : QObject(window), m_window(window), m_current(std::move(current)) {
    m_actions.newGateway = new QAction(tr("New &Gateway..."), m_window);
    m_actions.newGateway->setObjectName(QStringLiteral("newGatewayAction"));
    m_actions.newGateway->setStatusTip(tr("Add a Pluto Gateway to the project's bus"));
    connect(m_actions.newGateway, &QAction::triggered, this,
            [this] { newGateway(m_current().document); });
    m_actions.removeGateway = new QAction(tr("Remove Gate&way..."), m_window);
    m_actions.removeGateway->setObjectName(QStringLiteral("removeGatewayAction"));
    connect(m_actions.removeGateway, &QAction::triggered, this, [this] {
        const PageRef current = m_current();
        removeGateway(current.document, current.station);
    });
}

void GatewayCommands::updateActions(const PageRef& current) {
    const ProjectDocument* document = current.document;
    const bool writable =
        document && !document->isDamaged() && document->permission() == project::Permission::Full;
    m_actions.newGateway->setEnabled(writable &&
                                     !project::freeGatewayNodes(document->project()).empty());
    m_actions.removeGateway->setEnabled(writable && current.kind == PageRef::Kind::Gateway);
}

void GatewayCommands::newGateway(ProjectDocument* document) {
    if (!document || document->isDamaged())
        return;
    const std::vector<int> free = project::freeGatewayNodes(document->project());
    if (free.empty()) {
        QMessageBox::information(m_window, tr("New Gateway"),
                                 tr("Every gateway node address 0-15 is in use."));
        return;
    }
    QDialog dialog(m_window);
    dialog.setObjectName(QStringLiteral("newGatewayDialog"));
    dialog.setWindowTitle(tr("New Gateway"));
    auto* layout = new QVBoxLayout(&dialog);
    auto* intro = new QLabel(tr("A Pluto Gateway is a node of the Pluto bus that passes the "
                                "Plutos' data to a fieldbus. The Ethernet gateways (GATE-E1, "
                                "GATE-E2) serve Modbus TCP while simulating."),
                             &dialog);
    intro->setWordWrap(true);
    layout->addWidget(intro);
    auto* form = new QFormLayout;
    auto* type = new QComboBox(&dialog);
    type->setObjectName(QStringLiteral("newGatewayType"));
    for (project::GatewayType t : project::gatewayTypes())
        type->addItem(QString::fromLatin1(project::gatewayTypeName(t).data()), static_cast<int>(t));
    form->addRow(tr("&Type:"), type);
    auto* node = new QComboBox(&dialog);
    node->setObjectName(QStringLiteral("newGatewayNode"));
    for (int n : free)
        node->addItem(QString::number(n), n);
    form->addRow(tr("&Node address:"), node);
    layout->addLayout(form);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
    connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    layout->addWidget(buttons);
    dialog.resize(dialog.sizeHint().expandedTo(QSize(420, 0)));
    if (dialog.exec() != QDialog::Accepted)
        return;
    const int chosen = node->currentData().toInt();
    const auto chosenType = static_cast<project::GatewayType>(type->currentData().toInt());
    QString refusal;
    document->edit(tr("New Gateway %1").arg(chosen), [&](project::Project& p) {
        if (auto problem = project::addGateway(p, chosen, chosenType))
            refusal = QString::fromStdString(*problem);
    });
    if (!refusal.isEmpty()) {
        QMessageBox::warning(m_window, tr("New Gateway"), refusal);
        return;
    }
    emit gatewayAdded(document, chosen);
}

void GatewayCommands::removeGateway(ProjectDocument* document, int node) {
    if (!document || !document->project().gateways.count(node))
        return;
    const auto answer = QMessageBox::question(
        m_window, tr("Remove Gateway"),
        tr("Remove gateway %1 with its settings from the project? Units that receive its data "
           "keep their setting. Edit > Undo brings it back.")
            .arg(node));
    if (answer != QMessageBox::Yes)
        return;
    emit gatewayRemoving(document, node);
    document->edit(tr("Remove Gateway %1").arg(node),
                   [&](project::Project& p) { project::removeGateway(p, node); });
}

} // namespace rs::ui
