// SPDX-License-Identifier: GPL-3.0-or-later
#include "pl110/Pl110Window.h"

#include "MarksSnapshot.h"
#include "document/Autosave.h"
#include "pl110/Address.h"
#include "pl110/Pl110Document.h"
#include "pl110/Pl110LadderView.h"
#include "pl110/Pl110Lexer.h"
#include "pl110/Pl110LineDialog.h"
#include "pl110/Pl110NamesPage.h"
#include "pl110/Pl110Simulation.h"
#include "pl110/Pl110WaveformPanel.h"
#include "pl110/ProgramText.h"
#include "pl110/RungEditing.h"
#include "pl110/Rungs.h"
#include "shell/NamedIcon.h"
#include "shell/Preferences.h"
#include "text/ProgramEditor.h"

#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QLabel>
#include <QListWidget>
#include <QLocale>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QStatusBar>
#include <QTabWidget>
#include <QToolBar>

namespace rs::ui {

namespace {

// Typing is taken into the document after this pause, as one undo step per burst.
constexpr int kTypingPauseMs = 400;
// The live pages redraw at most this often, whatever the scan rate.
constexpr int kLiveRefreshMs = 50;

bool isBitAddress(const pl110::Address& address) {
    return address.width == pl110::Width::Bit;
}

QString diagnosticText(const lang::Diagnostic& d) {
    return QStringLiteral("%1:%2: %3: %4")
        .arg(d.line)
        .arg(d.column)
        .arg(d.severity == lang::Severity::Error ? Pl110Window::tr("error")
                                                 : Pl110Window::tr("warning"))
        .arg(QString::fromStdString(d.message));
}

} // namespace

Pl110Window::Pl110Window(Pl110Document* document, QWidget* parent)
    : QMainWindow(parent), m_document(document), m_simulation(new Pl110Simulation(document, this)),
      m_pages(new QTabWidget(this)), m_ladder(new Pl110LadderView(this)),
      m_editor(new ProgramEditor(new Pl110Lexer, this)),
      m_names(new Pl110NamesPage(document, this)), m_problems(new QListWidget(this)),
      m_scenarioOutput(new QPlainTextEdit(this)),
      m_waveform(new Pl110WaveformPanel(document, m_simulation, this)) {
    setObjectName(QStringLiteral("pl110Window"));
    setAttribute(Qt::WA_DeleteOnClose);
    document->setParent(this);

    m_editor->setObjectName(QStringLiteral("pl110Editor"));
    m_editor->setProjectUndo(true);
    m_pages->setObjectName(QStringLiteral("pl110Pages"));
    m_pages->setDocumentMode(true);
    m_pages->addTab(m_ladder, tr("Ladder"));
    m_pages->addTab(m_editor, tr("Program"));
    m_pages->addTab(m_names, tr("Names and Areas"));
    setCentralWidget(m_pages);

    m_problems->setObjectName(QStringLiteral("pl110Problems"));
    auto* problemsDock = new QDockWidget(tr("Problems"), this);
    problemsDock->setObjectName(QStringLiteral("pl110ProblemsDock"));
    problemsDock->setWidget(m_problems);
    addDockWidget(Qt::BottomDockWidgetArea, problemsDock);
    m_scenarioOutput->setObjectName(QStringLiteral("pl110ScenarioOutput"));
    m_scenarioOutput->setReadOnly(true);
    auto* scenarioDock = new QDockWidget(tr("Scenario Results"), this);
    scenarioDock->setObjectName(QStringLiteral("pl110ScenarioDock"));
    scenarioDock->setWidget(m_scenarioOutput);
    addDockWidget(Qt::BottomDockWidgetArea, scenarioDock);
    auto* waveformDock = new QDockWidget(tr("Waveform"), this);
    waveformDock->setObjectName(QStringLiteral("pl110WaveformDock"));
    waveformDock->setWidget(m_waveform);
    addDockWidget(Qt::BottomDockWidgetArea, waveformDock);
    tabifyDockWidget(problemsDock, scenarioDock);
    tabifyDockWidget(problemsDock, waveformDock);
    problemsDock->raise();
    resizeDocks({problemsDock}, {150}, Qt::Vertical);

    m_editor->setTextBytes(document->text());
    m_typing.setSingleShot(true);
    m_typing.setInterval(kTypingPauseMs);
    connect(&m_typing, &QTimer::timeout, this, &Pl110Window::applyTyping);
    connect(m_editor, &QsciScintilla::textChanged, this, [this] {
        if (!m_settingEditor)
            m_typing.start();
    });
    connect(&m_autosave, &QTimer::timeout, this, &Pl110Window::autosaveNow);
    m_autosave.start(Preferences::load().autosaveMinutes * 60 * 1000);
    m_liveRefresh.setSingleShot(true);
    m_liveRefresh.setInterval(kLiveRefreshMs);
    connect(&m_liveRefresh, &QTimer::timeout, this, &Pl110Window::refreshLive);

    connect(document, &Pl110Document::changed, this, &Pl110Window::followDocument);
    connect(document, &Pl110Document::pathChanged, this, &Pl110Window::updateTitle);
    connect(document, &Pl110Document::modifiedChanged, this, &Pl110Window::updateTitle);
    connect(m_ladder, &Pl110LadderView::operandClicked, this, &Pl110Window::operandClicked);
    connect(m_ladder, &Pl110LadderView::operandMenuRequested, this, &Pl110Window::operandMenu);
    connect(m_ladder, &Pl110LadderView::editRequested, this, &Pl110Window::editSelected);
    connect(m_problems, &QListWidget::itemActivated, this, [this](QListWidgetItem* item) {
        goToLine(item->data(Qt::UserRole).toInt(), item->data(Qt::UserRole + 1).toInt());
    });
    connect(m_names, &Pl110NamesPage::message, this,
            [this](const QString& text) { statusBar()->showMessage(text, 5000); });
    connect(
        m_names, &Pl110NamesPage::valueEntered, this,
        [this](const pl110::Address& address, qint64 value) { m_simulation->set(address, value); });
    connect(m_simulation, &Pl110Simulation::scanned, this, &Pl110Window::scheduleLiveRefresh);
    connect(m_simulation, &Pl110Simulation::started, this, &Pl110Window::updateSimulationActions);
    connect(m_simulation, &Pl110Simulation::stopped, this, [this](const QString& why) {
        updateSimulationActions();
        if (!why.isEmpty())
            statusBar()->showMessage(why, 8000);
    });
    connect(m_simulation, &Pl110Simulation::discarded, this, &Pl110Window::refreshLive);

    createActions();
    followDocument();
    // Every named variable is plotted from the start; more are added by hand.
    for (const pl110::Line& line : document->program().declarations)
        if (const auto* declaration = std::get_if<pl110::NameDeclaration>(&line.body))
            m_simulation->record(declaration->variable.address);
    m_ladder->setFocus();
    resize(1180, 760);
}

Pl110Window::~Pl110Window() {
    Autosave::release(m_document->autosaveId());
}

QString Pl110Window::openWindow(const QString& path) {
    QString error;
    Pl110Document* document = Pl110Document::open(path, error);
    if (!document)
        return error;
    auto* window = new Pl110Window(document);
    window->show();
    return {};
}

Pl110Window* Pl110Window::newWindow(const QString& name) {
    auto* window = new Pl110Window(Pl110Document::create(name));
    window->show();
    return window;
}

void Pl110Window::createActions() {
    const auto action = [this](const QString& text, const char* name,
                               const QKeySequence& key = {}) {
        auto* created = new QAction(text, this);
        created->setObjectName(QString::fromLatin1(name));
        if (!key.isEmpty())
            created->setShortcut(key);
        return created;
    };
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* newProgram = action(tr("&New PL110 Program"), "pl110NewAction", QKeySequence::New);
    connect(newProgram, &QAction::triggered, this, [] { newWindow(tr("New program")); });
    QAction* open = action(tr("&Open..."), "pl110OpenAction", QKeySequence::Open);
    open->setIcon(namedIcon("document-open"));
    connect(open, &QAction::triggered, this, &Pl110Window::openOther);
    QAction* saveAction = action(tr("&Save"), "pl110SaveAction", QKeySequence::Save);
    saveAction->setIcon(namedIcon("document-save"));
    connect(saveAction, &QAction::triggered, this, &Pl110Window::save);
    QAction* saveAsAction = action(tr("Save &As..."), "pl110SaveAsAction", QKeySequence::SaveAs);
    connect(saveAsAction, &QAction::triggered, this, &Pl110Window::saveAs);
    QAction* close = action(tr("&Close"), "pl110CloseAction", QKeySequence::Close);
    connect(close, &QAction::triggered, this, &QWidget::close);
    file->addActions({newProgram, open, saveAction, saveAsAction});
    file->addSeparator();
    file->addAction(close);

    // One undo history for every page; typing in progress is taken in first.
    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = action(tr("&Undo"), "pl110UndoAction", QKeySequence::Undo);
    undo->setIcon(namedIcon("edit-undo"));
    connect(undo, &QAction::triggered, this, [this] {
        applyTyping();
        m_document->undoStack()->undo();
    });
    QAction* redo = action(tr("&Redo"), "pl110RedoAction");
    QList<QKeySequence> redoKeys = QKeySequence::keyBindings(QKeySequence::Redo);
    if (!redoKeys.contains(QKeySequence(Qt::CTRL | Qt::Key_Y)))
        redoKeys << QKeySequence(Qt::CTRL | Qt::Key_Y);
    redo->setShortcuts(redoKeys);
    redo->setIcon(namedIcon("edit-redo"));
    connect(redo, &QAction::triggered, this, [this] {
        applyTyping();
        m_document->undoStack()->redo();
    });
    const auto updateUndo = [this, undo, redo] {
        QUndoStack* stack = m_document->undoStack();
        undo->setEnabled(stack->canUndo() || m_typing.isActive());
        redo->setEnabled(stack->canRedo());
        undo->setText(stack->canUndo() ? tr("&Undo %1").arg(stack->undoText()) : tr("&Undo"));
        redo->setText(stack->canRedo() ? tr("&Redo %1").arg(stack->redoText()) : tr("&Redo"));
    };
    connect(m_document->undoStack(), &QUndoStack::indexChanged, this, updateUndo);
    connect(m_editor, &QsciScintilla::textChanged, this, updateUndo);
    updateUndo();
    QAction* format = action(tr("&Format Text"), "pl110FormatAction",
                             QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F));
    format->setStatusTip(tr("Write the program as the printer writes it: one space around "
                            "operators, names as declared"));
    connect(format, &QAction::triggered, this, [this] {
        applyTyping();
        if (!m_document->readsWhole()) {
            statusBar()->showMessage(tr("Fix the errors first: formatting would drop the lines "
                                        "that do not read."),
                                     8000);
            return;
        }
        m_document->setProgram(m_document->program(), tr("Format Text"));
    });
    edit->addActions({undo, redo});
    edit->addSeparator();
    edit->addAction(format);

    QMenu* view = menuBar()->addMenu(tr("&View"));
    const std::array pages = {std::pair{tr("&Ladder"), Page::Ladder},
                              std::pair{tr("&Program Text"), Page::Program},
                              std::pair{tr("&Names and Areas"), Page::Names}};
    int key = Qt::Key_1;
    for (const auto& [text, page] : pages) {
        QAction* show = action(text, "pl110PageAction", QKeySequence(Qt::CTRL | key++));
        connect(show, &QAction::triggered, this, [this, page = page] { showPage(page); });
        view->addAction(show);
    }

    createLadderActions(action);

    QMenu* simulation = menuBar()->addMenu(tr("&Simulation"));
    m_start = action(tr("&Start"), "pl110StartAction", QKeySequence(Qt::Key_F5));
    m_start->setStatusTip(tr("Run the program on the simulated clock; click an input's contact "
                             "to switch it"));
    m_start->setIcon(QIcon::fromTheme(QStringLiteral("media-playback-start")));
    connect(m_start, &QAction::triggered, this, [this] {
        applyTyping();
        simulationAnswer(m_simulation->start());
    });
    m_stop = action(tr("S&top"), "pl110StopAction", QKeySequence(Qt::SHIFT | Qt::Key_F5));
    m_stop->setStatusTip(tr("Hold the program and the clock; the state stays shown"));
    m_stop->setIcon(QIcon::fromTheme(QStringLiteral("media-playback-pause")));
    connect(m_stop, &QAction::triggered, m_simulation, &Pl110Simulation::stop);
    m_singleScan = action(tr("Single S&can"), "pl110SingleScanAction", QKeySequence(Qt::Key_F10));
    m_singleScan->setIcon(QIcon::fromTheme(QStringLiteral("media-skip-forward")));
    connect(m_singleScan, &QAction::triggered, this, [this] {
        applyTyping();
        simulationAnswer(m_simulation->singleScan());
    });
    m_reset = action(tr("&Reset"), "pl110ResetAction", QKeySequence(Qt::CTRL | Qt::Key_F5));
    m_reset->setStatusTip(tr("Power on again at time 0; inputs set and forces stay"));
    m_reset->setIcon(QIcon::fromTheme(QStringLiteral("view-refresh")));
    connect(m_reset, &QAction::triggered, this, [this] {
        applyTyping();
        simulationAnswer(m_simulation->reset());
    });
    QAction* serve = action(tr("Serve &Modbus RTU"), "pl110ServeModbusAction");
    serve->setCheckable(true);
    serve->setStatusTip(tr("Answer Modbus RTU requests on a pseudo-terminal, as the PL110's "
                           "serial port, from the simulated memory (slave 1)"));
    auto* device = new QLabel(this);
    device->setObjectName(QStringLiteral("pl110ModbusDevice"));
    statusBar()->addPermanentWidget(device);
    device->hide();
    connect(serve, &QAction::toggled, this, [this, serve, device](bool on) {
        applyTyping();
        if (!on) {
            m_simulation->stopServing();
            device->hide();
            return;
        }
        if (const QString error = m_simulation->serveModbus(1); !error.isEmpty()) {
            statusBar()->showMessage(error, 8000);
            const QSignalBlocker blocker(serve);
            serve->setChecked(false);
            return;
        }
        device->setText(tr("Modbus RTU: %1, slave 1").arg(m_simulation->modbusDevice()));
        device->show();
    });
    QAction* scenario = action(tr("Run Sce&nario..."), "pl110RunScenarioAction");
    scenario->setStatusTip(tr("Run a scenario file (.scn) from power on and list its results"));
    connect(scenario, &QAction::triggered, this, &Pl110Window::chooseScenario);
    simulation->addActions({m_start, m_stop, m_singleScan, m_reset});
    simulation->addSeparator();
    simulation->addActions({scenario, serve});

    QToolBar* tools = addToolBar(tr("Simulation"));
    tools->setObjectName(QStringLiteral("pl110ToolBar"));
    tools->addActions({saveAction, undo, redo});
    tools->addSeparator();
    tools->addActions({m_start, m_stop, m_singleScan, m_reset});
    // The ladder's edits for the mouse, on a row of their own.
    addToolBarBreak();
    QToolBar* ladderTools = addToolBar(tr("Ladder"));
    ladderTools->setObjectName(QStringLiteral("pl110LadderToolBar"));
    ladderTools->addActions(m_ladderEdits);
    updateSimulationActions();
}

void Pl110Window::createLadderActions(
    const std::function<QAction*(const QString&, const char*, const QKeySequence&)>& action) {
    // The ladder's keys work where the ladder has the focus; the menu reaches
    // the same actions from anywhere.
    const auto onLadder = [this](QAction* ladderAction, const QList<QKeySequence>& keys) {
        ladderAction->setShortcuts(keys);
        ladderAction->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        m_ladder->addAction(ladderAction);
        return ladderAction;
    };
    QMenu* ladder = menuBar()->addMenu(tr("&Ladder"));
    QAction* newRung = onLadder(action(tr("&New Rung..."), "pl110NewRungAction", {}),
                                {QKeySequence(Qt::Key_Insert)});
    newRung->setStatusTip(tr("Write a rung after the selected one: its output, '=' and its "
                             "condition"));
    connect(newRung, &QAction::triggered, this, [this] { this->newRung(false); });
    QAction* newInitRung =
        onLadder(action(tr("New Rung in &INIT..."), "pl110NewInitRungAction", {}),
                 {QKeySequence(Qt::SHIFT | Qt::Key_Insert)});
    newInitRung->setStatusTip(tr("Write a rung at the end of INIT, which runs once before the "
                                 "first scan"));
    connect(newInitRung, &QAction::triggered, this, [this] { this->newRung(true); });
    QAction* edit = onLadder(action(tr("&Edit..."), "pl110EditAction", {}),
                             {QKeySequence(Qt::Key_Return), QKeySequence(Qt::Key_Enter)});
    edit->setStatusTip(tr("Change the selected contact, or the selected rung as its line"));
    connect(edit, &QAction::triggered, this, &Pl110Window::editSelected);
    const auto inserting = [&](const QString& text, const char* name, QKeySequence key,
                               Insertion where) {
        QAction* created = onLadder(action(text, name, {}), {key});
        connect(created, &QAction::triggered, this, [this, where] { insertAtSelection(where); });
        return created;
    };
    QAction* after = inserting(tr("Contact &After..."), "pl110ContactAfterAction",
                               QKeySequence(Qt::Key_BracketRight), Insertion::After);
    QAction* before = inserting(tr("Contact &Before..."), "pl110ContactBeforeAction",
                                QKeySequence(Qt::Key_BracketLeft), Insertion::Before);
    QAction* parallel = inserting(tr("Contact in &Parallel..."), "pl110ContactParallelAction",
                                  QKeySequence(Qt::Key_Backslash), Insertion::Parallel);
    QAction* remove = onLadder(action(tr("&Delete"), "pl110DeleteAction", {}),
                               {QKeySequence(Qt::Key_Delete), QKeySequence(Qt::Key_Backspace)});
    remove->setStatusTip(tr("Delete the selected element; with the output selected, the rung"));
    connect(remove, &QAction::triggered, this, &Pl110Window::deleteSelected);
    QAction* up = onLadder(action(tr("Move Rung &Up"), "pl110MoveRungUpAction", {}),
                           {QKeySequence(Qt::CTRL | Qt::Key_Up)});
    connect(up, &QAction::triggered, this, [this] { moveSelectedRung(-1); });
    QAction* down = onLadder(action(tr("Move Rung Do&wn"), "pl110MoveRungDownAction", {}),
                             {QKeySequence(Qt::CTRL | Qt::Key_Down)});
    connect(down, &QAction::triggered, this, [this] { moveSelectedRung(1); });
    QAction* toggle =
        onLadder(action(tr("T&oggle"), "pl110ToggleAction", {}), {QKeySequence(Qt::Key_Space)});
    toggle->setStatusTip(tr("While simulating: switch the selected contact's input, or force "
                            "its variable the other way"));
    connect(toggle, &QAction::triggered, this, [this] {
        if (const ladder::ElementLayout* element = m_ladder->selectedElement())
            if (element->shape != ladder::Shape::Box && !element->address.isEmpty())
                operandClicked(element->address);
    });
    QAction* plot =
        onLadder(action(tr("Plot in &Waveform"), "pl110PlotAction", {}), {QKeySequence(Qt::Key_W)});
    plot->setStatusTip(tr("Record the selected contact's or output's variable in the waveform"));
    connect(plot, &QAction::triggered, this, [this] {
        const ladder::ElementLayout* element = m_ladder->selectedElement();
        if (!element || element->address.isEmpty())
            return;
        // A box's address line holds more than its variable ("T1 PT 80").
        const QString variable = element->address.section(u' ', 0, 0);
        const QString error = m_waveform->add(variable);
        statusBar()->showMessage(
            error.isEmpty() ? tr("%1 is plotted in the waveform").arg(variable) : error, 5000);
        if (error.isEmpty())
            m_waveform->parentWidget()->raise();
    });
    QAction* text =
        action(tr("Ladder or &Text"), "pl110LadderOrTextAction", QKeySequence(Qt::Key_F6));
    text->setStatusTip(tr("Switch between the ladder and the program text at the same rung"));
    connect(text, &QAction::triggered, this, [this] {
        if (m_pages->currentWidget() == m_ladder) {
            goToLine(std::max(m_ladder->selectedLine(), 1));
            return;
        }
        applyTyping();
        showPage(Page::Ladder);
        int line = 0;
        int index = 0;
        m_editor->getCursorPosition(&line, &index);
        m_ladder->select(pl110::rungAtLine(m_document->program(), line + 1)); // editor lines from 0
        m_ladder->setFocus();
    });
    ladder->addActions({newRung, newInitRung, edit, after, before, parallel, remove});
    ladder->addSeparator();
    ladder->addActions({up, down});
    m_ladderEdits = {newRung, edit, after, before, parallel, remove, up, down};
    ladder->addSeparator();
    ladder->addActions({toggle, plot, text});
    // Moving the selection: keys only.
    const std::array moves = {std::tuple{Qt::Key_Left, -1, 0}, std::tuple{Qt::Key_Right, 1, 0},
                              std::tuple{Qt::Key_Up, 0, -1}, std::tuple{Qt::Key_Down, 0, 1}};
    for (const auto& [key, columns, rungs] : moves) {
        QAction* move = onLadder(new QAction(this), {QKeySequence(key)});
        connect(move, &QAction::triggered, this, [this, columns = columns, rungs = rungs] {
            m_ladder->moveSelection(columns, rungs);
        });
    }
}

bool Pl110Window::mayEditLadder() {
    applyTyping();
    if (m_document->readsWhole())
        return true;
    statusBar()->showMessage(tr("Fix the errors on the Program page first: the ladder's edits "
                                "rewrite the text, and lines with errors would be lost."),
                             8000);
    return false;
}

void Pl110Window::applyLadderEdit(const QString& what, const std::string& refusal,
                                  const pl110::Program& edited, int select, std::uint16_t element) {
    if (!refusal.empty()) {
        statusBar()->showMessage(
            tr("%1 was not done: %2").arg(what, QString::fromStdString(refusal)), 8000);
        return;
    }
    m_document->setProgram(edited, what);
    m_ladder->select(select, element);
    m_ladder->setFocus();
}

QString Pl110Window::readProblem(const lang::Diagnostics& diagnostics) {
    if (diagnostics.empty())
        return {};
    const lang::Diagnostic& first = diagnostics.front();
    return tr("Column %1: %2").arg(first.column).arg(QString::fromStdString(first.message));
}

void Pl110Window::newRung(bool intoInit) {
    if (!mayEditLadder())
        return;
    const pl110::Program& program = m_document->program();
    Pl110LineDialog dialog(
        intoInit ? tr("New Rung in INIT") : tr("New Rung"),
        tr("The rung as its line is written: its output, '=' and its "
           "condition, for example Q1 = I1 * /I2"),
        QString(),
        [&program](const QString& text) {
            return readProblem(pl110::readRung(program, text.toStdString()).diagnostics);
        },
        this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    pl110::Program edited = program;
    const std::vector<pl110::NumberedRung> rungs = pl110::numberedRungs(program);
    // After the selected rung in its part; into INIT: after INIT's last rung.
    int after = m_ladder->selectedRung();
    bool init = after >= 1 && rungs[static_cast<std::size_t>(after - 1)].init;
    if (intoInit) {
        init = true;
        after = static_cast<int>(
            std::count_if(rungs.begin(), rungs.end(), [](const auto& rung) { return rung.init; }));
    }
    const std::string refusal = pl110::insertRung(
        edited, after, *pl110::readRung(program, dialog.text().toStdString()).line, init);
    applyLadderEdit(tr("New Rung"), refusal, edited, after + 1);
}

void Pl110Window::editSelected() {
    // A copy: the edit lays the ladder out again.
    const ladder::ElementLayout* selected = m_ladder->selectedElement();
    if (!selected || !mayEditLadder())
        return;
    const ladder::ElementLayout element = *selected;
    const pl110::Program& program = m_document->program();
    const int number = m_ladder->selectedRung();
    const pl110::NumberedRung rung =
        pl110::numberedRungs(program)[static_cast<std::size_t>(number - 1)];
    pl110::Program edited = program;
    if (element.output >= 0) {
        Pl110LineDialog dialog(
            tr("Edit Rung"),
            tr("The rung as its line is written: its output, '=' and its "
               "condition, and a comment after ';'"),
            QString::fromStdString(pl110::printRungLine(*rung.line)),
            [&program](const QString& text) {
                return readProblem(pl110::readRung(program, text.toStdString()).diagnostics);
            },
            this);
        if (dialog.exec() != QDialog::Accepted)
            return;
        const std::string refusal = pl110::replaceRung(
            edited, number, *pl110::readRung(program, dialog.text().toStdString()).line);
        applyLadderEdit(tr("Edit Rung"), refusal, edited, number);
        return;
    }
    const pl110::Circuit* node = ladder::nodeAt(rung.rung->condition, element.path.node);
    Pl110LineDialog dialog(
        tr("Edit Element"),
        tr("The element as a rung writes it: a contact such as I3 or /I3, a "
           "comparison such as (VW1 >= 10), NOT, P or N; several joined by * "
           "and + take its place together"),
        node ? QString::fromStdString(pl110::printCondition(*node)) : QString(),
        [&program](const QString& text) {
            return readProblem(pl110::readCondition(program, text.toStdString()).diagnostics);
        },
        this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const std::string refusal =
        pl110::replaceNode(edited, number, element.path.node,
                           *pl110::readCondition(program, dialog.text().toStdString()).circuit);
    applyLadderEdit(tr("Edit Element"), refusal, edited, number, element.element);
}

void Pl110Window::insertAtSelection(Insertion where) {
    // A copy: the edit lays the ladder out again.
    const ladder::ElementLayout* selected = m_ladder->selectedElement();
    if (!selected || !mayEditLadder())
        return;
    const ladder::ElementLayout element = *selected;
    const pl110::Program& program = m_document->program();
    const QString what = where == Insertion::Parallel ? tr("Contact in Parallel")
                         : where == Insertion::Before ? tr("Contact Before")
                                                      : tr("Contact After");
    Pl110LineDialog dialog(
        what,
        tr("A contact such as I3 or /I3, a comparison such as (VW1 >= 10), "
           "NOT, P or N, or several joined by * and +"),
        QString(),
        [&program](const QString& text) {
            return readProblem(pl110::readCondition(program, text.toStdString()).diagnostics);
        },
        this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const int number = m_ladder->selectedRung();
    // With the output selected, the part goes around or after the whole condition.
    const pl110::ElementNodePath path =
        element.output >= 0 ? pl110::ElementNodePath{} : element.path.node;
    const pl110::Circuit part = *pl110::readCondition(program, dialog.text().toStdString()).circuit;
    pl110::Program edited = program;
    const std::string refusal =
        where == Insertion::Parallel
            ? pl110::insertInParallel(edited, number, path, part)
            : pl110::insertInSeries(edited, number, path, part,
                                    where == Insertion::Before && element.output < 0
                                        ? ladder::Side::Before
                                        : ladder::Side::After);
    applyLadderEdit(what, refusal, edited, number, element.element);
}

void Pl110Window::deleteSelected() {
    // A copy: the edit lays the ladder out again.
    const ladder::ElementLayout* selected = m_ladder->selectedElement();
    if (!selected || !mayEditLadder())
        return;
    const ladder::ElementLayout element = *selected;
    const int number = m_ladder->selectedRung();
    pl110::Program edited = m_document->program();
    if (element.output >= 0) {
        applyLadderEdit(tr("Delete Rung"), pl110::removeRung(edited, number), edited,
                        std::max(1, number - 1));
        return;
    }
    // What takes the element's place is selected next.
    applyLadderEdit(tr("Delete Element"), pl110::removeElement(edited, number, element.path.node),
                    edited, number, element.element);
}

void Pl110Window::moveSelectedRung(int direction) {
    const int number = m_ladder->selectedRung();
    if (number == 0 || !mayEditLadder())
        return;
    const std::uint16_t element = m_ladder->selectedElement()->element;
    pl110::Program edited = m_document->program();
    applyLadderEdit(direction < 0 ? tr("Move Rung Up") : tr("Move Rung Down"),
                    pl110::moveRung(edited, number, direction), edited, number + direction,
                    element);
}

void Pl110Window::showPage(Page page) {
    m_pages->setCurrentIndex(static_cast<int>(page));
}

bool Pl110Window::showRung(int number) {
    showPage(Page::Ladder);
    return m_ladder->showRung(number);
}

void Pl110Window::applyTyping() {
    if (!m_typing.isActive())
        return;
    m_typing.stop();
    m_document->setText(m_editor->textBytes(), tr("Typing"), true);
}

void Pl110Window::followDocument() {
    if (m_editor->textBytes() != m_document->text()) {
        // Undo, redo or another page changed the text: show it where the user was.
        int line = 0;
        int index = 0;
        m_editor->getCursorPosition(&line, &index);
        const int firstShown = m_editor->firstVisibleLine();
        m_settingEditor = true;
        m_typing.stop();
        m_editor->setTextBytes(m_document->text());
        m_settingEditor = false;
        m_editor->setCursorPosition(std::min(line, std::max(m_editor->lines() - 1, 0)), index);
        m_editor->setFirstVisibleLine(firstShown);
    }
    const lang::Diagnostics& diagnostics = m_document->diagnostics();
    m_editor->setDiagnostics(diagnostics);
    m_problems->clear();
    for (const lang::Diagnostic& d : diagnostics) {
        auto* item = new QListWidgetItem(diagnosticText(d), m_problems);
        item->setData(Qt::UserRole, d.line);
        item->setData(Qt::UserRole + 1, d.column);
        item->setIcon(namedIcon(d.severity == lang::Severity::Error ? "error" : "warning"));
    }
    m_ladder->setProgram(m_document->program());
    const int errors = lang::errorCount(diagnostics);
    statusBar()->showMessage(
        errors == 0 ? tr("%n rung(s), no errors", nullptr, m_ladder->rungCount())
                    : tr("%n error(s): the ladder shows the lines that read", nullptr, errors));
    updateTitle();
    updateSimulationActions();
    refreshLive();
}

void Pl110Window::updateTitle() {
    setWindowTitle(tr("%1[*] — PL110 — Rungsmith").arg(m_document->displayName()));
    setWindowModified(m_document->isModified());
}

void Pl110Window::updateSimulationActions() {
    const bool running = m_simulation->isRunning();
    const bool runnable = m_document->isRunnable();
    m_start->setEnabled(!running && runnable);
    m_stop->setEnabled(running);
    m_singleScan->setEnabled(runnable);
    m_reset->setEnabled(runnable);
}

void Pl110Window::scheduleLiveRefresh() {
    if (!m_liveRefresh.isActive())
        m_liveRefresh.start();
}

void Pl110Window::refreshLive() {
    const pl110::ScanEngine* engine = m_simulation->engine();
    m_ladder->setPower(engine ? std::optional(render::snapshotOfMarks(engine->marks()))
                              : std::nullopt);
    m_names->showValues(engine);
    m_waveform->recordingChanged();
    if (!engine)
        return;
    const QString seconds =
        QLocale().toString(static_cast<double>(engine->timeMs()) / 1000.0, 'f', 2);
    statusBar()->showMessage(
        m_simulation->isRunning()
            ? tr("Simulating: %1 s, scan %2").arg(seconds).arg(engine->scans())
            : tr("Stopped at %1 s, scan %2").arg(seconds).arg(engine->scans()));
}

void Pl110Window::simulationAnswer(const QString& error) {
    if (!error.isEmpty()) {
        statusBar()->showMessage(error, 8000);
        m_problems->parentWidget()->raise();
    }
    updateSimulationActions();
}

void Pl110Window::operandClicked(const QString& address) {
    const pl110::ScanEngine* engine = m_simulation->engine();
    if (!engine) {
        statusBar()->showMessage(tr("Start the simulation (F5) to switch inputs from the ladder."),
                                 5000);
        return;
    }
    const pl110::AddressReading reading = pl110::readAddress(address.toStdString());
    if (reading.shape != pl110::AddressReading::Shape::Address || !isBitAddress(reading.address))
        return;
    // A click switches an input as its terminal would; any other bit is forced.
    const std::int64_t value = engine->value(reading.address) ? 0 : 1;
    m_simulation->set(reading.address, value);
    statusBar()->showMessage(reading.address.area == pl110::Area::Input
                                 ? tr("%1 set to %2").arg(address).arg(value)
                                 : tr("%1 forced to %2").arg(address).arg(value),
                             5000);
}

void Pl110Window::operandMenu(const QString& address, const QPoint& where) {
    const pl110::AddressReading reading = pl110::readAddress(address.toStdString());
    if (reading.shape != pl110::AddressReading::Shape::Address)
        return;
    const pl110::Address target = reading.address;
    const bool input = target.area == pl110::Area::Input;
    QMenu menu(this);
    menu.addAction(input ? tr("Set %1 to 1").arg(address) : tr("Force %1 to 1").arg(address), this,
                   [this, target] { m_simulation->set(target, 1); });
    menu.addAction(input ? tr("Set %1 to 0").arg(address) : tr("Force %1 to 0").arg(address), this,
                   [this, target] { m_simulation->set(target, 0); });
    QAction* release =
        menu.addAction(input ? tr("Let go of %1").arg(address) : tr("Release %1").arg(address),
                       this, [this, target] { m_simulation->release(target); });
    release->setEnabled(m_simulation->isForced(target));
    menu.addSeparator();
    menu.addAction(tr("Show in Program Text"), this, [this, address] {
        showPage(Page::Program);
        m_editor->findFirst(address, false, false, true, false, true, 0, 0);
    });
    menu.exec(where);
}

void Pl110Window::goToLine(int line, int column) {
    showPage(Page::Program);
    m_editor->goTo(line, column);
    m_editor->setFocus();
}

bool Pl110Window::save() {
    applyTyping();
    if (m_document->path().isEmpty())
        return saveAs();
    if (const QString error = m_document->save(); !error.isEmpty()) {
        QMessageBox::warning(this, tr("Save"), error);
        return false;
    }
    Autosave::remove(m_document->autosaveId());
    statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(m_document->path())),
                             5000);
    return true;
}

bool Pl110Window::saveAs() {
    applyTyping();
    const QString suggested = m_document->path().isEmpty()
                                  ? m_document->displayName() + QStringLiteral(".sps")
                                  : m_document->path();
    const QString path = QFileDialog::getSaveFileName(this, tr("Save PL110 Program As"), suggested,
                                                      tr("PL110 programs (*.sps)"));
    if (path.isEmpty())
        return false;
    if (const QString error = m_document->saveAs(path); !error.isEmpty()) {
        QMessageBox::warning(this, tr("Save As"), error);
        return false;
    }
    Autosave::remove(m_document->autosaveId());
    statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(path)), 5000);
    return true;
}

bool Pl110Window::maySaveOrDiscard() {
    applyTyping();
    if (!m_document->isModified())
        return true;
    const auto answer = QMessageBox::question(
        this, tr("Close"), tr("Save the changes to %1?").arg(m_document->displayName()),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save)
        return save();
    return answer == QMessageBox::Discard;
}

void Pl110Window::autosaveNow() {
    applyTyping();
    if (!m_document->isModified())
        return;
    const QString error = Autosave::write(m_document->autosaveId(), m_document->path(),
                                          m_document->displayName(), m_document->text());
    if (!error.isEmpty())
        statusBar()->showMessage(tr("Autosave failed: %1").arg(error), 8000);
}

void Pl110Window::closeEvent(QCloseEvent* event) {
    if (maySaveOrDiscard()) {
        m_simulation->stop();
        // Saved or discarded: the copy has done its work.
        Autosave::remove(m_document->autosaveId());
        event->accept();
    } else {
        event->ignore();
    }
}

void Pl110Window::openOther() {
    const QString directory = QFileInfo(m_document->path()).absolutePath();
    const QString path = QFileDialog::getOpenFileName(this, tr("Open PL110 Program"), directory,
                                                      tr("PL110 programs (*.sps);;All files (*)"));
    if (path.isEmpty())
        return;
    if (const QString error = openWindow(path); !error.isEmpty()) {
        QMessageBox box(QMessageBox::Warning, tr("Open"),
                        tr("Could not open “%1”.").arg(QDir::toNativeSeparators(path)),
                        QMessageBox::Ok, this);
        box.setInformativeText(error);
        box.exec();
    }
}

void Pl110Window::chooseScenario() {
    const QString directory = QFileInfo(m_document->path()).absolutePath();
    const QString path = QFileDialog::getOpenFileName(this, tr("Run Scenario"), directory,
                                                      tr("Scenarios (*.scn);;All files (*)"));
    if (path.isEmpty())
        return;
    if (const QString error = runScenario(path); !error.isEmpty())
        QMessageBox::warning(this, tr("Run Scenario"), error);
}

QString Pl110Window::runScenario(const QString& path) {
    applyTyping();
    const Pl110Simulation::ScenarioRun run = m_simulation->runScenario(path);
    if (!run.error.isEmpty())
        return run.error;
    QStringList lines;
    for (const std::string& line : run.report.diagnostics)
        lines << QString::fromStdString(line);
    for (const std::string& line : run.report.failures)
        lines << QString::fromStdString(line);
    lines << (run.report.diagnostics.empty()
                  ? tr("%1: %2 passed, %3 failed")
                        .arg(QFileInfo(path).fileName())
                        .arg(run.report.passed)
                        .arg(run.report.failed)
                  : tr("%1 did not run: it has errors").arg(QFileInfo(path).fileName()));
    m_scenarioOutput->setPlainText(lines.join(u'\n'));
    m_scenarioOutput->parentWidget()->raise();
    refreshLive();
    updateSimulationActions();
    return {};
}

} // namespace rs::ui
