// SPDX-License-Identifier: GPL-3.0-or-later
#include "Verbs.h"

#include "blocks/ProjectInstances.h"
#include "compiler/Compiler.h"
#include "compiler/ImageCodec.h"
#include "project/ProjectFile.h"

#include <QFileInfo>

namespace rs::cli {

int usage(const QString& message) {
    std::fprintf(stderr, "rungsmith-cli: %s\nTry 'rungsmith-cli --help'.\n", qPrintable(message));
    return UsageOrIo;
}

namespace {

// The closing line of the original tool.
int summarize(int errors, Streams streams) {
    std::fprintf(streams.out, "%d Error(s) detected Result=%s\n", errors, errors ? "FAILED" : "OK");
    return errors ? Failed : Ok;
}

} // namespace

int runCheck(const QString& path, const QStringList& libraryFiles,
             const compiler::CheckOptions& options, Streams streams) {
    LoadedProject loaded = loadProject(path, libraryFiles);
    if (loaded.status != Ok)
        return loaded.status;
    // A check makes no image, so the text it was read from is not needed
    // again: its memory goes to the checks (2.4 MB of a large project).
    std::string().swap(loaded.text);
    compiler::CompileResult result = blocks::compileProject(
        loaded.project, loaded.diagnostics, options, {}, compiler::Output::DiagnosticsOnly);
    printDiagnostics(path, result.diagnostics);
    return summarize(result.errors(), streams);
}

int runCompile(const QString& path, const QString& output, const QStringList& libraryFiles,
               const compiler::CheckOptions& options, Streams streams) {
    compiler::CompileResult result;
    {
        LoadedProject loaded = loadProject(path, libraryFiles);
        if (loaded.status != Ok)
            return loaded.status;
        result = compiled(loaded, options);
    } // the tree's memory goes to encoding the image (issue 23: 126 MB were touched, now 81)
    printDiagnostics(path, result.diagnostics);
    if (result.errors())
        return summarize(result.errors(), streams);
    QString target = output;
    if (target.isEmpty()) {
        const QFileInfo info(path);
        target = info.path() + "/" + info.completeBaseName() + ".hps";
    }
    const QString error = project::writeTextFile(
        target, [&](const project::TextSink& sink) { compiler::writeHps(result.images, sink); });
    if (!error.isEmpty()) {
        std::fprintf(streams.err, "rungsmith-cli: %s\n", qPrintable(error));
        return UsageOrIo;
    }
    return summarize(0, streams);
}

int runFormat(const QString& path, const QStringList& libraryFiles, Streams streams) {
    LoadedProject loaded = loadProject(path, libraryFiles);
    if (loaded.status != Ok)
        return loaded.status;
    printDiagnostics(path, loaded.diagnostics);
    if (!loaded.ok())
        return Failed;
    const std::string text = project::writeProject(loaded.project);
    std::fwrite(text.data(), 1, text.size(), streams.out);
    return Ok;
}

compiler::CompileResult compiled(const LoadedProject& loaded,
                                 const compiler::CheckOptions& options) {
    return blocks::compileProject(loaded.project, loaded.diagnostics, options, loaded.text);
}

} // namespace rs::cli
