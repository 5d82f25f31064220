// SPDX-License-Identifier: GPL-3.0-or-later
#include "shell/MainWindow.h"

#include "compiler/ProgramCheck.h"
#include "document/ProjectDocument.h"
#include "document/ProjectMerging.h"
#include "document/ProjectPaths.h"
#include "ladder/LadderPage.h"
#include "output/CompileOutput.h"
#include "output/ProblemsView.h"
#include "pages/AsiOptionsPage.h"
#include "pages/GatewayCommands.h"
#include "pages/GatewayPage.h"
#include "pages/IoOptionsPage.h"
#include "pages/MarkValidatedDialog.h"
#include "pages/ProjectPage.h"
#include "pages/UnitPage.h"
#include "pages/VariablesPage.h"
#include "project/Sequences.h"
#include "project/TextPlace.h"
#include "project/UnitSettings.h"
#include "prove/CounterexampleOpening.h"
#include "prove/PropertiesPage.h"
#include "prove/PropertyEditor.h"
#include "review/CompareDialog.h"
#include "shell/NamedIcon.h"
#include "shell/PreferencesDialog.h"
#include "shell/ProjectTree.h"
#include "shell/Theme.h"
#include "shell/WelcomePage.h"
#include "sim/SimulationMode.h"
#include "text/ProgramEditor.h"
#include "text/TextPage.h"

#include <Qsci/qsciglobal.h>

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QStackedWidget>
#include <QStatusBar>
#include <QToolBar>

namespace rs::ui {

namespace {

const QString kGeometryKey = QStringLiteral("mainWindow/geometry");
const QString kStateKey = QStringLiteral("mainWindow/state");

constexpr int kStatusMessageMs = 4000;

LadderColours ladderColoursOf(const Preferences& preferences) {
    return {preferences.ladderBackground,    preferences.ladderFocusedBackground,
            preferences.ladderComponentBody, preferences.ladderLines,
            preferences.ladderLinesOff,      preferences.ladderLinesOn};
}

} // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent), m_preferences(Preferences::load()) {
    setObjectName(QStringLiteral("mainWindow"));
    m_pages = new QStackedWidget(this);
    m_pages->setObjectName(QStringLiteral("pages"));
    setCentralWidget(m_pages);

    m_welcomePage = new WelcomePage(m_pages);
    m_projectPage = new ProjectPage(m_pages);
    m_unitPage = new UnitPage(m_pages);
    m_ioPage = new IoOptionsPage(m_pages);
    m_asiPage = new AsiOptionsPage(m_pages);
    m_gatewayPage = new GatewayPage(m_pages);
    m_variablesPage = new VariablesPage(m_pages);
    m_textPage = new TextPage(m_pages);
    m_ladderPage = new LadderPage(m_pages);
    m_propertiesPage = new PropertiesPage(m_pages);
    for (QWidget* page : std::initializer_list<QWidget*>{
             m_welcomePage, m_projectPage, m_unitPage, m_ioPage, m_asiPage, m_gatewayPage,
             m_variablesPage, m_textPage, m_ladderPage, m_propertiesPage})
        m_pages->addWidget(page);

    createCommands();
    createActions();
    createToolBar();
    createDocks();
    // Compiling reports in the Output dock and, while it runs, in the status bar.
    m_compileRun = new CompileRun(this, m_output, m_outputDock, m_textPage, m_ladderPage);
    connect(m_compileRun, &CompileRun::runningChanged, this, &MainWindow::updateActions);
    connect(m_compileRun, &CompileRun::message, this, &MainWindow::showMessage);
    createMenus();
    createStatusBar();
    m_simulation = new SimulationMode(this);
    m_simulation->session()->setUpdateInterval(m_preferences.screenUpdateMs);
    m_textPage->setWarnUnconfiguredIo(m_preferences.warnUnconfiguredIo);
    m_ladderPage->setColours(ladderColoursOf(m_preferences));

    const OpenProjects::Actions& projectActions = m_projects->actions();
    m_welcomePage->offer({projectActions.newProject, projectActions.open, projectActions.example});
    m_welcomePage->showRecent(m_projects->recentPaths());
    connect(m_welcomePage, &WelcomePage::openRequested, m_projects,
            [this](const QString& path) { m_projects->openFile(path); });

    connect(m_textPage, &TextPage::diagnosticsChanged, this, [this](const lang::Diagnostics& d) {
        m_problems->setDiagnostics(d);
        showSummary(d);
    });
    connect(m_textPage, &TextPage::repaired, this, [this](ProjectDocument* document) {
        rebuildTree();
        // The user was typing: the unit's code stays in the text editor.
        showFirstPageOf(document, PageRef::Kind::Code);
        showMessage(tr("The project reads without errors now; its pages are back."));
    });
    m_propertiesPage->setProveAllAction(m_proveAllAction);
    connect(m_propertiesPage, &PropertiesPage::provingChanged, this, &MainWindow::updateActions);
    connect(m_propertiesPage, &PropertiesPage::counterexampleRequested, this,
            [this](ProjectDocument* document, const PropertyProof& proof) {
                QString error;
                const QString path = openCounterexample(*this, document, proof, error);
                if (!error.isEmpty())
                    showMessage(error);
                else if (!path.isEmpty())
                    showMessage(
                        tr("Running %1 in the simulator.").arg(QDir::toNativeSeparators(path)));
            });
    connect(m_ladderPage, &LadderPage::textRequested, this, [this] {
        showPage({PageRef::Kind::Code, m_ladderPage->document(), m_ladderPage->station(),
                  m_ladderPage->sequence()});
    });
    connect(m_textPage, &TextPage::ladderRequested, this, [this] {
        showPage({PageRef::Kind::Ladder, m_textPage->document(), m_textPage->station(),
                  m_current.kind == PageRef::Kind::Code ? m_current.sequence : 0});
    });
    connect(m_ladderPage, &LadderPage::newSequenceRequested, this,
            [this] { m_units->newSequence(m_ladderPage->document(), m_ladderPage->station()); });
    connect(m_unitPage, &UnitPage::remanentRequested, m_units, &UnitCommands::editRemanent);
    connect(m_variablesPage, &VariablesPage::remanentRequested, m_units,
            &UnitCommands::editRemanent);
    connect(m_variablesPage, &VariablesPage::csvImportRequested, m_units, &UnitCommands::importCsv);
    connect(m_variablesPage, &VariablesPage::csvExportRequested, m_units, &UnitCommands::exportCsv);
    connect(&m_undoGroup, &QUndoGroup::canUndoChanged, this, &MainWindow::updateActions);
    connect(&m_undoGroup, &QUndoGroup::canRedoChanged, this, &MainWindow::updateActions);
    connect(&m_undoGroup, &QUndoGroup::undoTextChanged, this, &MainWindow::updateActions);
    connect(&m_undoGroup, &QUndoGroup::redoTextChanged, this, &MainWindow::updateActions);
    m_projects->setAutosaveInterval(m_preferences.autosaveMinutes);

    resize(1280, 800);
    rebuildTree();
    showPage(PageRef{});
}

MainWindow::~MainWindow() {
    // The projects outlive the window's members; nothing of theirs may reach them.
    for (ProjectDocument* document : m_projects->documents())
        disconnect(document, nullptr, this, nullptr);
}

// ----- actions and menus

void MainWindow::createCommands() {
    m_projects = new OpenProjects(this, m_textPage, [this] { return currentDocument(); });
    connect(m_projects, &OpenProjects::added, this, &MainWindow::documentAdded);
    connect(m_projects, &OpenProjects::removed, this, &MainWindow::documentRemoved);
    connect(m_projects, &OpenProjects::opened, this,
            [this](ProjectDocument* document) { showFirstPageOf(document); });
    connect(m_projects, &OpenProjects::created, this, [this](ProjectDocument* document) {
        showPage({PageRef::Kind::Project, document});
    });
    connect(m_projects, &OpenProjects::message, this, &MainWindow::showMessage);

    m_units = new UnitCommands(this, [this] {
        PageRef page = m_current;
        page.document = currentDocument();
        return page;
    });
    connect(m_projects, &OpenProjects::unitWanted, m_units, &UnitCommands::newUnit);
    connect(m_units, &UnitCommands::unitAdded, this,
            [this](ProjectDocument* document, int station) {
                showPage({PageRef::Kind::Unit, document, station});
            });
    connect(m_units, &UnitCommands::sequenceAdded, this,
            [this](ProjectDocument* document, int station, int sequence) {
                const bool ladder = m_current.kind == PageRef::Kind::Ladder;
                showPage({ladder ? PageRef::Kind::Ladder : PageRef::Kind::Code, document, station,
                          sequence});
            });
    connect(m_units, &UnitCommands::unitRemoving, this,
            [this](ProjectDocument* document, int station) {
                if (m_current.document == document && m_current.station == station)
                    showPage({PageRef::Kind::Project, document});
            });
    connect(m_units, &UnitCommands::message, this, &MainWindow::showMessage);

    m_gateways = new GatewayCommands(this, [this] {
        PageRef page = m_current;
        page.document = currentDocument();
        return page;
    });
    connect(m_gateways, &GatewayCommands::gatewayAdded, this,
            [this](ProjectDocument* document, int node) {
                showPage({PageRef::Kind::Gateway, document, node});
            });
    connect(m_gateways, &GatewayCommands::gatewayRemoving, this,
            [this](ProjectDocument* document, int node) {
                if (m_current.document == document && m_current.kind == PageRef::Kind::Gateway &&
                    m_current.station == node)
                    showPage({PageRef::Kind::Project, document});
            });
    connect(m_gatewayPage, &GatewayPage::removeRequested, m_gateways,
            &GatewayCommands::removeGateway);
}

void MainWindow::createActions() {
    const auto action = [this](const QString& text, const char* name,
                               const QKeySequence& shortcut = {}) {
        auto* created = new QAction(text, this);
        created->setObjectName(QString::fromLatin1(name));
        created->setShortcut(shortcut);
        return created;
    };

    m_quitAction = action(tr("&Quit"), "quitAction", QKeySequence::Quit);
    m_quitAction->setMenuRole(QAction::QuitRole);
    connect(m_quitAction, &QAction::triggered, this, &QWidget::close);

    m_undoAction = action(tr("&Undo"), "undoAction");
    m_undoAction->setShortcuts(QKeySequence::Undo);
    m_undoAction->setIcon(namedIcon("edit-undo"));
    connect(m_undoAction, &QAction::triggered, this, &MainWindow::undo);
    m_redoAction = action(tr("&Redo"), "redoAction");
    m_redoAction->setIcon(namedIcon("edit-redo"));
    // Every binding of the platform (Ctrl+Shift+Z on Linux desktops), and
    // Ctrl+Y, which the manual's tool and Windows use, wherever it is not one.
    QList<QKeySequence> redoKeys = QKeySequence::keyBindings(QKeySequence::Redo);
    if (!redoKeys.contains(QKeySequence(Qt::CTRL | Qt::Key_Y)))
        redoKeys << QKeySequence(Qt::CTRL | Qt::Key_Y);
    m_redoAction->setShortcuts(redoKeys);
    connect(m_redoAction, &QAction::triggered, this, &MainWindow::redo);

    // The clipboard commands act on whatever text field has the focus.
    auto forward = [](const char* slot) {
        return [slot] {
            if (QWidget* focus = QApplication::focusWidget())
                QMetaObject::invokeMethod(focus, slot);
        };
    };
    m_cutAction = action(tr("Cu&t"), "cutAction", QKeySequence::Cut);
    connect(m_cutAction, &QAction::triggered, this, forward("cut"));
    m_copyAction = action(tr("&Copy"), "copyAction", QKeySequence::Copy);
    connect(m_copyAction, &QAction::triggered, this, forward("copy"));
    m_pasteAction = action(tr("&Paste"), "pasteAction", QKeySequence::Paste);
    connect(m_pasteAction, &QAction::triggered, this, forward("paste"));
    m_selectAllAction = action(tr("Select &All"), "selectAllAction", QKeySequence::SelectAll);
    connect(m_selectAllAction, &QAction::triggered, this, forward("selectAll"));

    m_formatAction = action(tr("&Format Document"), "formatDocumentAction",
                            QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F));
    m_formatAction->setIcon(namedIcon("format-document"));
    m_formatAction->setStatusTip(tr("Rewrite the text in the canonical layout"));
    connect(m_formatAction, &QAction::triggered, this, &MainWindow::formatDocument);

    m_codeViewAction = action(tr("&Ladder or Text"), "codeViewAction", QKeySequence(Qt::Key_F6));
    m_codeViewAction->setStatusTip(tr("Show the code as ladder networks or as text"));
    connect(m_codeViewAction, &QAction::triggered, this, [this] {
        PageRef other = m_current;
        other.kind =
            m_current.kind == PageRef::Kind::Code ? PageRef::Kind::Ladder : PageRef::Kind::Code;
        showPage(other);
    });

    m_markValidatedAction = action(tr("Mark as &Validated..."), "markValidatedAction");
    m_markValidatedAction->setStatusTip(
        tr("Record this version's program signatures as the validated baseline"));
    connect(m_markValidatedAction, &QAction::triggered, this, [this] {
        if (ProjectDocument* document = currentDocument(); document && !document->isDamaged()) {
            MarkValidatedDialog dialog(document, this);
            if (dialog.exec() == QDialog::Accepted)
                showMessage(tr("%1 is marked as validated.").arg(document->displayName()));
        }
    });

    m_compareAction = action(tr("Compare &With..."), "compareAction");
    m_compareAction->setStatusTip(
        tr("What differs between another version of the project and this one, network by network"));
    connect(m_compareAction, &QAction::triggered, this, [this] {
        ProjectDocument* document = currentDocument();
        if (!document || document->isDamaged())
            return;
        const QString old = QFileDialog::getOpenFileName(this, tr("Compare With"),
                                                         QFileInfo(document->path()).absolutePath(),
                                                         tr("Rungsmith projects (*.sps)"));
        if (!old.isEmpty())
            openComparison(document, old);
    });
    m_compareValidatedAction = action(tr("Compare With Va&lidated"), "compareValidatedAction");
    m_compareValidatedAction->setStatusTip(
        tr("What changed since the project was marked as validated"));
    connect(m_compareValidatedAction, &QAction::triggered, this, [this] {
        if (ProjectDocument* document = currentDocument();
            document && !document->isDamaged() && document->project().baseline)
            openComparison(document, QString());
    });

    m_preferencesAction =
        action(tr("Pr&eferences..."), "preferencesAction", QKeySequence::Preferences);
    m_preferencesAction->setIcon(namedIcon("preferences"));
    m_preferencesAction->setMenuRole(QAction::PreferencesRole);
    connect(m_preferencesAction, &QAction::triggered, this, &MainWindow::editPreferences);

    m_compileAction = action(tr("&Compile"), "compileAction", QKeySequence(Qt::Key_F7));
    m_compileAction->setIcon(namedIcon("compile"));
    m_compileAction->setStatusTip(tr("Check the project and write the compiled file (.hps)"));
    connect(m_compileAction, &QAction::triggered, this, &MainWindow::compile);

    m_proveAllAction =
        action(tr("&Prove All"), "proveAllAction", QKeySequence(Qt::CTRL | Qt::Key_F7));
    m_proveAllAction->setIcon(namedIcon("prove"));
    m_proveAllAction->setStatusTip(
        tr("Prove every property of the project for every input sequence, or find one that "
           "breaks it"));
    connect(m_proveAllAction, &QAction::triggered, this, &MainWindow::proveAll);

    m_aboutAction = action(tr("&About Rungsmith"), "aboutAction");
    m_aboutAction->setMenuRole(QAction::AboutRole);
    connect(m_aboutAction, &QAction::triggered, this, &MainWindow::about);
}

void MainWindow::createMenus() {
    const OpenProjects::Actions& projectActions = m_projects->actions();
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->setObjectName(QStringLiteral("fileMenu"));
    file->addAction(projectActions.newProject);
    file->addAction(projectActions.open);
    m_recentMenu = file->addMenu(tr("Open &Recent"));
    m_recentMenu->setObjectName(QStringLiteral("recentMenu"));
    file->addSeparator();
    file->addAction(projectActions.save);
    file->addAction(projectActions.saveAs);
    file->addAction(projectActions.saveAll);
    file->addAction(projectActions.close);
    file->addSeparator();
    QMenu* exportMenu = file->addMenu(tr("&Export"));
    exportMenu->setObjectName(QStringLiteral("exportMenu"));
    exportMenu->addAction(projectActions.exportText);
    file->addAction(projectActions.protect);
    file->addSeparator();
    file->addAction(m_quitAction);
    // Another window may have changed the list since this one last showed it.
    connect(file, &QMenu::aboutToShow, this, [this] { m_projects->fillRecentMenu(m_recentMenu); });
    m_projects->fillRecentMenu(m_recentMenu);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    edit->setObjectName(QStringLiteral("editMenu"));
    edit->addAction(m_undoAction);
    edit->addAction(m_redoAction);
    edit->addSeparator();
    edit->addAction(m_cutAction);
    edit->addAction(m_copyAction);
    edit->addAction(m_pasteAction);
    edit->addSeparator();
    edit->addAction(m_selectAllAction);
    edit->addSeparator();
    edit->addAction(m_formatAction);
    edit->addSeparator();
    edit->addAction(m_preferencesAction);

    QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
    viewMenu->setObjectName(QStringLiteral("viewMenu"));
    viewMenu->addAction(m_treeDock->toggleViewAction());
    viewMenu->addAction(m_problemsDock->toggleViewAction());
    viewMenu->addAction(m_outputDock->toggleViewAction());
    viewMenu->addAction(m_fileToolBar->toggleViewAction());
    viewMenu->addSeparator();
    viewMenu->addAction(m_codeViewAction);

    QMenu* projectMenu = menuBar()->addMenu(tr("&Project"));
    projectMenu->setObjectName(QStringLiteral("projectMenu"));
    const UnitCommands::Actions& unitActions = m_units->actions();
    projectMenu->addAction(unitActions.newUnit);
    projectMenu->addAction(unitActions.newSequence);
    projectMenu->addAction(unitActions.removeUnit);
    projectMenu->addSeparator();
    projectMenu->addAction(m_gateways->actions().newGateway);
    projectMenu->addAction(m_gateways->actions().removeGateway);
    projectMenu->addSeparator();
    projectMenu->addAction(unitActions.remanent);
    projectMenu->addAction(unitActions.importCsv);
    projectMenu->addAction(unitActions.exportCsv);
    projectMenu->addSeparator();
    projectMenu->addAction(m_markValidatedAction);
    projectMenu->addAction(m_compareValidatedAction);
    projectMenu->addAction(m_compareAction);

    QMenu* build = menuBar()->addMenu(tr("&Build"));
    build->setObjectName(QStringLiteral("buildMenu"));
    build->addAction(m_compileAction);
    build->addSeparator();
    build->addAction(m_proveAllAction);

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->setObjectName(QStringLiteral("helpMenu"));
    help->addAction(projectActions.example);
    help->addSeparator();
    help->addAction(m_aboutAction);
}

void MainWindow::createToolBar() {
    m_fileToolBar = addToolBar(tr("Main"));
    m_fileToolBar->setObjectName(QStringLiteral("fileToolBar"));
    m_fileToolBar->setIconSize(QSize(20, 20));
    const OpenProjects::Actions& projectActions = m_projects->actions();
    m_fileToolBar->addAction(projectActions.newProject);
    m_fileToolBar->addAction(projectActions.open);
    m_fileToolBar->addAction(projectActions.save);
    m_fileToolBar->addAction(projectActions.saveAll);
    m_fileToolBar->addSeparator();
    m_fileToolBar->addAction(m_undoAction);
    m_fileToolBar->addAction(m_redoAction);
    m_fileToolBar->addSeparator();
    m_fileToolBar->addAction(m_units->actions().newUnit);
    m_fileToolBar->addAction(m_formatAction);
    m_fileToolBar->addSeparator();
    m_fileToolBar->addAction(m_compileAction);
}

void MainWindow::createDocks() {
    m_tree = new ProjectTree(this);
    m_tree->setObjectName(QStringLiteral("projectTree"));
    connect(m_tree, &ProjectTree::pageRequested, this,
            [this](const PageRef& page) { showPage(page); });
    connect(m_tree, &ProjectTree::menuRequested, this, &MainWindow::showTreeMenu);
    m_treeDock = new QDockWidget(tr("Projects"), this);
    m_treeDock->setObjectName(QStringLiteral("projectTreeDock"));
    m_treeDock->setWidget(m_tree);
    addDockWidget(Qt::LeftDockWidgetArea, m_treeDock);
    resizeDocks({m_treeDock}, {260}, Qt::Horizontal);

    m_problems = new ProblemsView(this);
    m_problems->setObjectName(QStringLiteral("problemsView"));
    connect(m_problems, &ProblemsView::problemActivated, this, [this](int line, int column) {
        if (m_pages->currentWidget() == m_textPage)
            m_textPage->editor()->goTo(line, column);
    });
    m_problemsDock = new QDockWidget(tr("Problems"), this);
    m_problemsDock->setObjectName(QStringLiteral("problemsDock"));
    m_problemsDock->setWidget(m_problems);
    addDockWidget(Qt::BottomDockWidgetArea, m_problemsDock);

    m_output = new CompileOutput(this);
    m_output->setObjectName(QStringLiteral("compileOutput"));
    connect(m_output, &CompileOutput::placeActivated, this, &MainWindow::showCompilePlace);
    m_outputDock = new QDockWidget(tr("Output"), this);
    m_outputDock->setObjectName(QStringLiteral("outputDock"));
    m_outputDock->setWidget(m_output);
    addDockWidget(Qt::BottomDockWidgetArea, m_outputDock);
    tabifyDockWidget(m_problemsDock, m_outputDock);
    m_problemsDock->raise();
    resizeDocks({m_problemsDock}, {140}, Qt::Vertical);
}

void MainWindow::createStatusBar() {
    m_position = new QLabel(this);
    m_position->setObjectName(QStringLiteral("cursorPositionLabel"));
    m_summary = new QLabel(this);
    m_summary->setObjectName(QStringLiteral("problemSummaryLabel"));
    statusBar()->addPermanentWidget(m_compileRun->progressBar());
    for (QLabel* label : {m_position, m_summary}) {
        label->setContentsMargins(8, 0, 8, 0);
        statusBar()->addPermanentWidget(label);
    }
    connect(m_textPage->editor(), &QsciScintilla::cursorPositionChanged, this,
            [this](int line, int index) {
                m_position->setText(tr("Line %1, Column %2").arg(line + 1).arg(index + 1));
            });
    m_position->setText(tr("Line %1, Column %2").arg(1).arg(1));
    showSummary({});
}

// ----- projects

ProjectDocument* MainWindow::currentDocument() const {
    if (m_current.document)
        return m_current.document;
    const std::vector<ProjectDocument*>& documents = m_projects->documents();
    return documents.empty() ? nullptr : documents.back();
}

ProgramEditor* MainWindow::editor() const {
    return m_textPage->editor();
}

void MainWindow::documentAdded(ProjectDocument* document) {
    m_undoGroup.addStack(document->undoStack());
    connect(document, &ProjectDocument::changed, this, [this, document] {
        // The tree shows units, sequences and gateways; lines of a step change none.
        if (!document->changedStepLines())
            rebuildTree();
        updateTitle();
        updateActions(); // a baseline marked or undone
    });
    connect(document, &ProjectDocument::modificationChanged, this, &MainWindow::updateTitle);
    connect(document, &ProjectDocument::pathChanged, this, &MainWindow::updateTitle);
    connect(document, &ProjectDocument::permissionChanged, this, [this] {
        updateTitle();
        updateActions();
    });
    connect(document, &ProjectDocument::editRefused, this, &MainWindow::showMessage);
    rebuildTree();
}

void MainWindow::documentRemoved(ProjectDocument* document) {
    m_undoGroup.removeStack(document->undoStack());
    m_compileRun->forget(document);
    if (m_current.document == document) {
        m_current = {};
        m_textPage->showUnit(nullptr, 0);
    }
    if (m_propertiesPage->document() == document)
        m_propertiesPage->showProject(nullptr);
    rebuildTree();
    if (documents().empty())
        showPage(PageRef{});
    else
        showFirstPageOf(documents().back());
}

void MainWindow::rebuildTree() {
    m_tree->setDocuments(documents());
    m_tree->select(m_current);
}

void MainWindow::showFirstPageOf(ProjectDocument* document, PageRef::Kind codeView) {
    if (document->isDamaged()) {
        showPage({PageRef::Kind::ProjectText, document, TextPage::kWholeProject});
        return;
    }
    const auto stations = document->project().stations();
    if (stations.empty())
        showPage({PageRef::Kind::Project, document});
    else
        showPage({codeView, document, stations.front(), 0});
}

// ----- pages

bool MainWindow::leaveTextPage() {
    if (m_pages->currentWidget() != m_textPage || !m_textPage->document() ||
        m_textPage->station() == TextPage::kWholeProject || m_textPage->applyNow())
        return true;
    QMessageBox box(QMessageBox::Warning, tr("Code With Errors"),
                    tr("The code of Pluto %1 has errors, so it cannot be read into the project.")
                        .arg(m_textPage->station()),
                    QMessageBox::NoButton, this);
    box.setInformativeText(tr("Keep editing to fix them, or discard the changes since the code "
                              "last read without errors."));
    QPushButton* keep = box.addButton(tr("&Keep Editing"), QMessageBox::RejectRole);
    QAbstractButton* discard = box.addButton(QMessageBox::Discard);
    box.setDefaultButton(keep);
    box.exec();
    if (box.clickedButton() != discard) {
        m_tree->select(m_current);
        return false;
    }
    m_textPage->discardChanges();
    return true;
}

bool MainWindow::showPage(const PageRef& page) {
    if (page == m_current && page.kind != PageRef::Kind::None)
        return true;
    const bool sameText = page.kind == PageRef::Kind::Code &&
                          m_current.kind == PageRef::Kind::Code &&
                          page.document == m_current.document && page.station == m_current.station;
    if (!sameText && !leaveTextPage())
        return false;
    m_current = page;
    ProjectDocument* document = page.document;
    switch (page.kind) {
    case PageRef::Kind::None:
        m_welcomePage->showRecent(m_projects->recentPaths());
        m_pages->setCurrentWidget(m_welcomePage);
        if (!documents().empty())
            m_current.document = nullptr;
        break;
    case PageRef::Kind::Project:
        m_projectPage->showProject(document);
        m_pages->setCurrentWidget(m_projectPage);
        break;
    case PageRef::Kind::Unit:
        m_unitPage->showUnit(document, page.station);
        m_pages->setCurrentWidget(m_unitPage);
        break;
    case PageRef::Kind::IoOptions:
        m_ioPage->showUnit(document, page.station);
        m_pages->setCurrentWidget(m_ioPage);
        break;
    case PageRef::Kind::AsiOptions:
        m_asiPage->showUnit(document, page.station);
        m_pages->setCurrentWidget(m_asiPage);
        break;
    case PageRef::Kind::Gateway:
        m_gatewayPage->showGateway(document, page.station);
        m_pages->setCurrentWidget(m_gatewayPage);
        break;
    case PageRef::Kind::Variables:
        m_variablesPage->showUnit(document, page.station);
        m_pages->setCurrentWidget(m_variablesPage);
        break;
    case PageRef::Kind::ProjectText:
    case PageRef::Kind::Code:
        if (!sameText || m_textPage->document() != document)
            m_textPage->showUnit(document, page.station);
        m_pages->setCurrentWidget(m_textPage);
        if (page.kind == PageRef::Kind::Code)
            m_textPage->showSequence(page.sequence);
        break;
    case PageRef::Kind::Ladder:
        m_ladderPage->showUnit(document, page.station, page.sequence);
        m_pages->setCurrentWidget(m_ladderPage);
        break;
    case PageRef::Kind::Properties:
        m_propertiesPage->showProject(document);
        m_pages->setCurrentWidget(m_propertiesPage);
        break;
    }
    const bool onText = m_pages->currentWidget() == m_textPage;
    if (!onText) {
        m_problems->setDiagnostics({});
        showSummary({});
    }
    m_position->setVisible(onText);
    m_summary->setVisible(onText);
    if (document)
        m_undoGroup.setActiveStack(document->undoStack());
    m_tree->select(m_current);
    updateTitle();
    updateActions();
    emit pageChanged();
    return true;
}

bool MainWindow::showPage(PageRef::Kind kind, int station, int sequence) {
    ProjectDocument* document = currentDocument();
    if (document && kind == PageRef::Kind::Project)
        return showPage(PageRef{kind, document});
    if (kind == PageRef::Kind::Properties)
        return document && !document->isDamaged() && showPage(PageRef{kind, document});
    if (kind == PageRef::Kind::Gateway)
        return document && !document->isDamaged() && document->project().gateways.count(station) &&
               showPage(PageRef{kind, document, station});
    if (!document || !project::unitSettings(document->project(), station))
        return false;
    if (sequence != 0) {
        const std::vector<int> sequences = project::sequencesOf(document->project(), station);
        if ((kind != PageRef::Kind::Code && kind != PageRef::Kind::Ladder) ||
            std::find(sequences.begin(), sequences.end(), sequence) == sequences.end())
            return false;
    }
    return showPage(PageRef{kind, document, station, sequence});
}

bool MainWindow::showUnit(int station) {
    return showPage(PageRef::Kind::Code, station);
}

void MainWindow::updateTitle() {
    ProjectDocument* document = currentDocument();
    if (!document) {
        setWindowTitle(QStringLiteral("Rungsmith"));
        setWindowModified(false);
        return;
    }
    QString name = document->displayName();
    if (document->permission() == project::Permission::ReadOnly)
        name = tr("%1 (read only)").arg(name);
    else if (document->permission() == project::Permission::Configure)
        name = tr("%1 (config options only)").arg(name);
    setWindowTitle(QStringLiteral("%1[*] — Rungsmith").arg(name));
    setWindowModified(document->isModified());
}

void MainWindow::updateActions() {
    ProjectDocument* document = currentDocument();
    const bool onText = m_pages->currentWidget() == m_textPage;
    m_projects->updateActions(document);
    PageRef shown = m_current;
    shown.document = document;
    m_units->updateActions(shown);
    m_gateways->updateActions(shown);
    m_compileAction->setEnabled(document != nullptr && !isCompiling());
    m_proveAllAction->setEnabled(document != nullptr && !document->isDamaged() &&
                                 !m_propertiesPage->isProving());
    const bool writable =
        document != nullptr && document->permission() == project::Permission::Full;
    m_formatAction->setEnabled(onText && writable);
    m_markValidatedAction->setEnabled(writable && !document->isDamaged());
    m_compareAction->setEnabled(document != nullptr && !document->isDamaged());
    m_compareValidatedAction->setEnabled(document != nullptr && !document->isDamaged() &&
                                         document->project().baseline.has_value());
    m_codeViewAction->setEnabled(m_current.kind == PageRef::Kind::Code ||
                                 m_current.kind == PageRef::Kind::Ladder);
    // A text with an undo of its own: the damaged project's, the properties'.
    if ((onText && m_textPage->station() == TextPage::kWholeProject) ||
        m_pages->currentWidget() == m_propertiesPage) {
        m_undoAction->setEnabled(true);
        m_redoAction->setEnabled(true);
        m_undoAction->setText(tr("&Undo"));
        m_redoAction->setText(tr("&Redo"));
        return;
    }
    m_undoAction->setEnabled(m_undoGroup.canUndo());
    m_redoAction->setEnabled(m_undoGroup.canRedo());
    m_undoAction->setText(m_undoGroup.canUndo() ? tr("&Undo %1").arg(m_undoGroup.undoText())
                                                : tr("&Undo"));
    m_redoAction->setText(m_undoGroup.canRedo() ? tr("&Redo %1").arg(m_undoGroup.redoText())
                                                : tr("&Redo"));
}

void MainWindow::openComparison(ProjectDocument* document, const QString& oldPath) {
    // Modeless: the reviewer walks through the networks it lists.
    auto* dialog = new CompareDialog(document, oldPath, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(document, &QObject::destroyed, dialog, &QWidget::close);
    connect(dialog, &CompareDialog::networkChosen, this,
            [this, document](int station, int sequence, int step, int number) {
                if (showPage({PageRef::Kind::Ladder, document, station, sequence}))
                    m_ladderPage->selectNetwork({station, sequence, step}, number);
            });
    dialog->show();
}

// ----- edits

void MainWindow::undo() {
    if (m_pages->currentWidget() == m_propertiesPage) {
        m_propertiesPage->editor()->undo();
        return;
    }
    if (m_pages->currentWidget() == m_textPage) {
        if (m_textPage->station() == TextPage::kWholeProject) {
            m_textPage->editor()->undo();
            return;
        }
        // Typing not yet read is an edit of its own: undo takes it back first.
        m_textPage->applyNow();
    }
    m_undoGroup.undo();
}

void MainWindow::redo() {
    if (m_pages->currentWidget() == m_propertiesPage) {
        m_propertiesPage->editor()->redo();
        return;
    }
    if (m_pages->currentWidget() == m_textPage &&
        m_textPage->station() == TextPage::kWholeProject) {
        m_textPage->editor()->redo();
        return;
    }
    m_undoGroup.redo();
}

void MainWindow::formatDocument() {
    if (m_pages->currentWidget() != m_textPage)
        return;
    if (!m_textPage->formatText()) {
        showMessage(tr("Not formatted: the text has %n error(s).", nullptr,
                       lang::errorCount(m_textPage->diagnostics())));
        return;
    }
    showMessage(tr("Formatted."));
}

void MainWindow::editPreferences() {
    PreferencesDialog dialog(m_preferences, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const Preferences chosen = dialog.preferences();
    const bool themeChanged = chosen.theme != m_preferences.theme;
    m_preferences = chosen;
    m_preferences.save();
    if (themeChanged)
        applyTheme(m_preferences.theme);
    m_projects->setAutosaveInterval(m_preferences.autosaveMinutes);
    m_simulation->session()->setUpdateInterval(m_preferences.screenUpdateMs);
    m_textPage->setWarnUnconfiguredIo(m_preferences.warnUnconfiguredIo);
    m_ladderPage->setColours(ladderColoursOf(m_preferences));
}

void MainWindow::showTreeMenu(const PageRef& page, const QPoint& globalPosition) {
    QMenu menu(this);
    ProjectDocument* document = page.document;
    auto add = [&](const QString& text, auto&& run) {
        connect(menu.addAction(text), &QAction::triggered, this, run);
    };
    switch (page.kind) {
    case PageRef::Kind::None:
        menu.addAction(m_projects->actions().newProject);
        menu.addAction(m_projects->actions().open);
        break;
    case PageRef::Kind::Project:
    case PageRef::Kind::ProjectText:
        if (!document->isDamaged()) {
            add(tr("New &Pluto..."), [this, document] { m_units->newUnit(document); });
            add(tr("New &Gateway..."), [this, document] { m_gateways->newGateway(document); });
        }
        add(tr("&Save Project"), [this, document] { m_projects->save(document); });
        add(tr("Save Project &As..."), [this, document] { m_projects->saveAs(document); });
        if (!document->isDamaged()) {
            add(tr("Export Program &Text..."),
                [this, document] { m_projects->exportProgramText(document); });
            menu.addSeparator();
            for (const bool ignore : {false, true})
                add(ignore ? tr("Merge Project (&ignore conflicts)...") : tr("&Merge Project..."),
                    [this, document, ignore] {
                        if (ProjectDocument* other =
                                chooseProjectToMerge(this, document, m_projects->documents()))
                            if (const QString said =
                                    mergeOpenProject(this, document, other, ignore);
                                !said.isEmpty())
                                showMessage(said);
                    });
        }
        menu.addSeparator();
        add(tr("&Close Project"), [this, document] { m_projects->close(document); });
        break;
    case PageRef::Kind::Variables:
        add(tr("&Import Variable Names to Pluto..."),
            [this, document, page] { m_units->importCsv(document, page.station); });
        add(tr("E&xport Variable Names from Pluto..."),
            [this, document, page] { m_units->exportCsv(document, page.station); });
        if (project::unitTypeOf(document->project(), page.station).remanent)
            add(tr("&Remanent Variables..."),
                [this, document, page] { m_units->editRemanent(document, page.station); });
        break;
    case PageRef::Kind::Unit:
    case PageRef::Kind::IoOptions:
    case PageRef::Kind::AsiOptions:
    case PageRef::Kind::Code:
    case PageRef::Kind::Ladder:
        add(tr("New &Sequence..."),
            [this, document, page] { m_units->newSequence(document, page.station); });
        menu.addSeparator();
        add(tr("&Remove Pluto..."),
            [this, document, page] { m_units->removeUnit(document, page.station); });
        break;
    case PageRef::Kind::Gateway:
        add(tr("Remove Gate&way..."),
            [this, document, page] { m_gateways->removeGateway(document, page.station); });
        break;
    case PageRef::Kind::Properties:
        add(tr("&Prove All"), [this, document] {
            if (showPage({PageRef::Kind::Properties, document}))
                proveAll();
        });
        break;
    }
    menu.exec(globalPosition);
}

// ----- compiling

void MainWindow::compile() {
    ProjectDocument* document = currentDocument();
    if (!document || isCompiling())
        return;
    if (m_textPage->document() == document)
        m_textPage->applyNow();
    // The image written beside a project must come from that file as saved, or
    // it would match no source a reviewer can read (the image's project CRC
    // names the text it came from).
    CompileRun::Image image = CompileRun::Image::Write;
    if (hasOwnFile(*document) && document->isModified()) {
        QMessageBox box(QMessageBox::Question, tr("Compile"),
                        tr("%1 has changes that are not saved.").arg(document->displayName()),
                        QMessageBox::Save | QMessageBox::Ignore | QMessageBox::Cancel, this);
        box.setInformativeText(
            tr("The compiled file (.hps) is written beside the project and must come from the "
               "saved file. Save first, or only check the changes without writing the "
               "compiled file."));
        box.button(QMessageBox::Save)->setText(tr("&Save and Compile"));
        box.button(QMessageBox::Ignore)->setText(tr("C&heck Only"));
        box.setDefaultButton(QMessageBox::Save);
        switch (box.exec()) {
        case QMessageBox::Save:
            if (!m_projects->save(document))
                return;
            break;
        case QMessageBox::Ignore:
            image = CompileRun::Image::CheckOnly;
            break;
        default:
            return;
        }
    }
    compiler::CheckOptions options;
    options.warnUnconfiguredIo = m_preferences.warnUnconfiguredIo;
    m_compileRun->start(document, options, image);
}

void MainWindow::proveAll() {
    ProjectDocument* document = currentDocument();
    if (!document || document->isDamaged() || m_propertiesPage->isProving())
        return;
    if (m_textPage->document() == document)
        m_textPage->applyNow();
    if (!showPage({PageRef::Kind::Properties, document}))
        return;
    compiler::CheckOptions options;
    options.warnUnconfiguredIo = m_preferences.warnUnconfiguredIo;
    m_propertiesPage->proveAll(options);
}

void MainWindow::showCompilePlace(const project::TextPlace& place, int column) {
    ProjectDocument* document =
        m_compileRun->document() ? m_compileRun->document() : currentDocument();
    if (!document)
        return;
    using Kind = project::TextPlace::Kind;
    switch (place.kind) {
    case Kind::UnitCode:
        if (showPage({PageRef::Kind::Code, document, place.station, m_current.sequence}))
            m_textPage->editor()->goTo(place.line, column);
        return;
    case Kind::Unit:
        showPage({PageRef::Kind::Unit, document, place.station});
        return;
    case Kind::Variable:
        if (showPage({PageRef::Kind::Variables, document, place.station}))
            m_variablesPage->showVariable(place.address);
        return;
    case Kind::Project:
        showPage(document->isDamaged()
                     ? PageRef{PageRef::Kind::ProjectText, document, TextPage::kWholeProject}
                     : PageRef{PageRef::Kind::Project, document});
        return;
    }
}

// ----- the rest

void MainWindow::showSummary(const std::vector<lang::Diagnostic>& diagnostics) {
    const int errors = lang::errorCount(diagnostics);
    const int warnings = static_cast<int>(diagnostics.size()) - errors;
    m_summary->setText(tr("%n error(s)", nullptr, errors) + QStringLiteral(", ") +
                       tr("%n warning(s)", nullptr, warnings));
}

void MainWindow::showMessage(const QString& message) {
    statusBar()->showMessage(message, kStatusMessageMs);
}

void MainWindow::about() {
    QMessageBox::about(
        this, tr("About Rungsmith"),
        tr("<h3>Rungsmith %1</h3>"
           "<p>An IDE for Pluto safety PLCs: projects, units, I/O options, variables and the "
           "program as ladder and as text, checked, compiled and simulated.</p>"
           "<p>Built with Qt %2 and QScintilla %3.</p>")
            .arg(QCoreApplication::applicationVersion(), QString::fromLatin1(qVersion()),
                 QStringLiteral(QSCINTILLA_VERSION_STR)));
}

void MainWindow::restoreLayout() {
    const QSettings settings;
    if (settings.contains(kGeometryKey))
        restoreGeometry(settings.value(kGeometryKey).toByteArray());
    restoreState(settings.value(kStateKey).toByteArray());
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!leaveTextPage()) {
        event->ignore();
        return;
    }
    if (!m_projects->prepareToQuit()) {
        event->ignore();
        return;
    }
    QSettings settings;
    settings.setValue(kGeometryKey, saveGeometry());
    settings.setValue(kStateKey, saveState());
    event->accept();
}

} // namespace rs::ui
