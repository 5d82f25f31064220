// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProjectLoading.h"

#include "Verbs.h"
#include "blocks/LibrarySearch.h"
#include "blocks/ProjectInstances.h"
#include "project/ProjectFile.h"
#include "project/ProtectedText.h"

#include <QCoreApplication>
#include <QFileInfo>

#include <cstdio>

namespace rs::cli {

bool isLibraryFile(const QString& value) {
    return QFileInfo(value).isFile() ||
           value.endsWith(QStringLiteral(".") + QLatin1String(blocks::kLibraryExtension));
}

QStringList libraryFiles(const Invocation& invocation) {
    QStringList files;
    for (const QString& value : invocation.options.values(QStringLiteral("lib")))
        if (isLibraryFile(value))
            files.append(value);
    return files;
}

LoadedProject loadProject(const QString& path, const QStringList& libraryFiles) {
    LoadedProject loaded;
    project::FileText file = project::readTextFile(path);
    if (!file.error.isEmpty()) {
        std::fprintf(stderr, "rungsmith-cli: %s\n", qPrintable(file.error));
        loaded.status = UsageOrIo;
        return loaded;
    }
    loaded.places = {QCoreApplication::applicationDirPath(), path, libraryFiles};
    blocks::ProjectWithInstances read = blocks::readProjectWithInstances(file.text, loaded.places);
    for (const auto& problem : read.libraryProblems) {
        if (!problem.readError.isEmpty()) {
            std::fprintf(stderr, "rungsmith-cli: %s\n", qPrintable(problem.readError));
            loaded.status = UsageOrIo;
        }
        printDiagnostics(problem.path, problem.diagnostics);
    }
    if (loaded.status != Ok)
        return loaded;
    loaded.project = std::move(read.read.project);
    loaded.diagnostics = std::move(read.read.diagnostics);
    // A protected project changed outside Rungsmith is not taken as its author left it.
    if (auto tampered = project::verifyProjectText(file.text)) {
        loaded.diagnostics.push_back(std::move(*tampered));
        lang::sortByPlace(loaded.diagnostics);
    }
    loaded.text = std::move(file.text);
    return loaded;
}

// The standard error is unbuffered: a line at a time was a system call for
// each of a large project's thousands of warnings. Written in pieces of
// 64 KB instead, each piece whole lines.
void printDiagnostics(const QString& path, const lang::Diagnostics& diagnostics) {
    constexpr std::size_t kPiece = 64 * 1024;
    const std::string name = path.toStdString();
    std::string piece;
    piece.reserve(kPiece + 4096);
    const auto write = [&piece] {
        std::fwrite(piece.data(), 1, piece.size(), stderr);
        piece.clear();
    };
    for (const auto& diagnostic : diagnostics) {
        piece += lang::formatDiagnostic(name, diagnostic);
        piece += '\n';
        if (piece.size() >= kPiece)
            write();
    }
    write();
}

} // namespace rs::cli
