// SPDX-License-Identifier: GPL-3.0-or-later
#include "SimulationMode.h"

#include "BusStatusView.h"
#include "ForcesView.h"
#include "GatewayView.h"
#include "ModbusService.h"
#include "ScenarioFileViewer.h"
#include "ScenarioResultsView.h"
#include "SimulationControls.h"
#include "WatchView.h"
#include "WaveformPanel.h"
#include "WaveformView.h"
#include "document/ProjectDocument.h"
#include "ladder/LadderPage.h"
#include "pages/VariableTableModel.h"
#include "pages/VariablesPage.h"
#include "shell/MainWindow.h"
#include "shell/Preferences.h"
#include "shell/StatusColors.h"

#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalBlocker>
#include <QStackedWidget>
#include <QStatusBar>
#include <QToolBar>
#include <QTreeWidget>

#include <algorithm>

namespace rs::ui {

namespace {

constexpr int kMessageMs = 4000;
constexpr int kBottomDockHeight = 230;
constexpr double kMostBottomDockShare = 0.3; // of the window's height: the page keeps the rest
constexpr int kErrorCodeRegister = 11;       // SR_ErrorCode
constexpr int kProgressSteps = 1000;

// The operand as the ladder page spells it ("/I0.2" for P(/I0.2)).
lang::Address addressOf(const QString& spelled) {
    QString word = spelled.trimmed();
    if (word.startsWith(QLatin1Char('/')))
        word.remove(0, 1);
    const lang::AddressWord read = lang::readAddressWord(word.toStdString());
    return read.shape == lang::AddressWord::Shape::Variable ? read.address : lang::Address{};
}

} // namespace

SimulationMode::SimulationMode(MainWindow* window)
    : QObject(window), m_window(window), m_controls(new SimulationControls(&m_session, window)),
      m_forces(new ForcesView(&m_session, window)), m_watch(new WatchView(&m_session, window)),
      m_bus(new BusStatusView(&m_session, window)),
      m_modbus(new ModbusService(
          [this](const gateway::ModbusRequest& request) { return m_session.answerModbus(request); },
          this)),
      m_serveModbus(new QAction(tr("Serve &Modbus TCP"), this)),
      m_gateway(new GatewayView(&m_session, m_modbus, m_serveModbus, window)),
      m_waveform(new WaveformPanel(&m_session, window)),
      m_scenarios(new ScenarioResultsView(window)), m_viewer(new ScenarioFileViewer(window)),
      m_unitCode(new QLabel(window)), m_scenarioProgress(new QProgressBar(window)),
      m_cancelScenario(new QPushButton(tr("Cancel"), window)) {
    QMenuBar* menuBar = window->menuBar();
    auto* help = window->findChild<QMenu*>(QStringLiteral("helpMenu"));
    menuBar->insertMenu(help ? help->menuAction() : nullptr, m_controls->menu());
    window->addToolBar(m_controls->toolBar());

    m_forcesDock = addDock(m_forces, tr("Forces"), "forcesDock");
    m_watchDock = addDock(m_watch, tr("Watch"), "watchDock");
    m_waveformDock = addDock(m_waveform, tr("Waveform"), "waveformDock", false);
    m_busDock = addDock(m_bus, tr("Bus Status"), "busStatusDock");
    m_gatewayDock = addDock(m_gateway, tr("Gateways"), "gatewayDock");
    m_serveModbus->setObjectName(QStringLiteral("serveModbusAction"));
    m_serveModbus->setCheckable(true);
    m_serveModbus->setEnabled(false);
    m_serveModbus->setStatusTip(tr("Answer Modbus TCP clients for the project's Ethernet gateway "
                                   "while simulating, at the address the preferences give"));
    m_controls->menu()->addSeparator();
    m_controls->menu()->addAction(m_serveModbus);
    connect(m_serveModbus, &QAction::toggled, this, &SimulationMode::serveModbus);
    connect(m_modbus, &ModbusService::message, this, &SimulationMode::message);
    m_scenariosDock = addDock(m_scenarios, tr("Scenarios"), "scenariosDock");
    if (auto* view = window->findChild<QMenu*>(QStringLiteral("viewMenu"))) {
        view->addSeparator();
        for (QDockWidget* dock :
             {m_forcesDock, m_watchDock, m_waveformDock, m_busDock, m_gatewayDock, m_scenariosDock})
            view->addAction(dock->toggleViewAction());
        view->addAction(m_controls->toolBar()->toggleViewAction());
    }

    m_unitCode->setObjectName(QStringLiteral("unitCodeLabel"));
    m_unitCode->setContentsMargins(8, 0, 8, 0);
    m_unitCode->hide();
    window->statusBar()->addPermanentWidget(m_unitCode);

    m_scenarioProgress->setObjectName(QStringLiteral("scenarioProgress"));
    m_scenarioProgress->setRange(0, kProgressSteps);
    m_scenarioProgress->setMaximumWidth(260);
    m_scenarioProgress->hide();
    m_cancelScenario->setObjectName(QStringLiteral("cancelScenarioButton"));
    m_cancelScenario->setToolTip(tr("Stop the scenario; the simulation shows where it got"));
    m_cancelScenario->hide();
    window->statusBar()->addPermanentWidget(m_scenarioProgress);
    window->statusBar()->addPermanentWidget(m_cancelScenario);
    connect(m_cancelScenario, &QPushButton::clicked, &m_session,
            &SimulationSession::cancelScenario);
    connect(&m_session, &SimulationSession::scenarioStarted, this, [this] {
        m_scenarioProgress->setValue(0);
        m_scenarioProgress->show();
        m_cancelScenario->show();
    });
    connect(&m_session, &SimulationSession::scenarioProgress, this,
            [this](qint64 reachedMs, qint64 totalMs) {
                // Steps of the bar, as the virtual time may well not fit an int.
                const double part =
                    totalMs > 0 ? std::min(1.0, static_cast<double>(reachedMs) / totalMs) : 0.0;
                m_scenarioProgress->setValue(static_cast<int>(part * kProgressSteps));
                m_scenarioProgress->setFormat(
                    tr("Scenario: %1 of %2 s")
                        .arg(static_cast<double>(reachedMs) / 1000.0, 0, 'f', 1)
                        .arg(static_cast<double>(totalMs) / 1000.0, 0, 'f', 1));
            });
    connect(&m_session, &SimulationSession::scenarioFinished, this,
            &SimulationMode::scenarioFinished);
    connect(&m_session, &SimulationSession::projectChanged, this, [this] {
        m_scenarios->tree()->clear();
        m_scenariosDock->hide();
    });

    connect(m_controls, &SimulationControls::simulateToggled, this, [this](bool on) {
        if (!on) {
            end();
            return;
        }
        const QString error = begin();
        if (!error.isEmpty())
            QMessageBox::warning(m_window, tr("Simulation"), error);
    });
    connect(m_controls, &SimulationControls::scenarioRequested, this, [this] {
        const QString path = QFileDialog::getOpenFileName(m_window, tr("Run Scenario"), QString(),
                                                          tr("Scenarios (*.scn);;All files (*)"));
        if (!path.isEmpty())
            startScenario(path);
    });
    connect(m_scenarios, &ScenarioResultsView::lineActivated, this,
            [this](const QString& path, int line) {
                const QString error = m_viewer->showLine(path, line);
                if (!error.isEmpty()) {
                    message(error);
                    return;
                }
                m_viewer->show();
                m_viewer->raise();
            });
    connect(&m_session, &SimulationSession::stateChanged, this, &SimulationMode::stateChanged);
    connect(&m_session, &SimulationSession::updated, this, &SimulationMode::refresh);
    connect(&m_session, &SimulationSession::endedBecause, this, &SimulationMode::message);
    connect(window, &MainWindow::pageChanged, this, [this] {
        m_controls->setProjectAvailable(m_window->currentDocument() != nullptr);
        refresh();
    });
    if (VariablesPage* variables = window->variablesPage()) {
        connect(variables, &VariablesPage::operandToggled, this, &SimulationMode::operandClicked);
        connect(variables, &VariablesPage::operandMenuRequested, this,
                &SimulationMode::showOperandMenu);
    }
    if (LadderPage* ladder = window->ladderPage()) {
        connect(ladder, &LadderPage::operandClicked, this, &SimulationMode::operandClicked);
        connect(ladder, &LadderPage::operandMenuRequested, this, &SimulationMode::showOperandMenu);
    }
    m_controls->setProjectAvailable(window->currentDocument() != nullptr);
}

SimulationMode::~SimulationMode() {
    // The server's thread answers through m_session, which goes before the children.
    m_modbus->stop();
    // The pages outlive nothing here, but must not keep a pointer to m_live.
    if (m_liveLadder)
        m_liveLadder->setLiveState(nullptr);
}

QDockWidget* SimulationMode::addDock(QWidget* content, const QString& title, const char* name,
                                     bool withProblems) {
    auto* dock = new QDockWidget(title, m_window);
    dock->setObjectName(QString::fromLatin1(name));
    dock->setWidget(content);
    m_window->addDockWidget(Qt::BottomDockWidgetArea, dock, Qt::Horizontal);
    auto* problems = m_window->findChild<QDockWidget*>(QStringLiteral("problemsDock"));
    if (withProblems && problems)
        m_window->tabifyDockWidget(problems, dock);
    dock->hide();
    return dock;
}

QString SimulationMode::begin() {
    ProjectDocument* document = m_window->currentDocument();
    const QString error = m_session.begin(document);
    if (!error.isEmpty())
        return error;
    showSimulationDocks(document);
    return {};
}

void SimulationMode::showSimulationDocks(const ProjectDocument* document) {
    if (m_lastSimulationDocks) {
        for (QDockWidget* dock : *m_lastSimulationDocks)
            dock->show();
    } else {
        for (QDockWidget* dock : {m_forcesDock, m_watchDock, m_waveformDock})
            dock->show();
        if (document->project().stations().size() > 1 || !document->project().gateways.empty())
            m_busDock->show();
        if (!document->project().gateways.empty())
            m_gatewayDock->show();
    }
    if (!m_simulationDocksShown)
        showBottomDocks();
    m_simulationDocksShown = true;
    m_forcesDock->raise();
    message(
        tr("Simulating %1. Editing the project ends the simulation.").arg(document->displayName()));
}

void SimulationMode::hideSimulationDocks() {
    if (!m_simulationDocksShown)
        return;
    m_simulationDocksShown = false;
    std::vector<QDockWidget*> shown;
    for (QDockWidget* dock : {m_forcesDock, m_watchDock, m_waveformDock, m_busDock, m_gatewayDock})
        if (dock->isVisible()) {
            shown.push_back(dock);
            dock->hide();
        }
    if (!shown.empty())
        m_lastSimulationDocks = std::move(shown);
}

void SimulationMode::serveModbus(bool on) {
    if (!on) {
        m_modbus->stop();
        return;
    }
    const Preferences preferences = Preferences::load();
    const QString error = m_modbus->start(preferences.modbusHost, preferences.modbusPort);
    if (!error.isEmpty()) {
        const QSignalBlocker blocker(m_serveModbus);
        m_serveModbus->setChecked(false);
        QMessageBox::warning(m_window, tr("Serve Modbus TCP"),
                             tr("Cannot serve Modbus TCP on %1:%2: %3. Choose another address or "
                                "port in the preferences.")
                                 .arg(preferences.modbusHost)
                                 .arg(preferences.modbusPort)
                                 .arg(error));
        return;
    }
    message(tr("Serving Modbus TCP on %1.").arg(m_modbus->address()));
    m_gatewayDock->show();
    m_gatewayDock->raise();
}

void SimulationMode::end() {
    m_session.end();
}

void SimulationMode::startScenario(const QString& path) {
    if (!m_session.startScenario(m_window->currentDocument(), path))
        message(tr("A scenario is running already."));
}

SimulationSession::ScenarioResult SimulationMode::runScenario(const QString& path) {
    return m_session.runScenario(m_window->currentDocument(), path);
}

void SimulationMode::scenarioFinished(const SimulationSession::ScenarioResult& result) {
    m_scenarioProgress->hide();
    m_cancelScenario->hide();
    // A run started from editing is a simulation like any other: its docks come too.
    if (const ProjectDocument* document = m_session.document(); document && m_session.simulation())
        showSimulationDocks(document);
    m_scenarios->addResult(result);
    m_scenariosDock->show();
    m_scenariosDock->raise();
    m_waveform->view()->zoomToFit();
    if (result.cancelled)
        message(tr("Scenario %1 cancelled at t = %2 s.")
                    .arg(QFileInfo(result.path).fileName())
                    .arg(static_cast<double>(result.endMs) / 1000.0, 0, 'f', 3));
}

void SimulationMode::showBottomDocks() {
    // Room for a few traces and list rows; the page keeps the rest.
    const int height = std::min(std::max(m_waveformDock->height(), kBottomDockHeight),
                                static_cast<int>(m_window->height() * kMostBottomDockShare));
    m_window->resizeDocks({m_waveformDock}, {height}, Qt::Vertical);
    m_window->resizeDocks({m_waveformDock}, {m_window->width() * 3 / 5}, Qt::Horizontal);
}

void SimulationMode::message(const QString& text) {
    m_window->statusBar()->showMessage(text, kMessageMs);
}

void SimulationMode::stateChanged() {
    const sim::Simulation* simulation = m_session.simulation();
    m_builder.reset();
    m_window->variablesPage()->setSimulation(simulation);
    if (!simulation && m_liveLadder) {
        m_liveLadder->setLiveState(nullptr);
        m_liveLadder = nullptr;
    }
    m_unitCode->setVisible(simulation != nullptr);
    bool ethernet = false;
    if (simulation && m_session.document())
        for (const auto& [node, gateway] : m_session.document()->project().gateways)
            ethernet = ethernet || project::servesModbusTcp(gateway.type);
    if (!ethernet)
        m_serveModbus->setChecked(false); // the simulation ended: so does serving
    m_serveModbus->setEnabled(ethernet);
    if (!simulation)
        hideSimulationDocks();
    refresh();
}

void SimulationMode::refresh() {
    const sim::Simulation* simulation = m_session.simulation();
    if (!simulation)
        return;
    const bool simulated = m_window->currentDocument() == m_session.document();
    auto* pages = m_window->findChild<QStackedWidget*>(QStringLiteral("pages"));
    QWidget* shown = pages ? pages->currentWidget() : nullptr;

    LadderPage* ladder = m_window->ladderPage();
    if (ladder && shown == ladder && simulated) {
        m_builder.update(m_live, *simulation, ladder->station(), ladder->pinVariables());
        ladder->setLiveState(&m_live);
        m_liveLadder = ladder;
    } else if (m_liveLadder && (!simulated || ladder->document() != m_session.document())) {
        m_liveLadder->setLiveState(nullptr);
        m_liveLadder = nullptr;
    }
    // Values of the simulated project only: another open project's page stays as it is.
    VariablesPage* variables = m_window->variablesPage();
    variables->setSimulation(variables->model()->document() == m_session.document() ? simulation
                                                                                    : nullptr);
    if (shown == variables)
        variables->refreshStatus();

    const int station = m_window->currentPage().station >= 0 ? m_window->currentPage().station
                        : simulation->stations().empty()     ? 0
                                                             : simulation->stations().front();
    if (simulation->unit(station)) {
        const auto code =
            simulation->value({lang::AddressKind::SystemRegister, station, kErrorCodeRegister});
        m_unitCode->setText(unitCodeText(station, static_cast<int>(code)));
        QPalette palette = m_unitCode->palette();
        palette.setColor(QPalette::WindowText,
                         code == 0 ? passTextColor(palette) : errorTextColor(palette));
        m_unitCode->setPalette(palette);
    }
}

void SimulationMode::operandClicked(const QString& spelled) {
    const lang::Address address = addressOf(spelled);
    if (!address.valid() || !m_session.isActive())
        return;
    if (!m_session.toggle(address))
        message(tr("%1 is not an input: right-click it to force it.").arg(spelled));
}

void SimulationMode::showOperandMenu(const QString& spelled, const QPoint& globalPosition) {
    const lang::Address address = addressOf(spelled);
    if (!address.valid() || !m_session.isActive())
        return;
    const QString name = QString::fromStdString(lang::toString(address));
    QMenu menu(m_window);
    menu.setObjectName(QStringLiteral("forceMenu"));
    if (address.isBit()) {
        connect(menu.addAction(tr("Force %1 to &0").arg(name)), &QAction::triggered, this,
                [this, address] { m_session.force(address, 0); });
        connect(menu.addAction(tr("Force %1 to &1").arg(name)), &QAction::triggered, this,
                [this, address] { m_session.force(address, 1); });
    }
    connect(menu.addAction(tr("Force %1 to a &Value...").arg(name)), &QAction::triggered, this,
            [this, address, name] {
                bool ok = false;
                const int value =
                    QInputDialog::getInt(m_window, tr("Force"), tr("Value of %1:").arg(name),
                                         static_cast<int>(m_session.simulation()->value(address)),
                                         -2147483647, 2147483647, 1, &ok);
                if (ok)
                    m_session.force(address, value);
            });
    QAction* release = menu.addAction(tr("&Release %1").arg(name));
    release->setEnabled(m_session.isForced(address));
    connect(release, &QAction::triggered, this, [this, address] { m_session.release(address); });
    menu.addSeparator();
    connect(menu.addAction(tr("&Watch %1").arg(name)), &QAction::triggered, this, [this, name] {
        m_watch->add(name);
        m_watchDock->show();
        m_watchDock->raise();
    });
    menu.exec(globalPosition);
}

} // namespace rs::ui
