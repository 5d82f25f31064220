// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProveVerb.h"

#include "ProjectLoading.h"
#include "Verbs.h"
#include "project/ProjectFile.h"
#include "prove/Counterexample.h"
#include "prove/Prover.h"
#include "sim/Scenario.h"

#include <QDir>
#include <QFileInfo>

#include <cstdio>

namespace rs::cli {

namespace {

constexpr int kUnknown = 3; // none failed, some unknown (properties.md)
constexpr int kMaxDepth = 100'000;

} // namespace

int runProve(const Invocation& invocation) {
    if (invocation.arguments.size() != 2)
        return usage(QStringLiteral("prove takes FILE.sps and PROPS.prop"));
    const QString projectPath = invocation.arguments[0];
    const QString propertiesPath = invocation.arguments[1];
    prove::ProofOptions options;
    if (invocation.options.isSet(QStringLiteral("depth"))) {
        bool ok = false;
        options.maxDepth = invocation.options.value(QStringLiteral("depth")).toInt(&ok);
        if (!ok || options.maxDepth < 1 || options.maxDepth > kMaxDepth)
            return usage(
                QStringLiteral("--depth takes a number of scans from 1 to %1").arg(kMaxDepth));
    }
    const QString cexDir = invocation.options.isSet(QStringLiteral("cex"))
                               ? invocation.options.value(QStringLiteral("cex"))
                               : QStringLiteral(".");
    const LoadedProject loaded = loadProject(projectPath, libraryFiles(invocation));
    if (loaded.status != Ok)
        return loaded.status;
    const compiler::CompileResult compiled = rs::cli::compiled(loaded, {});
    if (compiled.errors()) {
        printDiagnostics(projectPath, compiled.diagnostics);
        std::fprintf(stdout, "%d Error(s) detected Result=FAILED\n", compiled.errors());
        return Failed;
    }
    const project::FileText text = project::readTextFile(propertiesPath);
    if (!text.error.isEmpty()) {
        std::fprintf(stderr, "rungsmith-cli: %s\n", qPrintable(text.error));
        return UsageOrIo;
    }
    const std::string fileName = QFileInfo(propertiesPath).fileName().toStdString();
    const sim::OperandNames names(loaded.project);
    const prove::PropertyFile file = prove::parseProperties(text.text, names);
    for (const auto& diagnostic : file.diagnostics)
        std::fprintf(diagnostic.severity == lang::Severity::Error ? stdout : stderr, "%s\n",
                     lang::formatDiagnostic(propertiesPath.toStdString(), diagnostic).c_str());
    if (lang::errorCount(file.diagnostics))
        return Failed;
    if (!QDir().mkpath(cexDir)) {
        std::fprintf(stderr, "rungsmith-cli: cannot make the folder %s\n", qPrintable(cexDir));
        return UsageOrIo;
    }
    int proved = 0;
    int failed = 0;
    int unknown = 0;
    const std::vector<prove::Verdict> verdicts =
        prove::proveProperties(compiled.images, file, options);
    for (const prove::Verdict& verdict : verdicts) {
        const std::string where = fileName + ":" + std::to_string(verdict.property->line) + ": ";
        std::string line;
        switch (verdict.status) {
        case prove::Verdict::Status::Proved:
            line = "proved";
            ++proved;
            break;
        case prove::Verdict::Status::Unreachable:
            line = "failed: never covered";
            ++failed;
            break;
        case prove::Verdict::Status::Unknown:
            line = "unknown: " + verdict.reason;
            ++unknown;
            break;
        case prove::Verdict::Status::Failed:
        case prove::Verdict::Status::Covered: {
            const prove::CounterexampleScenario scenario =
                prove::writeCounterexample(compiled.images, file, verdict, names, fileName);
            if (!scenario.reproduced) {
                line =
                    "unknown: internal error: the prover's " +
                    std::string(verdict.status == prove::Verdict::Status::Failed ? "counterexample"
                                                                                 : "witness") +
                    " of " + std::to_string(verdict.depth) + " scans does not replay (" +
                    scenario.problem + "); please report it";
                ++unknown;
                break;
            }
            const QString path =
                QDir(cexDir).filePath(QFileInfo(propertiesPath).completeBaseName() + "-" +
                                      QString::number(verdict.property->line) + ".scn");
            const QString error = project::writeTextFile(path, scenario.text);
            if (!error.isEmpty()) {
                std::fprintf(stderr, "rungsmith-cli: %s\n", qPrintable(error));
                return UsageOrIo;
            }
            const std::string shown = QDir::cleanPath(path).toStdString();
            if (verdict.status == prove::Verdict::Status::Failed) {
                line = "failed: counterexample of " + std::to_string(verdict.depth) + " scans in " +
                       shown;
                ++failed;
            } else {
                line = "covered in " + std::to_string(verdict.depth) + " scans: " + shown;
                ++proved;
            }
            break;
        }
        }
        std::fprintf(stdout, "%s%s\n", where.c_str(), line.c_str());
    }
    std::fprintf(stdout, "%d proved, %d failed, %d unknown\n", proved, failed, unknown);
    return failed ? Failed : unknown ? kUnknown : Ok;
}

} // namespace rs::cli
