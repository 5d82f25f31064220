// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Holds core types by value, so their headers come in here; Qt 6.4's moc cannot
// parse the C++20 standard headers they bring in (<concepts>) and needs only the names.
#ifndef Q_MOC_RUN
#include "blocks/LibrarySearch.h"
#include "lang/Diagnostic.h"
#include "project/Project.h"
#include "project/ProjectChange.h"
#include "project/ProtectionKeys.h"
#endif

#include <QObject>
#include <QString>
#include <QUndoStack>

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

namespace rs::ui {

// One open project: the model every page shows, the undo stack that every
// edit of every page goes through, and the file it belongs to.
//
// A file that reads with errors is kept as the text it is ("damaged"): the
// lines with errors could not be shown on the pages and would be lost on
// saving, so the project is edited as text until it reads cleanly.
//
// A password-protected project (manual Part 1, 4.1) is opened with a
// permission: every edit goes through replace(), which refuses all of them
// read only and, with permission to configure, any that changes more than
// the Config Options' states. Saving seals the file with the keys held.
class ProjectDocument : public QObject {
    Q_OBJECT
public:
    explicit ProjectDocument(project::Project project, QObject* parent = nullptr);
    ~ProjectDocument() override;

    const project::Project& project() const { return m_project; }
    QUndoStack* undoStack() { return &m_undoStack; }

    // Applies an edit as one undo step named `text`. Nothing is pushed when
    // the edit changes nothing or the permission refuses it (editRefused).
    // Returns whether it changed the project.
    bool edit(const QString& text, const std::function<void(project::Project&)>& change);
    bool replace(const QString& text, const project::Project& after);
    // The same, of the code of one unit: `change` is given, and `after` is,
    // the project without the other units' code (project::withOnlyCodeOf),
    // so an edit of a large project copies and compares one unit, not all.
    bool editUnitCode(const QString& text, int station,
                      const std::function<void(project::Project&)>& change);
    bool replaceUnitCode(const QString& text, int station, const project::Project& after);
    // The same, of a run of one step's lines: lines [first, first + removed)
    // of the unit's step `step` (its index) become `lines`. The cost is the run's.
    bool replaceStepLines(const QString& text, int station, std::size_t step, std::size_t first,
                          std::size_t removed, std::vector<lang::Line> lines);
    // While changed() is emitted for an undo step that replaced a run of one
    // step's lines and nothing else: which (ProjectChange::stepLines), so
    // that a view of the step reads again only what the run touches.
    const std::optional<project::StepLinesChange>& changedStepLines() const {
        return m_changedStepLines;
    }

    // The libraries the project uses (Project::libraries, found as
    // blocks::librariesFor finds them), read when first asked for and again
    // once that list or the project's file changes.
    const blocks::LibrarySet& libraries() const;
    // Reads the libraries again at the next call of libraries(): a user
    // library's file was written.
    void reloadLibraries();

    // What the user may change; Full for a project without protection.
    project::Permission permission() const { return m_permission; }
    // Sets the permission the project was opened with and the keys that gave it.
    void setPermission(project::Permission permission, const project::Keyring& keys);
    // Keys of a protection made in this session (File > Password Protect).
    void addKeys(const project::Keyring& keys);
    // A protected file changed outside Rungsmith: where, as reading it found.
    // Such a file opens read only.
    const std::optional<lang::Diagnostic>& tampering() const { return m_tampering; }
    // The holder of the main password takes such a change as theirs: full
    // permission, and saving seals the file again.
    void acceptTampering(const project::Keyring& keys);

    // Called by the undo commands.
    void applyChange(const project::ProjectChange& change, bool forward);

    QString path() const { return m_path; }
    // The file name, or a name for a project never saved.
    QString displayName() const;
    bool isModified() const;
    // A project that has never been saved, or was recovered, counts as modified.
    void setModifiedWithoutUndo(bool modified);

    bool isDamaged() const { return m_damaged; }
    const QByteArray& damagedText() const { return m_damagedText; }
    void setDamagedText(const QByteArray& text);
    // The damaged text now reads cleanly: it becomes the project.
    void repair(project::Project project);

    // What Save writes: the canonical text, or the damaged text as it is.
    QByteArray fileText() const;
    // Writes the file atomically, and the properties beside it when they
    // changed or the project moved; returns the error message, empty on success.
    QString saveTo(const QString& path);

    // The project's properties (docs/ide.md, "Properties"): the text of the
    // .prop file beside the project with its base name, which
    // `rungsmith-cli prove` takes too. Read when the project is opened, empty
    // when there is none; a change marks the project modified and Save
    // writes it. Not an undo step of the project: the editor undoes its typing.
    const QByteArray& propertiesText() const { return m_propertiesText; }
    void setPropertiesText(const QByteArray& text);
    // Why the properties file could not be read when the project was opened.
    const QString& propertiesError() const { return m_propertiesError; }
    // Where the properties are saved: beside the project file; empty without one.
    QString propertiesPath() const;
    static QString propertiesPathOf(const QString& projectPath);
    void setPath(const QString& path);

    // Identifies the project's autosave file.
    QString autosaveId() const { return m_autosaveId; }
    // A recovered project keeps writing to the copy it was recovered from.
    void setAutosaveId(const QString& id) { m_autosaveId = id; }

    // Reads a file; a file with errors opens damaged. Returns the error message
    // in `error` when the file cannot be read.
    static ProjectDocument* open(const QString& path, QString& error, QObject* parent);
    static ProjectDocument* fromText(const QByteArray& text, QObject* parent);

signals:
    void changed();
    // The properties' text changed (setPropertiesText).
    void propertiesChanged();
    void modificationChanged(bool modified);
    void pathChanged();
    // An edit was refused for the permission; `reason` says why, for the status bar.
    void editRefused(const QString& reason);
    void permissionChanged();

private:
    void emitModification();
    void refuse(const QString& reason);
    bool push(const QString& text, project::ProjectChange change,
              const project::Project* afterForPermission);

    project::Project m_project;
    QUndoStack m_undoStack;
    QString m_path;
    QString m_autosaveId;
    bool m_modifiedWithoutUndo = false;
    bool m_lastModified = false;
    bool m_damaged = false;
    QByteArray m_damagedText;
    QByteArray m_propertiesText;
    QString m_propertiesError;
    bool m_propertiesModified = false;
    project::Permission m_permission = project::Permission::Full;
    project::Keyring m_keys;
    std::optional<lang::Diagnostic> m_tampering;
    std::optional<project::StepLinesChange> m_changedStepLines;
    struct Libraries {
        std::vector<std::string> entries;
        QString path;
        blocks::LibrarySet set;
    };
    mutable std::optional<Libraries> m_libraries;
};

} // namespace rs::ui
