// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <vector>

class QWidget;

namespace rs::ui {

class ProjectDocument;

// The project tree's Merge Project... and Merge Project (ignore conflicts)...
// (manual Part 1, 12.2; project/ProjectMerge.h), on open projects.

// Asks which of the other open projects to merge into `into`; nullptr when
// none is open (the user is told to open one) or the choice is cancelled.
ProjectDocument* chooseProjectToMerge(QWidget* parent, const ProjectDocument* into,
                                      const std::vector<ProjectDocument*>& open);

// Adds the units of `other` to `into` as one undo step. Conflicts are listed
// in a message box and nothing is merged, or, ignoring name conflicts, the
// shared names are listed after merging. Returns what the status bar says,
// empty when nothing was merged.
QString mergeOpenProject(QWidget* parent, ProjectDocument* into, const ProjectDocument* other,
                         bool ignoreNameConflicts);

} // namespace rs::ui
