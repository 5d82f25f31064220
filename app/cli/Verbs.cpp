#include "Verbs.h"

#include "project/ProjectFile.h"

namespace rs::cli {

namespace {

struct Loaded {
    project::ProjectReadResult result;
    bool readable = false;
};

Loaded load(const QString& path, Streams streams) {
    project::FileText file = project::readTextFile(path);
    if (!file.error.isEmpty()) {
        std::fprintf(streams.err, "rungsmith-cli: %s\n", qPrintable(file.error));
        return {};
    }
    Loaded loaded{project::readProject(file.text), true};
    const std::string name = path.toStdString();
    for (const auto& diagnostic : loaded.result.diagnostics)
        std::fprintf(streams.err, "%s\n", lang::formatDiagnostic(name, diagnostic).c_str());
    return loaded;
}

} // namespace

int runCheck(const QString& path, Streams streams) {
    Loaded loaded = load(path, streams);
    if (!loaded.readable)
        return UsageOrIo;
    const int errors = lang::errorCount(loaded.result.diagnostics);
    std::fprintf(streams.out, "%d Error(s) detected Result=%s\n", errors, errors ? "FAILED" : "OK");
    return errors ? Failed : Ok;
}

int runFormat(const QString& path, Streams streams) {
    Loaded loaded = load(path, streams);
    if (!loaded.readable)
        return UsageOrIo;
    if (!loaded.result.ok())
        return Failed;
    const std::string text = project::writeProject(loaded.result.project);
    std::fwrite(text.data(), 1, text.size(), streams.out);
    return Ok;
}

} // namespace rs::cli
