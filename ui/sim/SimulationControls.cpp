// SPDX-License-Identifier: GPL-3.0-or-later
#include "SimulationControls.h"

#include "SimulationSession.h"

#include <QAction>
#include <QComboBox>
#include <QIcon>
#include <QLabel>
#include <QMenu>
#include <QToolBar>

namespace rs::ui {

namespace {

QString clockText(std::int64_t ms, std::uint64_t scans) {
    return SimulationControls::tr("t = %1 s  (%2 scans)")
        .arg(static_cast<double>(ms) / 1000.0, 0, 'f', 3)
        .arg(scans);
}

} // namespace

SimulationControls::SimulationControls(SimulationSession* session, QWidget* window)
    : QObject(window), m_session(session), m_menu(new QMenu(tr("&Simulate"), window)),
      m_toolBar(new QToolBar(tr("Simulate"), window)), m_speed(new QComboBox(window)),
      m_clock(new QLabel(window)) {
    const auto action = [this](const QString& text, const char* name, const QKeySequence& key,
                               const QString& tip) {
        auto* created = new QAction(text, this);
        created->setObjectName(QString::fromLatin1(name));
        created->setShortcut(key);
        created->setStatusTip(tip);
        return created;
    };
    m_simulate = action(tr("Si&mulation Mode"), "simulateAction", QKeySequence(Qt::Key_F9),
                        tr("Run the project in the simulator and show its live state; editing "
                           "ends it"));
    m_simulate->setCheckable(true);
    m_simulate->setIcon(QIcon::fromTheme(QStringLiteral("system-run")));
    m_start = action(tr("&Start"), "simulationStartAction", QKeySequence(Qt::Key_F5),
                     tr("Run the program on the simulated clock"));
    m_start->setIcon(QIcon::fromTheme(QStringLiteral("media-playback-start")));
    m_stop = action(tr("S&top"), "simulationStopAction", QKeySequence(Qt::SHIFT | Qt::Key_F5),
                    tr("Hold the program and the clock; the state stays shown"));
    m_stop->setIcon(QIcon::fromTheme(QStringLiteral("media-playback-pause")));
    m_singleScan = action(tr("Single S&can"), "simulationSingleScanAction",
                          QKeySequence(Qt::Key_F10), tr("Run one scan of every unit"));
    m_singleScan->setIcon(QIcon::fromTheme(QStringLiteral("media-skip-forward")));
    m_reset = action(tr("&Reset"), "simulationResetAction", QKeySequence(Qt::CTRL | Qt::Key_F5),
                     tr("Power on again at time 0; forces stay"));
    m_reset->setIcon(QIcon::fromTheme(QStringLiteral("view-refresh")));
    m_runScenario = action(tr("Run Sce&nario..."), "runScenarioAction", {},
                           tr("Run a scenario file (.scn) and list its results"));

    m_speed->setObjectName(QStringLiteral("simulationSpeed"));
    m_speed->addItem(tr("Real time"), SimulationSession::kRealTime);
    m_speed->addItem(tr("10x"), SimulationSession::kTenTimes);
    m_speed->addItem(tr("As fast as possible"), SimulationSession::kAsFastAsPossible);
    m_speed->setToolTip(tr("How fast the simulated clock runs"));
    m_clock->setObjectName(QStringLiteral("simulationClock"));
    m_clock->setContentsMargins(8, 0, 8, 0);
    m_clock->setToolTip(tr("The simulated clock"));

    m_menu->setObjectName(QStringLiteral("simulateMenu"));
    m_menu->addAction(m_simulate);
    m_menu->addSeparator();
    m_menu->addActions({m_start, m_stop, m_singleScan, m_reset});
    QMenu* speedMenu = m_menu->addMenu(tr("S&peed"));
    for (int i = 0; i < m_speed->count(); ++i) {
        QAction* choice = speedMenu->addAction(m_speed->itemText(i));
        connect(choice, &QAction::triggered, this, [this, i] { m_speed->setCurrentIndex(i); });
    }
    m_menu->addSeparator();
    m_menu->addAction(m_runScenario);

    m_toolBar->setObjectName(QStringLiteral("simulateToolBar"));
    m_toolBar->addAction(m_simulate);
    m_toolBar->addActions({m_start, m_stop, m_singleScan, m_reset});
    m_toolBar->addWidget(m_speed);
    m_toolBar->addWidget(m_clock);

    connect(m_simulate, &QAction::triggered, this, &SimulationControls::simulateToggled);
    connect(m_start, &QAction::triggered, this, [this] {
        if (!m_session->isActive())
            emit simulateToggled(true);
        m_session->start();
    });
    connect(m_stop, &QAction::triggered, m_session, &SimulationSession::stop);
    connect(m_singleScan, &QAction::triggered, this, [this] {
        if (!m_session->isActive())
            emit simulateToggled(true);
        m_session->singleScan();
    });
    connect(m_reset, &QAction::triggered, m_session, &SimulationSession::reset);
    connect(m_runScenario, &QAction::triggered, this, &SimulationControls::scenarioRequested);
    connect(m_speed, &QComboBox::currentIndexChanged, this,
            [this] { m_session->setSpeed(m_speed->currentData().toDouble()); });
    connect(m_session, &SimulationSession::stateChanged, this, &SimulationControls::updateActions);
    connect(m_session, &SimulationSession::updated, this, &SimulationControls::showClock);
    connect(m_session, &SimulationSession::scenarioStarted, this,
            &SimulationControls::updateActions);
    connect(m_session, &SimulationSession::scenarioFinished, this,
            &SimulationControls::updateActions);
    updateActions();
}

void SimulationControls::setProjectAvailable(bool available) {
    m_projectAvailable = available;
    updateActions();
}

void SimulationControls::showClock() {
    const sim::Simulation* simulation = m_session->simulation();
    m_clock->setText(simulation ? clockText(simulation->timeMs(), simulation->scans())
                                : tr("Not simulating"));
}

void SimulationControls::updateActions() {
    const SimulationSession::State state = m_session->state();
    const bool active = state != SimulationSession::State::Off;
    // While a scenario runs, its result will replace the simulation shown:
    // only leaving simulation mode (which cancels it) is offered.
    const bool free = !m_session->isRunningScenario();
    m_simulate->setChecked(active);
    m_simulate->setEnabled(active || m_projectAvailable);
    m_start->setEnabled(free && state != SimulationSession::State::Running &&
                        (active || m_projectAvailable));
    m_stop->setEnabled(state == SimulationSession::State::Running);
    m_singleScan->setEnabled(free && (active || m_projectAvailable));
    m_reset->setEnabled(free && active);
    m_runScenario->setEnabled(free && (active || m_projectAvailable));
    showClock();
}

} // namespace rs::ui
