// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QDateTime>
#include <QList>
#include <QString>

namespace rs::ui {

class ProjectDocument;

// Copies of modified projects, written every few minutes to a folder of the
// user's, so that the work survives a crash. A project's copy goes when it is
// saved or closed; copies still there at start-up are offered for recovery.
// While a Rungsmith holds a project open, a lock file says so, so that another
// Rungsmith running at the same time does not take its copies for a crash's.
class Autosave {
public:
    struct Copy {
        QString id;
        QString path;        // the project's own file, empty when never saved
        QString displayName; // as the window named it
        QDateTime written;
        QString copyPath; // the autosaved text
    };

    // The folder of the copies; tests point it elsewhere.
    static QString directory();
    static void setDirectory(const QString& directory);

    // Writes the document's copy; returns the error message, empty on success.
    static QString write(const ProjectDocument& document);
    // The same for any document: its id, its file, its name and its text
    // (a PL110 program's copy is its text; recovery tells the two apart).
    static QString write(const QString& id, const QString& path, const QString& displayName,
                         const QByteArray& text);
    static void remove(const QString& id);
    // Leaves the copy for recovery but lets go of its lock (the window goes
    // without its projects having been saved or closed).
    static void release(const QString& id);
    static QList<Copy> copies();
};

} // namespace rs::ui
