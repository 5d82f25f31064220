// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

namespace rs::ui {

class ProjectDocument;

// Where a project's files are, and where the file dialogs suggest putting them.

// A project saved in a file of its own: not new, and not the example that
// comes with the IDE (a resource path).
bool hasOwnFile(const ProjectDocument& document);
// The project's file, or for a project without one its name in the last folder.
QString suggestedPath(const ProjectDocument& document);
// The folder a file was last opened from or saved to, kept in the user's
// settings; the documents folder at first.
QString lastDirectory();
void rememberDirectory(const QString& path);

} // namespace rs::ui
