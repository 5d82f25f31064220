// SPDX-License-Identifier: GPL-3.0-or-later
#include "review/ProjectComparison.h"

#include "ReviewPages.h"
#include "blocks/ProjectInstances.h"
#include "project/ProjectFile.h"
#include "review/Validation.h"

#include <QCoreApplication>
#include <QDir>

namespace rs::ui {

namespace {

// One side read with its block instances (as the compiler and `diff` read it) and compiled.
struct Version {
    blocks::LibraryPlaces places;
    blocks::ProjectWithInstances read;
    compiler::CompileResult compiled;

    Version(const std::string& text, const QString& path, const QString& executableDir)
        : places{executableDir, path, {}}, read(blocks::readProjectWithInstances(text, places)),
          compiled(blocks::compileProject(read.read.project, read.read.diagnostics)) {}
};

QString hasErrors(const QString& name, int errors) {
    return QCoreApplication::translate("ProjectComparison",
                                       "%1 has %n error(s), so its behaviour cannot be compared. "
                                       "Build > Compile lists them.",
                                       nullptr, errors)
        .arg(name);
}

QString currentName(const QString& currentPath) {
    return currentPath.isEmpty() ? QCoreApplication::translate("ProjectComparison", "The project")
                                 : QDir::toNativeSeparators(currentPath);
}

} // namespace

ProjectComparison compareWithFile(const QString& oldPath, const std::string& currentText,
                                  const QString& currentPath, const QString& executableDir) {
    ProjectComparison comparison;
    const project::FileText file = project::readTextFile(oldPath);
    if (!file.error.isEmpty()) {
        comparison.error = file.error;
        return comparison;
    }
    const Version before(file.text, oldPath, executableDir);
    const Version after(currentText, currentPath, executableDir);
    if (before.compiled.errors())
        comparison.error = hasErrors(QDir::toNativeSeparators(oldPath), before.compiled.errors());
    else if (after.compiled.errors())
        comparison.error = hasErrors(currentName(currentPath), after.compiled.errors());
    if (!comparison.error.isEmpty())
        return comparison;
    comparison.diff = review::diffProjects(before.read.read.project, before.compiled,
                                           after.read.read.project, after.compiled);
    comparison.review =
        render::reviewPages({QDir::toNativeSeparators(oldPath), before.read.read.project,
                             before.places, before.compiled},
                            {currentPath.isEmpty() ? QStringLiteral("(not saved)")
                                                   : QDir::toNativeSeparators(currentPath),
                             after.read.read.project, after.places, after.compiled},
                            *comparison.diff, QStringLiteral("Rungsmith"));
    return comparison;
}

ProjectComparison compareWithBaseline(const std::string& currentText, const QString& currentPath,
                                      const QString& executableDir) {
    ProjectComparison comparison;
    const Version now(currentText, currentPath, executableDir);
    if (now.compiled.errors())
        comparison.error = hasErrors(currentName(currentPath), now.compiled.errors());
    else
        comparison.diff = review::changesSinceValidation(now.read.read.project, now.compiled);
    return comparison;
}

} // namespace rs::ui
