// SPDX-License-Identifier: GPL-3.0-or-later
#include "document/OpenProjects.h"

#include "document/Autosave.h"
#include "document/PasswordProtectDialog.h"
#include "document/ProjectDocument.h"
#include "document/ProjectPaths.h"
#include "document/ProtectedOpenDialog.h"
#include "pages/NewProjectDialog.h"
#include "pl110/Pl110Document.h"
#include "pl110/Pl110Window.h"
#include "pl110/ProgramFile.h"
#include "pl110/ProgramText.h"
#include "project/ProgramText.h"
#include "project/ProjectFile.h"
#include "project/ProjectProperties.h"
#include "shell/NamedIcon.h"
#include "text/TextPage.h"

#include <QAction>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QLocale>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>

namespace rs::ui {

namespace {

const QString kExamplePath = QStringLiteral(":/examples/muting.sps");

constexpr int kMillisecondsPerMinute = 60 * 1000;

QString projectFileFilter() {
    return OpenProjects::tr("Pluto projects (*.sps);;All files (*)");
}

} // namespace

OpenProjects::OpenProjects(QWidget* window, TextPage* textPage,
                           std::function<ProjectDocument*()> current)
    : QObject(window), m_window(window), m_textPage(textPage), m_current(std::move(current)) {
    createActions();
    connect(&m_autosaveTimer, &QTimer::timeout, this, &OpenProjects::autosaveNow);
}

OpenProjects::~OpenProjects() {
    for (ProjectDocument* document : m_documents) {
        disconnect(document, nullptr, this, nullptr);
        Autosave::release(document->autosaveId());
    }
}

void OpenProjects::createActions() {
    const auto action = [this](const QString& text, const char* name,
                               const QKeySequence& shortcut = {}) {
        auto* created = new QAction(text, m_window);
        created->setObjectName(QString::fromLatin1(name));
        created->setShortcut(shortcut);
        return created;
    };

    m_actions.newProject = action(tr("&New Project..."), "newAction", QKeySequence::New);
    m_actions.newProject->setIcon(namedIcon("document-new"));
    m_actions.newProject->setStatusTip(tr("Start a new project"));
    connect(m_actions.newProject, &QAction::triggered, this, &OpenProjects::newProject);

    m_actions.open = action(tr("&Open Project..."), "openAction", QKeySequence::Open);
    m_actions.open->setIcon(namedIcon("document-open"));
    m_actions.open->setStatusTip(tr("Open a project file"));
    connect(m_actions.open, &QAction::triggered, this, &OpenProjects::open);

    m_actions.save = action(tr("&Save Project"), "saveAction", QKeySequence::Save);
    m_actions.save->setIcon(namedIcon("document-save"));
    m_actions.save->setStatusTip(tr("Save the project"));
    connect(m_actions.save, &QAction::triggered, this, [this] { save(m_current()); });

    m_actions.saveAs = action(tr("Save Project &As..."), "saveAsAction", QKeySequence::SaveAs);
    m_actions.saveAs->setStatusTip(tr("Save the project under a new name"));
    connect(m_actions.saveAs, &QAction::triggered, this, [this] { saveAs(m_current()); });

    m_actions.saveAll =
        action(tr("Save A&ll"), "saveAllAction", QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_L));
    m_actions.saveAll->setIcon(namedIcon("document-save-all"));
    m_actions.saveAll->setStatusTip(tr("Save every open project"));
    connect(m_actions.saveAll, &QAction::triggered, this, &OpenProjects::saveAll);

    m_actions.close = action(tr("&Close Project"), "closeAction", QKeySequence::Close);
    m_actions.close->setStatusTip(tr("Close the project"));
    connect(m_actions.close, &QAction::triggered, this, [this] {
        if (ProjectDocument* document = m_current())
            close(document);
    });

    m_actions.exportText = action(tr("&Program Text..."), "exportTextAction");
    m_actions.exportText->setStatusTip(
        tr("Write the program in the language alone, for a text editor or the original compiler"));
    connect(m_actions.exportText, &QAction::triggered, this,
            [this] { exportProgramText(m_current()); });

    m_actions.protect = action(tr("Pass&word Protect..."), "protectAction");
    m_actions.protect->setStatusTip(
        tr("Protect the project with a password, change its protection or take it off"));
    connect(m_actions.protect, &QAction::triggered, this, [this] { passwordProtect(m_current()); });

    m_actions.example = action(tr("Open &Example Project"), "exampleAction");
    m_actions.example->setIcon(namedIcon("example"));
    connect(m_actions.example, &QAction::triggered, this, &OpenProjects::showExample);
}

void OpenProjects::updateActions(const ProjectDocument* current) {
    const bool hasDocument = current != nullptr;
    m_actions.save->setEnabled(hasDocument);
    m_actions.saveAs->setEnabled(hasDocument);
    m_actions.saveAll->setEnabled(!m_documents.empty());
    m_actions.close->setEnabled(hasDocument);
    m_actions.exportText->setEnabled(hasDocument && !current->isDamaged());
    m_actions.protect->setEnabled(hasDocument && !current->isDamaged() &&
                                  current->permission() == project::Permission::Full);
}

void OpenProjects::fillRecentMenu(QMenu* menu) {
    menu->clear();
    const QStringList paths = m_recentFiles.paths();
    for (int i = 0; i < paths.size(); ++i) {
        const QString shown = m_window->fontMetrics().elidedText(QDir::toNativeSeparators(paths[i]),
                                                                 Qt::ElideMiddle, 480);
        QAction* entry = menu->addAction(QStringLiteral("&%1 %2").arg(i + 1).arg(
            QString(shown).replace(QLatin1Char('&'), QStringLiteral("&&"))));
        entry->setStatusTip(paths[i]);
        connect(entry, &QAction::triggered, this, [this, path = paths[i]] { openFile(path); });
    }
    if (!paths.isEmpty()) {
        menu->addSeparator();
        menu->addAction(tr("&Clear Menu"), this, [this] { m_recentFiles.clear(); });
    }
    menu->menuAction()->setEnabled(!paths.isEmpty());
}

// ----- coming and going

void OpenProjects::add(ProjectDocument* document) {
    document->setParent(m_window);
    m_documents.push_back(document);
    connect(document, &ProjectDocument::modificationChanged, this, [document](bool modified) {
        if (!modified)
            Autosave::remove(document->autosaveId());
    });
    emit added(document);
}

void OpenProjects::remove(ProjectDocument* document) {
    Autosave::remove(document->autosaveId());
    std::erase(m_documents, document);
    emit removed(document);
    document->deleteLater();
}

QString OpenProjects::loadFile(const QString& path) {
    const QString absolute = QFileInfo(path).absoluteFilePath();
    for (ProjectDocument* document : m_documents) {
        if (document->path() == absolute) {
            emit opened(document);
            return {};
        }
    }
    QString error;
    ProjectDocument* document = ProjectDocument::open(path, error, m_window);
    if (!document)
        return error;
    add(document);
    emit opened(document);
    return {};
}

bool OpenProjects::openFile(const QString& path) {
    // A PL110 program opens in a window of its own (docs/pl110.md, "The window").
    const bool pl110 = pl110::isPl110File(path);
    const std::size_t before = m_documents.size();
    const QString error = pl110 ? Pl110Window::openWindow(path) : loadFile(path);
    if (error.isEmpty() && m_documents.size() > before && !askPermission(m_documents.back())) {
        remove(m_documents.back());
        return false;
    }
    if (error.isEmpty()) {
        m_recentFiles.add(QFileInfo(path).absoluteFilePath());
        rememberDirectory(path);
        ProjectDocument* document = m_current();
        emit message(pl110 ? tr("Opened %1 in a PL110 window").arg(QDir::toNativeSeparators(path))
                     : document && document->isDamaged()
                         ? tr("Opened %1. It has errors: fix them in its text.")
                               .arg(QDir::toNativeSeparators(path))
                         : tr("Opened %1").arg(QDir::toNativeSeparators(path)));
        return true;
    }
    QMessageBox box(QMessageBox::Warning, tr("Open Project"),
                    tr("Could not open “%1”.").arg(QDir::toNativeSeparators(path)), QMessageBox::Ok,
                    m_window);
    box.setInformativeText(error);
    box.exec();
    return false;
}

bool OpenProjects::askPermission(ProjectDocument* document) {
    if (const auto& tampering = document->tampering()) {
        QMessageBox box(QMessageBox::Warning, tr("Open Project"),
                        tr("“%1” was changed outside Rungsmith after it was password protected.")
                            .arg(document->displayName()),
                        QMessageBox::No | QMessageBox::Yes, m_window);
        box.setInformativeText(
            tr("The first change is at line %1: the signature the password made does not cover "
               "it. The project opens read only; its protection is evidence of changes, not a "
               "lock, and the file stays readable text. The holder of the main password can "
               "accept the change once it is reviewed.")
                .arg(tampering->line));
        box.button(QMessageBox::No)->setText(tr("Open &Read Only"));
        box.button(QMessageBox::Yes)->setText(tr("&Accept the Change..."));
        box.setDefaultButton(QMessageBox::No);
        if (box.exec() != QMessageBox::Yes || !document->project().protection)
            return true;
        ProtectedOpenDialog dialog(document->displayName(), *document->project().protection,
                                   m_window);
        dialog.askForFullPermissionOnly();
        if (dialog.exec() == QDialog::Accepted)
            document->acceptTampering(dialog.keys());
        return true;
    }
    if (!document->project().protection)
        return true;
    ProtectedOpenDialog dialog(document->displayName(), *document->project().protection, m_window);
    if (dialog.exec() != QDialog::Accepted)
        return false;
    document->setPermission(dialog.permission(), dialog.keys());
    return true;
}

void OpenProjects::passwordProtect(ProjectDocument* document) {
    if (!document || document->permission() != project::Permission::Full)
        return;
    PasswordProtectDialog dialog(document->project().protection, m_window);
    if (dialog.exec() != QDialog::Accepted)
        return;
    if (const auto& chosen = dialog.protection()) {
        document->addKeys(chosen->keys);
        document->edit(tr("Password Protect"),
                       [&](project::Project& project) { project.protection = chosen->record; });
        emit message(tr("Protected with a password: saving writes the protection."));
    } else if (document->edit(tr("Remove Password Protection"),
                              [](project::Project& project) { project.protection.reset(); })) {
        emit message(tr("The password protection is off once the project is saved."));
    }
}

void OpenProjects::showExample() {
    const project::FileText file = project::readTextFile(kExamplePath);
    ProjectDocument* document =
        ProjectDocument::fromText(QByteArray::fromStdString(file.text), m_window);
    add(document);
    emit opened(document);
}

ProjectDocument* OpenProjects::createProject(const QString& name, const QString& description,
                                             bool includeSource) {
    auto* document = new ProjectDocument(
        project::newProject(name.toStdString(), description.toStdString(), includeSource),
        m_window);
    document->setModifiedWithoutUndo(true);
    add(document);
    emit created(document);
    return document;
}

void OpenProjects::newProject() {
    NewProjectDialog dialog(m_window);
    if (dialog.exec() != QDialog::Accepted)
        return;
    if (dialog.target() == NewProjectDialog::Target::Pl110) {
        Pl110Window::newWindow(dialog.name());
        return;
    }
    ProjectDocument* document =
        createProject(dialog.name(), dialog.description(), dialog.includeSource());
    emit unitWanted(document);
}

void OpenProjects::open() {
    const QString path = QFileDialog::getOpenFileName(m_window, tr("Open Project"), lastDirectory(),
                                                      projectFileFilter());
    if (!path.isEmpty())
        openFile(path);
}

// ----- saving and closing

bool OpenProjects::save(ProjectDocument* document) {
    if (!document)
        return false;
    if (!hasOwnFile(*document))
        return saveAs(document);
    return saveAs(document, document->path());
}

bool OpenProjects::saveAs(ProjectDocument* document, const QString& requested) {
    if (!document)
        return false;
    if (m_textPage->document() == document && !m_textPage->applyNow() &&
        m_textPage->station() != TextPage::kWholeProject) {
        const auto answer = QMessageBox::warning(
            m_window, tr("Save Project"),
            tr("The code of Pluto %1 has errors, so your last changes to it are not part of the "
               "project. Save the project without them?")
                .arg(m_textPage->station()),
            QMessageBox::Save | QMessageBox::Cancel, QMessageBox::Cancel);
        if (answer != QMessageBox::Save)
            return false;
    }
    QString path = requested;
    if (path.isEmpty()) {
        path = QFileDialog::getSaveFileName(m_window, tr("Save Project As"),
                                            suggestedPath(*document), projectFileFilter());
        if (path.isEmpty())
            return false;
        if (QFileInfo(path).suffix().isEmpty())
            path += QStringLiteral(".sps");
    }
    const QString error = document->saveTo(path);
    if (!error.isEmpty()) {
        QMessageBox box(QMessageBox::Critical, tr("Save Project"),
                        tr("Could not save “%1”.").arg(QDir::toNativeSeparators(path)),
                        QMessageBox::Ok, m_window);
        box.setInformativeText(error);
        box.exec();
        return false;
    }
    m_recentFiles.add(document->path());
    rememberDirectory(path);
    emit message(tr("Saved %1").arg(QDir::toNativeSeparators(document->path())));
    return true;
}

void OpenProjects::saveAll() {
    for (ProjectDocument* document : std::vector<ProjectDocument*>(m_documents))
        if (document->isModified() && !save(document))
            return;
}

bool OpenProjects::maybeSave(ProjectDocument* document) {
    if (!document->isModified())
        return true;
    const auto answer = QMessageBox::warning(
        m_window, tr("Unsaved Changes"),
        tr("“%1” has changes that are not saved. Save them?").arg(document->displayName()),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save)
        return save(document);
    return answer == QMessageBox::Discard;
}

bool OpenProjects::close(ProjectDocument* document) {
    if (!document || !maybeSave(document))
        return false;
    remove(document);
    return true;
}

bool OpenProjects::exportProgramText(ProjectDocument* document, const QString& requested) {
    if (!document || document->isDamaged())
        return false;
    QString path = requested;
    if (path.isEmpty()) {
        const QFileInfo info(suggestedPath(*document));
        path = QFileDialog::getSaveFileName(
            m_window, tr("Export Program Text"),
            info.dir().filePath(info.completeBaseName() + tr("-program") + QStringLiteral(".sps")),
            projectFileFilter());
        if (path.isEmpty())
            return false;
    }
    const QString error = project::writeTextFile(path, project::programText(document->project()));
    if (!error.isEmpty()) {
        QMessageBox::critical(m_window, tr("Export Program Text"), error);
        return false;
    }
    emit message(tr("Wrote the program text to %1").arg(QDir::toNativeSeparators(path)));
    return true;
}

bool OpenProjects::prepareToQuit() {
    for (ProjectDocument* document : m_documents)
        if (!maybeSave(document))
            return false;
    for (ProjectDocument* document : m_documents)
        Autosave::remove(document->autosaveId());
    return true;
}

// ----- autosave

void OpenProjects::setAutosaveInterval(int minutes) {
    m_autosaveTimer.start(minutes * kMillisecondsPerMinute);
}

void OpenProjects::autosaveNow() {
    for (ProjectDocument* document : m_documents) {
        if (!document->isModified())
            continue;
        if (m_textPage->document() == document)
            m_textPage->applyNow();
        const QString error = Autosave::write(*document);
        if (!error.isEmpty())
            emit message(tr("Autosave failed: %1").arg(error));
    }
}

int OpenProjects::recoverAutosaved() {
    const QList<Autosave::Copy> copies = Autosave::copies();
    if (copies.isEmpty())
        return 0;
    QStringList names;
    for (const auto& copy : copies)
        names << QStringLiteral("%1 (%2)").arg(
            copy.displayName, QLocale().toString(copy.written, QLocale::ShortFormat));
    QMessageBox box(QMessageBox::Question, tr("Recover Projects"),
                    tr("Rungsmith was not closed properly. These projects have changes that were "
                       "saved automatically:"),
                    QMessageBox::NoButton, m_window);
    box.setInformativeText(names.join(QLatin1Char('\n')));
    QPushButton* recover = box.addButton(tr("&Recover"), QMessageBox::AcceptRole);
    box.setDefaultButton(recover);
    QAbstractButton* discard = box.addButton(QMessageBox::Discard);
    box.exec();
    if (box.clickedButton() == discard) {
        for (const auto& copy : copies)
            Autosave::remove(copy.id);
        return 0;
    }
    if (box.clickedButton() != recover) // closed without an answer: ask again next time
        return 0;
    int recovered = 0;
    for (const auto& copy : copies) {
        const project::FileText file = project::readTextFile(copy.copyPath);
        if (!file.error.isEmpty())
            continue;
        if (pl110::isPl110Text(file.text)) {
            // A PL110 program's copy opens in a window of its own again.
            auto* window = new Pl110Window(
                Pl110Document::recover(QByteArray::fromStdString(file.text), copy.path, copy.id));
            window->show();
            ++recovered;
            continue;
        }
        ProjectDocument* document =
            ProjectDocument::fromText(QByteArray::fromStdString(file.text), m_window);
        document->setAutosaveId(copy.id);
        if (!copy.path.isEmpty())
            document->setPath(copy.path);
        document->setModifiedWithoutUndo(true);
        add(document);
        emit opened(document);
        ++recovered;
    }
    return recovered;
}

} // namespace rs::ui
