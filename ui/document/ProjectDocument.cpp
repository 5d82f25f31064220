// SPDX-License-Identifier: GPL-3.0-or-later
#include "document/ProjectDocument.h"

#include "blocks/ProjectInstances.h"
#include "document/ProjectCommand.h"
#include "pl110/ProgramText.h"
#include "project/ProjectFile.h"
#include "project/ProtectedText.h"
#include "project/UnitText.h"

#include <QCoreApplication>

#include <QDir>
#include <QFileInfo>
#include <QUuid>

#include <algorithm>

namespace rs::ui {

namespace {

std::string_view view(const QByteArray& bytes) {
    return {bytes.constData(), static_cast<std::size_t>(bytes.size())};
}

} // namespace

ProjectDocument::ProjectDocument(project::Project project, QObject* parent)
    : QObject(parent), m_project(std::move(project)),
      m_autosaveId(QUuid::createUuid().toString(QUuid::WithoutBraces)) {
    connect(&m_undoStack, &QUndoStack::cleanChanged, this, &ProjectDocument::emitModification);
}

ProjectDocument::~ProjectDocument() {
    // The undo stack says it is clean as it goes; nobody is to hear that from
    // a project half destroyed.
    m_undoStack.disconnect(this);
}

ProjectDocument* ProjectDocument::fromText(const QByteArray& text, QObject* parent) {
    project::ProjectReadResult read = project::readProject(view(text));
    auto* document = new ProjectDocument(std::move(read.project), parent);
    if (!read.ok()) {
        document->m_damaged = true;
        document->m_damagedText = text;
    }
    // Protected: read only until a password opens more (OpenProjects asks).
    document->m_tampering = project::verifyProjectText(view(text));
    if (document->m_project.protection || document->m_tampering)
        document->m_permission = project::Permission::ReadOnly;
    return document;
}

ProjectDocument* ProjectDocument::open(const QString& path, QString& error, QObject* parent) {
    const project::FileText file = project::readTextFile(path);
    if (!file.error.isEmpty()) {
        error = file.error;
        return nullptr;
    }
    if (pl110::isPl110Text(file.text)) {
        // Read as a Pluto project it would be a wall of wrong errors.
        error = tr("It is a program for the Pixsys PL110, not a Pluto project: File > Open "
                   "opens it in a PL110 window.");
        return nullptr;
    }
    ProjectDocument* document = fromText(QByteArray::fromStdString(file.text), parent);
    document->m_path = QFileInfo(path).absoluteFilePath();
    if (const QString properties = document->propertiesPath(); QFileInfo::exists(properties)) {
        const project::FileText read = project::readTextFile(properties);
        document->m_propertiesError = read.error;
        document->m_propertiesText = QByteArray::fromStdString(read.text);
    }
    if (!document->isDamaged()) {
        // Instances written without their statements get them now, as one
        // undoable edit, so the project shows them and saving writes them.
        project::Project expanded = document->project();
        const blocks::InstanceExpansion expansion =
            blocks::expandInstances(expanded.program, document->libraries());
        if (expansion.expanded > 0)
            document->replace(tr("Expand Block Instances"), expanded);
    }
    return document;
}

const blocks::LibrarySet& ProjectDocument::libraries() const {
    if (!m_libraries || m_libraries->entries != m_project.libraries || m_libraries->path != m_path)
        m_libraries =
            Libraries{m_project.libraries, m_path,
                      blocks::librariesFor({QCoreApplication::applicationDirPath(), m_path, {}},
                                           m_project.libraries)};
    return m_libraries->set;
}

void ProjectDocument::reloadLibraries() {
    m_libraries.reset();
}

bool ProjectDocument::edit(const QString& text,
                           const std::function<void(project::Project&)>& change) {
    project::Project after = m_project;
    change(after);
    return replace(text, after);
}

bool ProjectDocument::replace(const QString& text, const project::Project& after) {
    return push(text, project::ProjectChange::between(m_project, after), &after);
}

bool ProjectDocument::editUnitCode(const QString& text, int station,
                                   const std::function<void(project::Project&)>& change) {
    project::Project after = project::withOnlyCodeOf(m_project, station);
    change(after);
    return replaceUnitCode(text, station, after);
}

bool ProjectDocument::replaceUnitCode(const QString& text, int station,
                                      const project::Project& after) {
    project::ProjectChange change = project::ProjectChange::ofUnitCode(m_project, after, station);
    if (m_permission != project::Permission::Configure)
        return push(text, std::move(change), nullptr);
    // Whether only options change is told of whole projects; rare enough to copy.
    project::Project whole = m_project;
    change.apply(whole);
    return push(text, std::move(change), &whole);
}

bool ProjectDocument::replaceStepLines(const QString& text, int station, std::size_t step,
                                       std::size_t first, std::size_t removed,
                                       std::vector<lang::Line> lines) {
    const auto& units = m_project.program.units;
    const auto unit = std::find_if(units.begin(), units.end(), [&](const lang::UnitProgram& u) {
        return u.station() == station;
    });
    if (unit == units.end())
        return false;
    project::ProjectChange change = project::ProjectChange::ofStepLines(
        m_project, static_cast<std::size_t>(unit - units.begin()), step, first, removed,
        std::move(lines));
    if (m_permission != project::Permission::Configure)
        return push(text, std::move(change), nullptr);
    project::Project whole = m_project;
    change.apply(whole);
    return push(text, std::move(change), &whole);
}

bool ProjectDocument::push(const QString& text, project::ProjectChange change,
                           const project::Project* afterForPermission) {
    if (change.empty())
        return false;
    if (m_permission == project::Permission::ReadOnly) {
        refuse(tr("The project is open read only: nothing in it can change."));
        return false;
    }
    if (m_permission == project::Permission::Configure &&
        !project::changesOnlyOptions(m_project, *afterForPermission)) {
        refuse(tr("The project is open with permission to configure: only its Config Options "
                  "can change."));
        return false;
    }
    m_undoStack.push(new ProjectCommand(*this, std::move(change), text));
    return true;
}

void ProjectDocument::applyChange(const project::ProjectChange& change, bool forward) {
    if (forward)
        change.apply(m_project);
    else
        change.revert(m_project);
    m_changedStepLines = change.stepLines(forward);
    emit changed();
    m_changedStepLines.reset();
    emitModification();
}

QString ProjectDocument::displayName() const {
    if (!m_path.isEmpty())
        return QFileInfo(m_path).fileName();
    const QString name = QString::fromStdString(m_project.name());
    return (name.isEmpty() ? tr("Untitled") : name) + QStringLiteral(".sps");
}

bool ProjectDocument::isModified() const {
    return m_modifiedWithoutUndo || m_propertiesModified || !m_undoStack.isClean();
}

void ProjectDocument::setPropertiesText(const QByteArray& text) {
    if (text == m_propertiesText)
        return;
    m_propertiesText = text;
    m_propertiesModified = true;
    emit propertiesChanged();
    emitModification();
}

QString ProjectDocument::propertiesPathOf(const QString& projectPath) {
    if (projectPath.isEmpty() || projectPath.startsWith(QLatin1Char(':')))
        return {};
    const QFileInfo info(projectPath);
    return info.dir().filePath(info.completeBaseName() + QStringLiteral(".prop"));
}

QString ProjectDocument::propertiesPath() const {
    return propertiesPathOf(m_path);
}

void ProjectDocument::setModifiedWithoutUndo(bool modified) {
    m_modifiedWithoutUndo = modified;
    emitModification();
}

void ProjectDocument::setDamagedText(const QByteArray& text) {
    if (text == m_damagedText)
        return;
    m_damagedText = text;
    m_modifiedWithoutUndo = true;
    emitModification();
}

void ProjectDocument::repair(project::Project project) {
    m_project = std::move(project);
    m_damaged = false;
    m_damagedText.clear();
    m_undoStack.clear();
    m_modifiedWithoutUndo = true;
    emit changed();
    emitModification();
}

QByteArray ProjectDocument::fileText() const {
    if (m_damaged)
        return m_damagedText;
    return QByteArray::fromStdString(
        project::sealProjectText(project::writeProject(m_project), m_keys));
}

void ProjectDocument::refuse(const QString& reason) {
    emit editRefused(reason);
    // A view that showed the edit as typed (a table's cell) shows the project again.
    emit changed();
}

void ProjectDocument::setPermission(project::Permission permission, const project::Keyring& keys) {
    m_permission = permission;
    m_keys.add(keys);
    emit permissionChanged();
}

void ProjectDocument::acceptTampering(const project::Keyring& keys) {
    m_tampering.reset();
    m_modifiedWithoutUndo = true;
    setPermission(project::Permission::Full, keys);
    emitModification();
}

void ProjectDocument::addKeys(const project::Keyring& keys) {
    m_keys.add(keys);
}

QString ProjectDocument::saveTo(const QString& path) {
    const QByteArray text = fileText();
    const QString error = project::writeTextFile(path, view(text));
    if (!error.isEmpty())
        return error;
    // The properties go with the project: to a new place too, once they have any text.
    const QString propertiesFile = propertiesPathOf(QFileInfo(path).absoluteFilePath());
    const bool moved = propertiesFile != propertiesPath();
    QString propertiesError;
    const bool wanted = !m_propertiesText.isEmpty() || QFileInfo::exists(propertiesFile);
    if (wanted && (m_propertiesModified || moved))
        propertiesError = project::writeTextFile(propertiesFile, view(m_propertiesText));
    if (propertiesError.isEmpty())
        m_propertiesModified = false;
    setPath(path);
    m_modifiedWithoutUndo = false;
    m_undoStack.setClean();
    emitModification();
    return propertiesError;
}

void ProjectDocument::setPath(const QString& path) {
    const QString absolute = QFileInfo(path).absoluteFilePath();
    if (absolute == m_path)
        return;
    m_path = absolute;
    emit pathChanged();
}

void ProjectDocument::emitModification() {
    const bool modified = isModified();
    if (modified == m_lastModified)
        return;
    m_lastModified = modified;
    emit modificationChanged(modified);
}

} // namespace rs::ui
