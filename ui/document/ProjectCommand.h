// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "project/ProjectChange.h"

#include <QUndoCommand>

namespace rs::ui {

class ProjectDocument;

// One edit of a project on its undo stack: the parts of the model it changed,
// before and after.
class ProjectCommand : public QUndoCommand {
public:
    ProjectCommand(ProjectDocument& document, project::ProjectChange change, const QString& text);

    void redo() override;
    void undo() override;

private:
    ProjectDocument& m_document;
    project::ProjectChange m_change;
};

} // namespace rs::ui
