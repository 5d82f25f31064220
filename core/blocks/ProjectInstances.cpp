// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProjectInstances.h"

#include "BlockInstance.h"
#include "InstanceExpansion.h"
#include "InstanceStanding.h"
#include "UnitVariables.h"

#include <QDir>
#include <QFileInfo>

#include <algorithm>
#include <numeric>
#include <optional>

namespace rs::blocks {

namespace {

// A user library entry's file: relative to the project's folder.
QString userLibraryPath(const LibraryPlaces& places, const std::string& entry) {
    const QString folder =
        places.projectPath.isEmpty() ? QString() : QFileInfo(places.projectPath).absolutePath();
    return QDir(folder).absoluteFilePath(QString::fromStdString(entry));
}

QString projectFolderOf(const LibraryPlaces& places) {
    return places.projectPath.isEmpty() ? QString() : QFileInfo(places.projectPath).absolutePath();
}

struct Pending {
    lang::Step* step;
    BlockInstance instance;
    std::vector<lang::Line> lines;
};

} // namespace

InstanceExpansion expandInstances(lang::Document& document, const LibrarySet& libraries) {
    return expandInstances(document, [&libraries]() -> const LibrarySet& { return libraries; });
}

InstanceExpansion expandInstances(lang::Document& document,
                                  const std::function<const LibrarySet&()>& librariesWhenNeeded) {
    InstanceExpansion result;
    lang::Diagnostics& diagnostics = result.diagnostics;
    for (auto& unit : document.units) {
        const int station = unit.station();
        std::vector<std::pair<lang::Step*, BlockInstance>> instances;
        for (auto& step : unit.steps) {
            StepInstances found = findInstances(step);
            diagnostics.insert(diagnostics.end(), found.diagnostics.begin(),
                               found.diagnostics.end());
            for (auto& instance : found.instances)
                instances.emplace_back(&step, std::move(instance));
        }
        if (instances.empty())
            continue;
        const LibrarySet& libraries = librariesWhenNeeded();
        std::vector<const BlockInstance*> recorded;
        for (const auto& found : instances)
            recorded.push_back(&found.second);
        PrivateVariables variables = freeVariables(document, station, recorded);

        UnitFrame frame(document, station);
        std::vector<Pending> pending;
        for (auto& [step, instance] : instances) {
            const LoadedLibrary* library = libraryOf(instance, libraries);
            const BlockDefinition* block =
                library ? library->library.findBlock(instance.type) : nullptr;
            const lang::SourceLocation at = instance.location;
            if (instance.hasExpansion()) {
                if (!block)
                    continue; // the statements are the program; the library is not needed
                const Standing standing = standingOf(block, instance, *step, frame, variables);
                if (standing == Standing::OtherVersion)
                    diagnostics.push_back({lang::Severity::Warning, at.line, at.column,
                                           instance.type + " is version " + block->version +
                                               " in its library; this instance was made by " +
                                               instance.version});
                else if (standing == Standing::EditedByHand)
                    diagnostics.push_back(
                        {lang::Severity::Warning, at.line, at.column,
                         "the statements of this " + instance.type +
                             " are not what the block makes of its record (edited by hand?); "
                             "they are kept and read as ordinary statements"});
                continue;
            }
            if (!block) {
                diagnostics.push_back(
                    {lang::Severity::Error, at.line, at.column,
                     "unknown block '" + instance.type + "'" +
                         (instance.library.empty() ? std::string()
                                                   : " in library '" + instance.library + "'")});
                continue;
            }
            Expansion expansion = expandInstance(*block, instance, frame, variables);
            diagnostics.insert(diagnostics.end(), expansion.diagnostics.begin(),
                               expansion.diagnostics.end());
            if (!expansion.ok())
                continue;
            instance.library = library->library.name;
            instance.version = block->version;
            pending.push_back({step, std::move(instance), std::move(expansion.lines)});
        }
        // Each step is written once, its expansions in place: inserting them
        // one by one would move the lines after them again for every instance.
        for (auto first = pending.begin(); first != pending.end();) {
            lang::Step* step = first->step;
            const auto last = std::find_if(first, pending.end(),
                                           [&](const Pending& p) { return p.step != step; });
            std::vector<lang::Line> lines;
            lines.reserve(step->lines.size() + std::accumulate(first, last, std::size_t{0},
                                                               [](std::size_t n, const Pending& p) {
                                                                   return n + p.lines.size();
                                                               }));
            auto next = first;
            for (std::size_t i = 0; i < step->lines.size(); ++i) {
                if (next != last && i == next->instance.end) {
                    lines.insert(lines.end(), std::make_move_iterator(next->lines.begin()),
                                 std::make_move_iterator(next->lines.end()));
                    ++next;
                    ++result.expanded;
                }
                lines.push_back(std::move(step->lines[i]));
                if (next != last && i == next->instance.record)
                    std::get<lang::CommentLine>(lines.back().body).text =
                        recordText(next->instance);
            }
            step->lines = std::move(lines);
            first = last;
        }
    }
    return result;
}

ProjectWithInstances readProjectWithInstances(std::string_view text, const LibrarySet& libraries) {
    ProjectWithInstances result{project::readProject(text), false, {}};
    project::ProjectReadResult& read = result.read;
    if (!read.ok())
        return result;
    const InstanceExpansion expansion = expandInstances(read.project.program, libraries);
    read.diagnostics.insert(read.diagnostics.end(), expansion.diagnostics.begin(),
                            expansion.diagnostics.end());
    lang::sortByPlace(read.diagnostics);
    result.expanded = expansion.expanded > 0;
    return result;
}

compiler::CompileResult compileProject(const project::Project& project,
                                       const lang::Diagnostics& readDiagnostics,
                                       const compiler::CheckOptions& options,
                                       std::string_view readFrom, compiler::Output output) {
    if (lang::errorCount(readDiagnostics) > 0) {
        compiler::CompileResult failed;
        failed.diagnostics = readDiagnostics;
        return failed;
    }
    compiler::CompileResult result = compiler::compile(project, options, readFrom, output);
    result.diagnostics.insert(result.diagnostics.begin(), readDiagnostics.begin(),
                              readDiagnostics.end());
    lang::sortByPlace(result.diagnostics);
    return result;
}

bool isUserLibraryEntry(std::string_view entry) {
    const std::string_view extension = kLibraryExtension;
    return entry.find('/') != std::string_view::npos ||
           (entry.size() > extension.size() && entry.ends_with(extension) &&
            entry[entry.size() - extension.size() - 1] == '.');
}

const LoadedLibrary* libraryOfEntry(const LibrarySet& set, const LibraryPlaces& places,
                                    const std::string& entry) {
    if (!isUserLibraryEntry(entry))
        return set.findLibrary(entry);
    const QString path = userLibraryPath(places, entry);
    for (const auto& loaded : set.libraries)
        if (loaded.origin == LibraryOrigin::User && loaded.path == path)
            return &loaded;
    return nullptr;
}

LibrarySet librariesFor(const LibraryPlaces& places,
                        const std::vector<std::string>& projectLibraries) {
    const QString projectFolder = projectFolderOf(places);
    const QStringList standardFolders = standardLibraryFolders(places.executableDir);
    if (projectLibraries.empty())
        return loadLibraries(standardFolders, projectFolder, places.userFiles);
    const LibrarySet standard = loadLibraries(standardFolders, {}, {});
    LibrarySet set;
    set.problems = standard.problems;
    for (const auto& named : projectLibraries) {
        if (isUserLibraryEntry(named)) {
            addLibraryFile(set, userLibraryPath(places, named), LibraryOrigin::User);
        } else if (const LoadedLibrary* found = standard.findLibrary(named)) {
            if (!set.findLibrary(named))
                set.libraries.push_back(*found);
        } else {
            set.problems.push_back(
                {places.projectPath,
                 {},
                 {{lang::Severity::Warning, 1, 1,
                   "the project uses the library '" + named + "', which is not installed"}}});
        }
    }
    for (const QString& path : places.userFiles)
        addLibraryFile(set, path, LibraryOrigin::User);
    return set;
}

ProjectWithInstances readProjectWithInstances(std::string_view text, const LibraryPlaces& places) {
    ProjectWithInstances result{project::readProject(text), false, {}};
    project::ProjectReadResult& read = result.read;
    if (!read.ok())
        return result;
    std::optional<LibrarySet> libraries;
    const auto all = [&]() -> const LibrarySet& {
        if (!libraries)
            libraries = librariesFor(places, read.project.libraries);
        return *libraries;
    };
    if (!read.project.libraries.empty())
        all(); // a library it names and that is missing is a warning
    const InstanceExpansion expansion = expandInstances(read.project.program, all);
    read.diagnostics.insert(read.diagnostics.end(), expansion.diagnostics.begin(),
                            expansion.diagnostics.end());
    lang::sortByPlace(read.diagnostics);
    result.expanded = expansion.expanded > 0;
    // Without an instance the standard libraries stay unread; the user's are
    // read for their problems.
    result.libraryProblems =
        libraries ? std::move(libraries->problems)
                  : loadLibraries({}, projectFolderOf(places), places.userFiles).problems;
    return result;
}

} // namespace rs::blocks
