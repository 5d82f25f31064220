// SPDX-License-Identifier: GPL-3.0-or-later
#include "WaveformPanel.h"

#include "SimulationSession.h"
#include "WaveformButtons.h"
#include "WaveformView.h"
#include "document/ProjectDocument.h"
#include "project/ProjectFile.h"
#include "project/VariableTable.h"
#include "shell/CompleterKeys.h"
#include "shell/StatusColors.h"

#include <QCompleter>
#include <QFileDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QStringListModel>
#include <QToolButton>

namespace rs::ui {

WaveformPanel::WaveformPanel(SimulationSession* session, QWidget* parent)
    : QWidget(parent), m_session(session), m_view(new WaveformView(&session->recorder(), this)),
      m_input(new QLineEdit(this)), m_completer(new QCompleter(this)), m_message(new QLabel(this)),
      m_remove(nullptr) {
    m_input->setObjectName(QStringLiteral("waveformInput"));
    m_input->setPlaceholderText(tr("Add a variable to plot"));
    m_input->setMinimumWidth(160);
    m_completer->setCaseSensitivity(Qt::CaseInsensitive);
    m_completer->setFilterMode(Qt::MatchContains);
    m_completer->setModel(new QStringListModel(m_completer));
    m_input->setCompleter(m_completer);
    finishCompletionInOneKey(m_completer);
    markAsError(m_message);
    m_message->hide();

    const WaveformButtons buttons = makeWaveformButtons(this, m_view);
    m_remove = buttons.remove;
    auto* removeAllButton = new QToolButton(this);
    removeAllButton->setText(tr("Remove All"));
    removeAllButton->setToolTip(tr("Stop plotting every variable, also those a scenario added"));
    removeAllButton->setObjectName(QStringLiteral("removeAllTracesButton"));

    layOutWaveformPanel(this, m_input,
                        {m_remove, removeAllButton, buttons.zoomIn, buttons.zoomOut, buttons.fit,
                         buttons.exportVcd},
                        m_message, m_view, [this](const QString& word) { return add(word); });
    connect(m_remove, &QToolButton::clicked, this, [this] {
        const int row = m_view->selectedRow();
        const auto& traces = m_session->recorder().traces();
        if (row < 0 || row >= static_cast<int>(traces.size()))
            return;
        m_session->recorder().remove(traces[static_cast<std::size_t>(row)].address);
        m_view->recordingChanged();
        m_remove->setEnabled(false);
    });
    connect(removeAllButton, &QToolButton::clicked, this, &WaveformPanel::removeAll);
    connect(buttons.exportVcd, &QToolButton::clicked, this, [this] {
        const QString error = exportVcd();
        if (!error.isEmpty())
            QMessageBox::warning(this, tr("Export VCD"), error);
    });
    m_view->setLabels([this](int row) {
        const lang::Address& address =
            m_session->recorder().traces()[static_cast<std::size_t>(row)].address;
        const ProjectDocument* document = m_session->document();
        const QString name =
            document ? QString::fromStdString(project::variableName(document->project(), address))
                     : QString();
        return QString::fromStdString(lang::toString(address)) +
               (name.isEmpty() ? QString() : QStringLiteral("  ") + name);
    });
    connect(m_session, &SimulationSession::updated, m_view, &WaveformView::recordingChanged);
    connect(m_session, &SimulationSession::projectChanged, this, [this] {
        m_view->recordingChanged();
        m_remove->setEnabled(false);
    });
    connect(m_session, &SimulationSession::stateChanged, this, [this] {
        static_cast<QStringListModel*>(m_completer->model())
            ->setStringList(m_session->operandWords());
        m_view->recordingChanged();
    });
}

QString WaveformPanel::add(const QString& word) {
    lang::Address address;
    QString error;
    if (!m_session->resolve(word, address, error))
        return error;
    m_session->recorder().add(address, m_session->simulation());
    m_view->recordingChanged();
    return {};
}

void WaveformPanel::removeAll() {
    m_session->recorder().removeAll();
    m_view->recordingChanged();
    m_remove->setEnabled(false);
}

QString WaveformPanel::exportVcd(const QString& requested) {
    if (m_session->recorder().isEmpty())
        return tr("Nothing is recorded yet: start the simulation or run a scenario.");
    QString path = requested;
    if (path.isEmpty()) {
        path = QFileDialog::getSaveFileName(this, tr("Export VCD"), QStringLiteral("waveform.vcd"),
                                            tr("Value Change Dumps (*.vcd);;All files (*)"));
        if (path.isEmpty())
            return {};
    }
    return project::writeTextFile(path, m_session->recorder().vcd("Rungsmith simulation"));
}

} // namespace rs::ui
