// SPDX-License-Identifier: GPL-3.0-or-later
#include "MergeVerb.h"

#include "ProjectLoading.h"
#include "ProtectedWriting.h"
#include "Verbs.h"
#include "project/ProjectFile.h"
#include "project/ProjectMerge.h"

#include <cstdio>

namespace rs::cli {

namespace {

// The project as written (block instances as records, not expanded), when it reads cleanly.
std::optional<project::Project> readForMerge(const QString& path, const Invocation& invocation,
                                             int& status) {
    const LoadedProject loaded = loadProject(path, libraryFiles(invocation));
    if (loaded.status != Ok) {
        status = loaded.status;
        return std::nullopt;
    }
    printDiagnostics(path, loaded.diagnostics);
    if (!loaded.ok()) {
        std::fprintf(stderr, "rungsmith-cli: %s has errors and cannot be merged\n",
                     qPrintable(path));
        status = Failed;
        return std::nullopt;
    }
    return project::readProject(loaded.text).project;
}

} // namespace

int runMerge(const Invocation& invocation) {
    const QString output = invocation.options.value(QStringLiteral("output"));
    if (invocation.arguments.size() != 2 || output.isEmpty())
        return usage(QStringLiteral("merge takes A.sps, B.sps and -o OUT.sps"));
    const QString intoPath = invocation.arguments[0];
    const QString otherPath = invocation.arguments[1];
    int status = Ok;
    const auto into = readForMerge(intoPath, invocation, status);
    if (!into)
        return status;
    const auto other = readForMerge(otherPath, invocation, status);
    if (!other)
        return status;
    const bool ignore = invocation.options.isSet(QStringLiteral("ignore-conflicts"));
    const project::MergeResult result = project::mergeProjects(*into, *other, ignore);
    for (const std::string& conflict : result.conflicts)
        std::fprintf(stderr, "rungsmith-cli: %s: %s%s\n", qPrintable(otherPath), conflict.c_str(),
                     result.merged ? "; kept only in the units that define it" : "");
    if (!result.merged) {
        std::fprintf(stderr, "rungsmith-cli: %s and %s were not merged\n", qPrintable(intoPath),
                     qPrintable(otherPath));
        return Failed;
    }
    const auto keys = writingKeys(invocation, intoPath, *into, status);
    if (!keys)
        return status;
    return writeProjectFile(output, *result.merged, *keys);
}

} // namespace rs::cli
