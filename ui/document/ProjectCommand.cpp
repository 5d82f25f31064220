// SPDX-License-Identifier: GPL-3.0-or-later
#include "document/ProjectCommand.h"

#include "document/ProjectDocument.h"

namespace rs::ui {

ProjectCommand::ProjectCommand(ProjectDocument& document, project::ProjectChange change,
                               const QString& text)
    : QUndoCommand(text), m_document(document), m_change(std::move(change)) {}

void ProjectCommand::redo() {
    m_document.applyChange(m_change, true);
}

void ProjectCommand::undo() {
    m_document.applyChange(m_change, false);
}

} // namespace rs::ui
