// SPDX-License-Identifier: GPL-3.0-or-later
#include "pl110/Pl110WaveformPanel.h"

#include "pl110/Pl110Document.h"
#include "pl110/Pl110Simulation.h"
#include "pl110/Rungs.h"
#include "pl110/Scenario.h"
#include "project/ProjectFile.h"
#include "shell/StatusColors.h"
#include "sim/WaveformButtons.h"
#include "sim/WaveformView.h"

#include <QFileDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QToolButton>

namespace rs::ui {

Pl110WaveformPanel::Pl110WaveformPanel(Pl110Document* document, Pl110Simulation* simulation,
                                       QWidget* parent)
    : QWidget(parent), m_document(document), m_simulation(simulation),
      m_view(new WaveformView(&simulation->recorder(), this)), m_input(new QLineEdit(this)),
      m_message(new QLabel(this)), m_remove(nullptr) {
    setObjectName(QStringLiteral("pl110WaveformPanel"));
    m_input->setObjectName(QStringLiteral("pl110WaveformInput"));
    m_input->setPlaceholderText(tr("Add a variable to plot: an address or a name"));
    m_input->setMinimumWidth(160);
    markAsError(m_message);
    m_message->hide();
    const WaveformButtons buttons = makeWaveformButtons(this, m_view);
    m_remove = buttons.remove;
    layOutWaveformPanel(this, m_input,
                        {m_remove, buttons.zoomIn, buttons.zoomOut, buttons.fit, buttons.exportVcd},
                        m_message, m_view, [this](const QString& word) { return add(word); });
    connect(m_remove, &QToolButton::clicked, this, [this] {
        const int row = m_view->selectedRow();
        const auto& traces = m_simulation->recorder().traces();
        if (row < 0 || row >= static_cast<int>(traces.size()))
            return;
        m_simulation->recorder().remove(traces[static_cast<std::size_t>(row)].address);
        m_remove->setEnabled(false);
        recordingChanged();
    });
    connect(buttons.exportVcd, &QToolButton::clicked, this, [this] {
        if (const QString error = exportVcd(); !error.isEmpty())
            QMessageBox::warning(this, tr("Export VCD"), error);
    });
    m_view->setLabels([this](int row) {
        const pl110::Address& address =
            m_simulation->recorder().traces()[static_cast<std::size_t>(row)].address;
        const std::string name = pl110::declaredName(m_document->program(), address);
        return QString::fromStdString(pl110::toString(address)) +
               (name.empty() ? QString() : QStringLiteral("  ") + QString::fromStdString(name));
    });
}

QString Pl110WaveformPanel::add(const QString& variable) {
    const pl110::ScenarioNames names(m_document->program());
    pl110::Address address;
    std::string error;
    if (!names.resolve(variable.trimmed().toStdString(), address, error))
        return QString::fromStdString(error);
    if (!m_simulation->record(address))
        return tr("%1 is plotted already").arg(variable.trimmed());
    recordingChanged();
    return {};
}

QString Pl110WaveformPanel::exportVcd(const QString& requested) {
    if (m_simulation->recorder().isEmpty())
        return tr("Nothing is recorded yet: start the simulation or run a scenario.");
    QString path = requested;
    if (path.isEmpty()) {
        path = QFileDialog::getSaveFileName(this, tr("Export VCD"), QStringLiteral("waveform.vcd"),
                                            tr("Value Change Dumps (*.vcd);;All files (*)"));
        if (path.isEmpty())
            return {};
    }
    return project::writeTextFile(path, m_simulation->recorder().vcd("Rungsmith PL110 simulation"));
}

void Pl110WaveformPanel::recordingChanged() {
    m_view->recordingChanged();
}

} // namespace rs::ui
