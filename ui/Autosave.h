#pragma once

#include <QDateTime>
#include <QList>
#include <QString>

namespace rs::ui {

class ProjectDocument;

// Copies of modified projects, written every few minutes to a folder of the
// user's, so that the work survives a crash. A project's copy goes when it is
// saved or closed; copies still there at start-up are offered for recovery.
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
    static void remove(const QString& id);
    static QList<Copy> copies();
};

} // namespace rs::ui
