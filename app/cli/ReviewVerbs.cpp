// SPDX-License-Identifier: GPL-3.0-or-later
#include "ReviewVerbs.h"

#include "Drawing.h"
#include "ProtectedWriting.h"
#include "ReviewPages.h"
#include "Verbs.h"
#include "compiler/ImageCodec.h"
#include "compiler/Signature.h"
#include "project/ProjectFile.h"
#include "review/ProjectDiff.h"
#include "review/Validation.h"

#include <QDate>

#include <algorithm>
#include <cstdio>

namespace rs::cli {

namespace {

compiler::CheckOptions checkOptions(const Invocation& invocation) {
    compiler::CheckOptions options;
    options.warnUnconfiguredIo = !invocation.options.isSet(QStringLiteral("no-io-warnings"));
    return options;
}

void printSignatures(const std::vector<compiler::UnitSignature>& units, std::uint32_t project) {
    for (const auto& unit : units)
        std::printf("Pluto %02d %s\n", unit.station, compiler::signatureText(unit.value).c_str());
    std::printf("project %s\n", compiler::signatureText(project).c_str());
}

int imageSignature(const QString& path) {
    const project::FileText file = project::readTextFile(path);
    if (!file.error.isEmpty()) {
        std::fprintf(stderr, "rungsmith-cli: %s\n", qPrintable(file.error));
        return UsageOrIo;
    }
    const compiler::HpsResult read = compiler::readHps(file.text);
    if (const auto* error = std::get_if<compiler::ImageError>(&read)) {
        // A fault in the bytes themselves has no place in the text: the
        // file's start stands for it.
        std::fprintf(stderr, "%s:%d:%d: error: %s\n", qPrintable(path), std::max(error->line, 1),
                     std::max(error->column, 1), error->message.c_str());
        return Failed;
    }
    const auto& images = std::get<std::vector<compiler::UnitImage>>(read);
    std::vector<compiler::UnitSignature> units;
    for (const auto& image : images)
        units.push_back({image.station, compiler::unitSignature(image)});
    // Units without code have no image; the project figure the compiler
    // stored covers them too.
    printSignatures(units, images.front().projectSignature);
    return Ok;
}

} // namespace

int runSignature(const Invocation& invocation) {
    if (invocation.arguments.size() != 1)
        return usage(QStringLiteral("signature takes exactly one FILE.sps or FILE.hps"));
    const QString path = invocation.arguments[0];
    if (path.endsWith(QStringLiteral(".hps"), Qt::CaseInsensitive))
        return imageSignature(path);
    LoadedProject loaded = loadProject(path, libraryFiles(invocation));
    if (loaded.status != Ok)
        return loaded.status;
    const compiler::CompileResult result = compiled(loaded, checkOptions(invocation));
    printDiagnostics(path, result.diagnostics);
    if (result.errors())
        return Failed;
    printSignatures(result.signatures, result.projectSignature);
    return Ok;
}

int runDiff(const Invocation& invocation) {
    if (invocation.arguments.size() != 2)
        return usage(QStringLiteral("diff takes OLD.sps and NEW.sps"));
    const QString oldPath = invocation.arguments[0];
    const QString newPath = invocation.arguments[1];
    const LoadedProject before = loadProject(oldPath, libraryFiles(invocation));
    if (before.status != Ok)
        return before.status;
    const LoadedProject after = loadProject(newPath, libraryFiles(invocation));
    if (after.status != Ok)
        return after.status;
    const compiler::CompileResult oldCompiled = compiled(before, checkOptions(invocation));
    const compiler::CompileResult newCompiled = compiled(after, checkOptions(invocation));
    printDiagnostics(oldPath, oldCompiled.diagnostics);
    printDiagnostics(newPath, newCompiled.diagnostics);
    // Without both signatures nothing can be said about the behaviour, and a
    // reviewer must not read silence as "no change".
    bool errors = false;
    for (const auto& [path, result] :
         {std::pair{oldPath, oldCompiled.errors()}, std::pair{newPath, newCompiled.errors()}})
        if (result) {
            std::fprintf(stderr,
                         "rungsmith-cli: %s has errors, so its behaviour cannot be compared\n",
                         qPrintable(path));
            errors = true;
        }
    if (errors)
        return Failed;
    const review::ProjectDiff diff =
        review::diffProjects(before.project, oldCompiled, after.project, newCompiled);
    for (const std::string& line : diff.lines())
        std::printf("%s\n", line.c_str());
    if (const QString pdf = invocation.options.value(QStringLiteral("pdf")); !pdf.isEmpty()) {
        const QString error = drawing().writeReviewPdf(
            pdf, render::reviewPages({oldPath, before.project, before.places, oldCompiled},
                                     {newPath, after.project, after.places, newCompiled}, diff,
                                     QStringLiteral("rungsmith-cli")));
        if (!error.isEmpty()) {
            std::fprintf(stderr, "rungsmith-cli: %s\n", qPrintable(error));
            return UsageOrIo;
        }
    }
    return diff.behaviourChanged() ? Failed : Ok;
}

int runValidate(const Invocation& invocation) {
    const QString by = invocation.options.value(QStringLiteral("by"));
    const QString output = invocation.options.value(QStringLiteral("output"));
    if (invocation.arguments.size() != 1 || by.trimmed().isEmpty() || output.isEmpty())
        return usage(QStringLiteral("validate takes FILE.sps, --by NAME and -o OUT.sps"));
    QDate date = QDate::currentDate();
    if (invocation.options.isSet(QStringLiteral("date"))) {
        date = QDate::fromString(invocation.options.value(QStringLiteral("date")), Qt::ISODate);
        if (!date.isValid())
            return usage(QStringLiteral("--date takes a date as YYYY-MM-DD"));
    }
    const QString path = invocation.arguments[0];
    const LoadedProject loaded = loadProject(path, libraryFiles(invocation));
    if (loaded.status != Ok)
        return loaded.status;
    const compiler::CompileResult result = compiled(loaded, checkOptions(invocation));
    printDiagnostics(path, result.diagnostics);
    if (result.errors())
        return Failed;
    // The file keeps its block instances as written; the baseline is of the
    // project they expand to, which is what `review` compares with.
    project::ProjectReadResult written = project::readProject(loaded.text);
    int status = Ok;
    const auto keys = writingKeys(invocation, path, written.project, status);
    if (!keys)
        return status;
    written.project.baseline = review::validatedBaseline(
        loaded.project, result, date.toString(Qt::ISODate).toStdString(), by.toStdString(),
        invocation.options.value(QStringLiteral("comment")).toStdString());
    return writeProjectFile(output, written.project, *keys);
}

int runReview(const Invocation& invocation) {
    if (invocation.arguments.size() != 1)
        return usage(QStringLiteral("review takes exactly one FILE.sps"));
    const QString path = invocation.arguments[0];
    const LoadedProject loaded = loadProject(path, libraryFiles(invocation));
    if (loaded.status != Ok)
        return loaded.status;
    const compiler::CompileResult result = compiled(loaded, checkOptions(invocation));
    printDiagnostics(path, result.diagnostics);
    if (result.errors()) {
        std::fprintf(stderr, "rungsmith-cli: %s has errors, so its behaviour cannot be compared\n",
                     qPrintable(path));
        return Failed;
    }
    if (!loaded.project.baseline) {
        std::fprintf(stderr,
                     "rungsmith-cli: %s has not been validated (it has no ;@validated record); "
                     "mark it with rungsmith-cli validate\n",
                     qPrintable(path));
        return Failed;
    }
    const project::Baseline& baseline = *loaded.project.baseline;
    std::printf("validated on %s by %s%s%s\n", lang::visibleText(baseline.date).c_str(),
                lang::visibleText(baseline.by).c_str(), baseline.comment.empty() ? "" : ": ",
                lang::visibleText(baseline.comment).c_str());
    const review::ProjectDiff diff = review::changesSinceValidation(loaded.project, result);
    for (const std::string& line : diff.lines())
        std::printf("%s\n", line.c_str());
    return diff.behaviourChanged() ? Failed : Ok;
}

} // namespace rs::cli
