// SPDX-License-Identifier: GPL-3.0-or-later
#include "document/ProjectMerging.h"

#include "document/ProjectDocument.h"
#include "project/ProjectMerge.h"

#include <QCoreApplication>
#include <QInputDialog>
#include <QMessageBox>
#include <QStringList>

namespace rs::ui {

namespace {

// A message about the merge with the conflicts listed below it.
void tellConflicts(QWidget* parent, QMessageBox::Icon icon, const QString& text,
                   const std::vector<std::string>& conflicts) {
    QStringList lines;
    for (const std::string& conflict : conflicts)
        lines << QString::fromStdString(conflict);
    QMessageBox box(icon, QCoreApplication::translate("ProjectMerging", "Merge Project"), text,
                    QMessageBox::Ok, parent);
    box.setInformativeText(lines.join(QLatin1Char('\n')));
    box.exec();
}

} // namespace

ProjectDocument* chooseProjectToMerge(QWidget* parent, const ProjectDocument* into,
                                      const std::vector<ProjectDocument*>& open) {
    std::vector<ProjectDocument*> others;
    QStringList names;
    for (ProjectDocument* document : open)
        if (document != into && !document->isDamaged()) {
            others.push_back(document);
            names << document->displayName();
        }
    if (others.empty()) {
        QMessageBox::information(
            parent, QCoreApplication::translate("ProjectMerging", "Merge Project"),
            QCoreApplication::translate("ProjectMerging",
                                        "Open the project to merge first (File > Open); its units "
                                        "are then added to %1.")
                .arg(into->displayName()));
        return nullptr;
    }
    bool chosen = false;
    const QString name = QInputDialog::getItem(
        parent, QCoreApplication::translate("ProjectMerging", "Merge Project"),
        QCoreApplication::translate("ProjectMerging", "Add the units of this project to %1:")
            .arg(into->displayName()),
        names, 0, false, &chosen);
    if (!chosen)
        return nullptr;
    return others[static_cast<std::size_t>(names.indexOf(name))];
}

QString mergeOpenProject(QWidget* parent, ProjectDocument* into, const ProjectDocument* other,
                         bool ignoreNameConflicts) {
    const project::MergeResult result =
        project::mergeProjects(into->project(), other->project(), ignoreNameConflicts);
    if (!result.merged) {
        tellConflicts(parent, QMessageBox::Warning,
                      QCoreApplication::translate(
                          "ProjectMerging",
                          "%1 cannot be merged into %2: every unit must keep its station and "
                          "every symbolic name must be one project's only.")
                          .arg(other->displayName(), into->displayName()),
                      result.conflicts);
        return {};
    }
    into->replace(QCoreApplication::translate("ProjectMerging", "Merge Project"), *result.merged);
    if (!result.conflicts.empty())
        tellConflicts(parent, QMessageBox::Information,
                      QCoreApplication::translate(
                          "ProjectMerging",
                          "%1 is merged into %2. Each name both used stays only in the units "
                          "that define it; elsewhere its variable is written as its address.")
                          .arg(other->displayName(), into->displayName()),
                      result.conflicts);
    return QCoreApplication::translate("ProjectMerging", "%1 is merged into %2.")
        .arg(other->displayName(), into->displayName());
}

} // namespace rs::ui
