#include "MainWindow.h"

#include "ProblemsView.h"
#include "ProgramEditor.h"
#include "project/ProjectFile.h"

#include <Qsci/qsciglobal.h>

#include <QAction>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QToolBar>

#include <string_view>

namespace rs::ui {

namespace {

// What File > New starts from: the smallest project that checks clean.
constexpr std::string_view kNewProjectText = "$name Untitled\n"
                                             "\n"
                                             "! type_pluto:00=B46,is3\n"
                                             "! pgm_pluto:00\n"
                                             "\n"
                                             "S0.0_0\n";

const QString kExamplePath = QStringLiteral(":/examples/muting.sps");
const QString kGeometryKey = QStringLiteral("mainWindow/geometry");
const QString kStateKey = QStringLiteral("mainWindow/state");

constexpr int kStatusMessageMs = 4000;

std::string_view view(const QByteArray& bytes) {
    return {bytes.constData(), static_cast<std::size_t>(bytes.size())};
}

QString projectFileFilter() {
    return MainWindow::tr("Pluto projects (*.sps);;All files (*)");
}

} // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent), m_editor(new ProgramEditor(this)) {
    setObjectName(QStringLiteral("mainWindow"));
    m_editor->setObjectName(QStringLiteral("programEditor"));
    setCentralWidget(m_editor);

    createActions();
    createToolBar();
    createProblemsDock();
    createMenus();
    createStatusBar();

    m_checkTimer.setSingleShot(true);
    m_checkTimer.setInterval(kCheckDelayMs);
    connect(&m_checkTimer, &QTimer::timeout, this, &MainWindow::check);
    connect(m_editor, &QsciScintilla::textChanged, this, [this] {
        m_checkTimer.start();
        updateEditActions();
    });
    connect(m_editor, &QsciScintilla::modificationChanged, this, &QWidget::setWindowModified);

    resize(1280, 800);
    showText(QByteArray(kNewProjectText.data(), static_cast<qsizetype>(kNewProjectText.size())), {},
             tr("untitled.sps"));
}

void MainWindow::createActions() {
    const auto action = [this](const QString& text, const char* name,
                               const QKeySequence& shortcut = {}) {
        auto* created = new QAction(text, this);
        created->setObjectName(QString::fromLatin1(name));
        created->setShortcut(shortcut);
        return created;
    };

    m_newAction = action(tr("&New"), "newAction", QKeySequence::New);
    m_newAction->setIcon(QIcon(QStringLiteral(":/icons/document-new.svg")));
    m_newAction->setStatusTip(tr("Start a new project"));
    connect(m_newAction, &QAction::triggered, this, &MainWindow::newProject);

    m_openAction = action(tr("&Open..."), "openAction", QKeySequence::Open);
    m_openAction->setIcon(QIcon(QStringLiteral(":/icons/document-open.svg")));
    m_openAction->setStatusTip(tr("Open a project file"));
    connect(m_openAction, &QAction::triggered, this, &MainWindow::open);

    m_saveAction = action(tr("&Save"), "saveAction", QKeySequence::Save);
    m_saveAction->setIcon(QIcon(QStringLiteral(":/icons/document-save.svg")));
    m_saveAction->setStatusTip(tr("Save the project"));
    connect(m_saveAction, &QAction::triggered, this, &MainWindow::save);

    m_saveAsAction = action(tr("Save &As..."), "saveAsAction", QKeySequence::SaveAs);
    m_saveAsAction->setStatusTip(tr("Save the project under a new name"));
    connect(m_saveAsAction, &QAction::triggered, this, &MainWindow::saveAs);

    m_quitAction = action(tr("&Quit"), "quitAction", QKeySequence::Quit);
    m_quitAction->setMenuRole(QAction::QuitRole);
    connect(m_quitAction, &QAction::triggered, this, &QWidget::close);

    m_undoAction = action(tr("&Undo"), "undoAction", QKeySequence::Undo);
    connect(m_undoAction, &QAction::triggered, m_editor, &QsciScintilla::undo);
    m_redoAction = action(tr("&Redo"), "redoAction", QKeySequence::Redo);
    connect(m_redoAction, &QAction::triggered, m_editor, &QsciScintilla::redo);
    m_cutAction = action(tr("Cu&t"), "cutAction", QKeySequence::Cut);
    connect(m_cutAction, &QAction::triggered, m_editor, &QsciScintilla::cut);
    m_copyAction = action(tr("&Copy"), "copyAction", QKeySequence::Copy);
    connect(m_copyAction, &QAction::triggered, m_editor, &QsciScintilla::copy);
    m_pasteAction = action(tr("&Paste"), "pasteAction", QKeySequence::Paste);
    connect(m_pasteAction, &QAction::triggered, m_editor, &QsciScintilla::paste);
    m_selectAllAction = action(tr("Select &All"), "selectAllAction", QKeySequence::SelectAll);
    connect(m_selectAllAction, &QAction::triggered, m_editor, [this] { m_editor->selectAll(); });
    connect(m_editor, &QsciScintilla::copyAvailable, m_cutAction, &QAction::setEnabled);
    connect(m_editor, &QsciScintilla::copyAvailable, m_copyAction, &QAction::setEnabled);
    m_cutAction->setEnabled(false);
    m_copyAction->setEnabled(false);

    m_formatAction = action(tr("&Format Document"), "formatDocumentAction",
                            QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F));
    m_formatAction->setIcon(QIcon(QStringLiteral(":/icons/format-document.svg")));
    m_formatAction->setStatusTip(tr("Rewrite the text in the canonical layout"));
    connect(m_formatAction, &QAction::triggered, this, &MainWindow::formatDocument);

    m_exampleAction = action(tr("Open &Example Project"), "exampleAction");
    connect(m_exampleAction, &QAction::triggered, this, [this] {
        if (maybeSave())
            showExample();
    });
    m_aboutAction = action(tr("&About Rungsmith"), "aboutAction");
    m_aboutAction->setMenuRole(QAction::AboutRole);
    connect(m_aboutAction, &QAction::triggered, this, &MainWindow::about);
}

void MainWindow::createMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->setObjectName(QStringLiteral("fileMenu"));
    file->addAction(m_newAction);
    file->addAction(m_openAction);
    m_recentMenu = file->addMenu(tr("Open &Recent"));
    m_recentMenu->setObjectName(QStringLiteral("recentMenu"));
    file->addSeparator();
    file->addAction(m_saveAction);
    file->addAction(m_saveAsAction);
    file->addSeparator();
    file->addAction(m_quitAction);
    // Another window may have changed the list since this one last showed it.
    connect(file, &QMenu::aboutToShow, this, &MainWindow::fillRecentMenu);
    fillRecentMenu();

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

    QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
    viewMenu->setObjectName(QStringLiteral("viewMenu"));
    viewMenu->addAction(m_problemsDock->toggleViewAction());
    viewMenu->addAction(m_fileToolBar->toggleViewAction());

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->setObjectName(QStringLiteral("helpMenu"));
    help->addAction(m_exampleAction);
    help->addSeparator();
    help->addAction(m_aboutAction);
}

void MainWindow::createToolBar() {
    m_fileToolBar = addToolBar(tr("File"));
    m_fileToolBar->setObjectName(QStringLiteral("fileToolBar"));
    m_fileToolBar->setIconSize(QSize(20, 20));
    m_fileToolBar->addAction(m_newAction);
    m_fileToolBar->addAction(m_openAction);
    m_fileToolBar->addAction(m_saveAction);
    m_fileToolBar->addSeparator();
    m_fileToolBar->addAction(m_formatAction);
}

void MainWindow::createProblemsDock() {
    m_problems = new ProblemsView(this);
    m_problems->setObjectName(QStringLiteral("problemsView"));
    connect(m_problems, &ProblemsView::problemActivated, m_editor, &ProgramEditor::goTo);

    m_problemsDock = new QDockWidget(tr("Problems"), this);
    m_problemsDock->setObjectName(QStringLiteral("problemsDock"));
    m_problemsDock->setWidget(m_problems);
    addDockWidget(Qt::BottomDockWidgetArea, m_problemsDock);
    resizeDocks({m_problemsDock}, {170}, Qt::Vertical);
}

void MainWindow::createStatusBar() {
    m_position = new QLabel(this);
    m_position->setObjectName(QStringLiteral("cursorPositionLabel"));
    m_summary = new QLabel(this);
    m_summary->setObjectName(QStringLiteral("problemSummaryLabel"));
    for (QLabel* label : {m_position, m_summary}) {
        label->setContentsMargins(8, 0, 8, 0);
        statusBar()->addPermanentWidget(label);
    }
    connect(m_editor, &QsciScintilla::cursorPositionChanged, this, [this](int line, int index) {
        m_position->setText(tr("Line %1, Column %2").arg(line + 1).arg(index + 1));
    });
    m_position->setText(tr("Line %1, Column %2").arg(1).arg(1));
}

void MainWindow::showText(const QByteArray& text, const QString& path, const QString& displayName) {
    m_editor->setTextBytes(text);
    m_path = path;
    m_displayName = displayName;
    updateTitle();
    updateEditActions();
    check();
}

void MainWindow::updateTitle() {
    setWindowTitle(QStringLiteral("%1[*] — Rungsmith").arg(m_displayName));
    setWindowModified(m_editor->isModified());
}

void MainWindow::updateEditActions() {
    m_undoAction->setEnabled(m_editor->isUndoAvailable());
    m_redoAction->setEnabled(m_editor->isRedoAvailable());
}

void MainWindow::check() {
    m_checkTimer.stop();
    const QByteArray text = m_editor->textBytes();
    const project::ProjectReadResult result = project::readProject(view(text));
    m_editor->setDiagnostics(result.diagnostics);
    m_problems->setDiagnostics(result.diagnostics);
    showSummary(result.diagnostics);
}

void MainWindow::showSummary(const lang::Diagnostics& diagnostics) {
    const int errors = lang::errorCount(diagnostics);
    const int warnings = static_cast<int>(diagnostics.size()) - errors;
    m_summary->setText(tr("%n error(s)", nullptr, errors) + QStringLiteral(", ") +
                       tr("%n warning(s)", nullptr, warnings));
}

QString MainWindow::loadFile(const QString& path) {
    const project::FileText file = project::readTextFile(path);
    if (!file.error.isEmpty())
        return file.error;
    const QFileInfo info(path);
    showText(QByteArray::fromStdString(file.text), info.absoluteFilePath(), info.fileName());
    return {};
}

bool MainWindow::openFile(const QString& path) {
    if (!maybeSave())
        return false;
    const QString error = loadFile(path);
    if (error.isEmpty()) {
        m_recentFiles.add(m_path);
        statusBar()->showMessage(tr("Opened %1").arg(QDir::toNativeSeparators(m_path)),
                                 kStatusMessageMs);
        return true;
    }
    QMessageBox box(QMessageBox::Warning, tr("Open Project"),
                    tr("Could not open “%1”.").arg(QDir::toNativeSeparators(path)), QMessageBox::Ok,
                    this);
    box.setInformativeText(error);
    box.exec();
    return false;
}

void MainWindow::showExample() {
    const project::FileText file = project::readTextFile(kExamplePath);
    showText(QByteArray::fromStdString(file.text), {}, QFileInfo(kExamplePath).fileName());
}

bool MainWindow::showUnit(int station) {
    const QByteArray text = m_editor->textBytes();
    const project::ProjectReadResult result = project::readProject(view(text));
    for (const auto& unit : result.project.program.units) {
        if (unit.station() == station) {
            m_editor->goTo(unit.header.location.line, 1);
            return true;
        }
    }
    return false;
}

void MainWindow::newProject() {
    if (!maybeSave())
        return;
    showText(QByteArray(kNewProjectText.data(), static_cast<qsizetype>(kNewProjectText.size())), {},
             tr("untitled.sps"));
}

void MainWindow::open() {
    if (!maybeSave())
        return;
    const QString directory =
        m_path.isEmpty() ? QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation)
                         : QFileInfo(m_path).absolutePath();
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open Project"), directory, projectFileFilter());
    if (!path.isEmpty())
        openFile(path);
}

bool MainWindow::save() {
    if (m_path.isEmpty())
        return saveAs();
    return saveTo(m_path);
}

bool MainWindow::saveAs() {
    const QString suggestion =
        m_path.isEmpty() ? QDir(QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation))
                               .filePath(m_displayName)
                         : m_path;
    QString path =
        QFileDialog::getSaveFileName(this, tr("Save Project As"), suggestion, projectFileFilter());
    if (path.isEmpty())
        return false;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".sps");
    return saveTo(path);
}

bool MainWindow::saveTo(const QString& path) {
    const QString error = project::writeTextFile(path, view(m_editor->textBytes()));
    if (!error.isEmpty()) {
        QMessageBox box(QMessageBox::Critical, tr("Save Project"),
                        tr("Could not save “%1”.").arg(QDir::toNativeSeparators(path)),
                        QMessageBox::Ok, this);
        box.setInformativeText(error);
        box.exec();
        return false;
    }
    const QFileInfo info(path);
    m_path = info.absoluteFilePath();
    m_displayName = info.fileName();
    m_editor->setModified(false);
    updateTitle();
    m_recentFiles.add(m_path);
    statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(m_path)),
                             kStatusMessageMs);
    return true;
}

void MainWindow::formatDocument() {
    const QByteArray text = m_editor->textBytes();
    const project::ProjectReadResult result = project::readProject(view(text));
    if (!result.ok()) {
        check();
        statusBar()->showMessage(tr("Not formatted: the text has %n error(s).", nullptr,
                                    lang::errorCount(result.diagnostics)),
                                 kStatusMessageMs);
        return;
    }
    const std::string formatted = project::writeProject(result.project);
    if (formatted == view(text)) {
        statusBar()->showMessage(tr("The text is already formatted."), kStatusMessageMs);
        return;
    }
    int line = 0;
    int index = 0;
    m_editor->getCursorPosition(&line, &index);
    const int firstShown = m_editor->firstVisibleLine();
    // One replacement inside one undo action: a single Undo brings the old text back.
    m_editor->beginUndoAction();
    m_editor->SendScintilla(QsciScintillaBase::SCI_SETTARGETRANGE, 0UL,
                            static_cast<long>(m_editor->length()));
    m_editor->SendScintilla(QsciScintillaBase::SCI_REPLACETARGET,
                            static_cast<unsigned long>(formatted.size()), formatted.data());
    m_editor->endUndoAction();
    m_editor->setCursorPosition(std::min(line, m_editor->lines() - 1), 0);
    m_editor->setFirstVisibleLine(firstShown);
    check();
    statusBar()->showMessage(tr("Formatted."), kStatusMessageMs);
}

void MainWindow::about() {
    QMessageBox::about(
        this, tr("About Rungsmith"),
        tr("<h3>Rungsmith %1</h3>"
           "<p>An IDE for Pluto safety PLCs: write and check programs in the Pluto text "
           "language.</p>"
           "<p>Built with Qt %2 and QScintilla %3.</p>")
            .arg(QStringLiteral(RUNGSMITH_VERSION), QString::fromLatin1(qVersion()),
                 QStringLiteral(QSCINTILLA_VERSION_STR)));
}

bool MainWindow::maybeSave() {
    if (!m_editor->isModified())
        return true;
    const auto answer = QMessageBox::warning(
        this, tr("Unsaved Changes"),
        tr("“%1” has changes that are not saved. Save them?").arg(m_displayName),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save)
        return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::fillRecentMenu() {
    m_recentMenu->clear();
    const QStringList paths = m_recentFiles.paths();
    for (int i = 0; i < paths.size(); ++i) {
        const QString shown =
            fontMetrics().elidedText(QDir::toNativeSeparators(paths[i]), Qt::ElideMiddle, 480);
        QAction* entry = m_recentMenu->addAction(QStringLiteral("&%1 %2").arg(i + 1).arg(
            QString(shown).replace(QLatin1Char('&'), QStringLiteral("&&"))));
        entry->setStatusTip(paths[i]);
        connect(entry, &QAction::triggered, this, [this, path = paths[i]] { openFile(path); });
    }
    if (!paths.isEmpty()) {
        m_recentMenu->addSeparator();
        m_recentMenu->addAction(tr("&Clear Menu"), this, [this] { m_recentFiles.clear(); });
    }
    m_recentMenu->menuAction()->setEnabled(!paths.isEmpty());
}

void MainWindow::restoreLayout() {
    const QSettings settings;
    if (settings.contains(kGeometryKey))
        restoreGeometry(settings.value(kGeometryKey).toByteArray());
    restoreState(settings.value(kStateKey).toByteArray());
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    QSettings settings;
    settings.setValue(kGeometryKey, saveGeometry());
    settings.setValue(kStateKey, saveState());
    event->accept();
}

} // namespace rs::ui
