// SPDX-License-Identifier: GPL-3.0-or-later
#include "VarsVerbs.h"

#include "Pl110Verbs.h"
#include "ProtectedWriting.h"
#include "Verbs.h"
#include "lang/Diagnostic.h"
#include "project/ProjectFile.h"
#include "project/VariableCsv.h"

#include <cstdio>
#include <optional>

namespace rs::cli {

namespace {

// The project with its diagnostics reported; nothing when it cannot be read
// (exit 2) or has errors (exit 1), with the status in `status`.
std::optional<project::Project> loadProject(const Invocation& invocation, const QString& path,
                                            int& status) {
    LoadedProject loaded = rs::cli::loadProject(path, libraryFiles(invocation));
    if (loaded.status != Ok) {
        status = loaded.status;
        return std::nullopt;
    }
    printDiagnostics(path, loaded.diagnostics);
    if (!loaded.ok()) {
        status = Failed;
        return std::nullopt;
    }
    return std::move(loaded.project);
}

int write(const QString& path, std::string_view text) {
    const QString error = project::writeTextFile(path, text);
    if (error.isEmpty())
        return Ok;
    std::fprintf(stderr, "rungsmith-cli: %s\n", qPrintable(error));
    return UsageOrIo;
}

int exportCsv(const Invocation& invocation, const QString& projectPath, const QString& out) {
    int status = Ok;
    const auto project = loadProject(invocation, projectPath, status);
    if (!project)
        return status;
    return write(out, project::exportVariablesCsv(*project, {}));
}

int importCsv(const Invocation& invocation, const QString& projectPath, const QString& csvPath,
              const QString& out) {
    int status = Ok;
    const auto project = loadProject(invocation, projectPath, status);
    if (!project)
        return status;
    const project::FileText csv = project::readTextFile(csvPath);
    if (!csv.error.isEmpty()) {
        std::fprintf(stderr, "rungsmith-cli: %s\n", qPrintable(csv.error));
        return UsageOrIo;
    }
    const project::CsvImport imported = project::importVariablesCsv(*project, csv.text, {});
    for (const auto& problem : imported.problems)
        std::fprintf(stderr, "%s:%d:%d: error: %s\n", qPrintable(csvPath), problem.line,
                     problem.column, lang::visibleText(problem.message).c_str());
    if (!imported.problems.empty())
        return Failed;
    const auto keys = writingKeys(invocation, projectPath, *project, status);
    if (!keys)
        return status;
    return writeProjectFile(out, imported.project, *keys);
}

} // namespace

int runVars(const Invocation& invocation) {
    const QStringList& arguments = invocation.arguments;
    const QString out = invocation.options.value(QStringLiteral("output"));
    if (arguments.isEmpty())
        return usage("vars takes export or import");
    const QString& action = arguments.front();
    if (action == QLatin1String("export")) {
        if (arguments.size() != 2 || out.isEmpty())
            return usage("vars export takes FILE.sps and -o OUT.csv");
        if (const auto text = pl110Text(arguments[1]))
            return exportPl110Names(*text, arguments[1], out);
        return exportCsv(invocation, arguments[1], out);
    }
    if (action == QLatin1String("import")) {
        if (arguments.size() != 3 || out.isEmpty())
            return usage("vars import takes FILE.sps, IN.csv and -o OUT.sps");
        if (const auto text = pl110Text(arguments[1]))
            return importPl110Names(*text, arguments[1], arguments[2], out);
        return importCsv(invocation, arguments[1], arguments[2], out);
    }
    return usage(
        qPrintable(QStringLiteral("unknown vars action '%1'; use export or import").arg(action)));
}

} // namespace rs::cli
