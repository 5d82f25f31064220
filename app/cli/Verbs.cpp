// SPDX-License-Identifier: GPL-3.0-or-later
#include "Verbs.h"

#include "compiler/Compiler.h"
#include "compiler/ImageCodec.h"
#include "project/ProjectFile.h"

#include <QFileInfo>

namespace rs::cli {

namespace {

struct Loaded {
    std::string text;
    bool readable = false;
};

Loaded load(const QString& path, Streams streams) {
    project::FileText file = project::readTextFile(path);
    if (!file.error.isEmpty()) {
        std::fprintf(streams.err, "rungsmith-cli: %s\n", qPrintable(file.error));
        return {};
    }
    return {std::move(file.text), true};
}

void report(const QString& path, const lang::Diagnostics& diagnostics, Streams streams) {
    const std::string name = path.toStdString();
    for (const auto& diagnostic : diagnostics)
        std::fprintf(streams.err, "%s\n", lang::formatDiagnostic(name, diagnostic).c_str());
}

// The closing line of the original tool.
int summarize(int errors, Streams streams) {
    std::fprintf(streams.out, "%d Error(s) detected Result=%s\n", errors, errors ? "FAILED" : "OK");
    return errors ? Failed : Ok;
}

} // namespace

int runCheck(const QString& path, const compiler::CheckOptions& options, Streams streams) {
    Loaded loaded = load(path, streams);
    if (!loaded.readable)
        return UsageOrIo;
    compiler::CompileResult result = compiler::compileText(loaded.text, options);
    report(path, result.diagnostics, streams);
    return summarize(result.errors(), streams);
}

int runCompile(const QString& path, const QString& output, const compiler::CheckOptions& options,
               Streams streams) {
    Loaded loaded = load(path, streams);
    if (!loaded.readable)
        return UsageOrIo;
    compiler::CompileResult result = compiler::compileText(loaded.text, options);
    report(path, result.diagnostics, streams);
    if (result.errors())
        return summarize(result.errors(), streams);
    QString target = output;
    if (target.isEmpty()) {
        const QFileInfo info(path);
        target = info.path() + "/" + info.completeBaseName() + ".hps";
    }
    const QString error = project::writeTextFile(target, compiler::writeHps(result.images));
    if (!error.isEmpty()) {
        std::fprintf(streams.err, "rungsmith-cli: %s\n", qPrintable(error));
        return UsageOrIo;
    }
    return summarize(0, streams);
}

int runFormat(const QString& path, Streams streams) {
    Loaded loaded = load(path, streams);
    if (!loaded.readable)
        return UsageOrIo;
    project::ProjectReadResult result = project::readProject(loaded.text);
    report(path, result.diagnostics, streams);
    if (!result.ok())
        return Failed;
    const std::string text = project::writeProject(result.project);
    std::fwrite(text.data(), 1, text.size(), streams.out);
    return Ok;
}

} // namespace rs::cli
