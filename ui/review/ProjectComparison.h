// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#ifndef Q_MOC_RUN
#include "ReviewPdf.h"
#include "review/ProjectDiff.h"
#endif

#include <QString>

#include <optional>
#include <string>

namespace rs::ui {

// What Project > Compare With... shows (docs/review.md): `rungsmith-cli diff`
// of another version and the project as it is now, or what changed since the
// project's validated baseline. Both run on any thread.
struct ProjectComparison {
    QString error; // why nothing could be compared: a file not read, a side with errors
    std::optional<review::ProjectDiff> diff;
    // The pages `diff --pdf` writes; a baseline keeps no networks to draw, so
    // a comparison with it has none.
    std::optional<render::Review> review;
};

// The project as it is now (`currentText`, canonical) against the project
// in `oldPath`, which is the old side.
ProjectComparison compareWithFile(const QString& oldPath, const std::string& currentText,
                                  const QString& currentPath, const QString& executableDir);

// The project as it is now against its baseline, which it must have.
ProjectComparison compareWithBaseline(const std::string& currentText, const QString& currentPath,
                                      const QString& executableDir);

} // namespace rs::ui
