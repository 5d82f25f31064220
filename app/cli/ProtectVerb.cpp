// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProtectVerb.h"

#include "ProjectLoading.h"
#include "ProtectedWriting.h"
#include "Verbs.h"
#include "project/ProjectFile.h"
#include "project/ProtectedText.h"

#include <cstdio>

namespace rs::cli {

namespace {

std::optional<project::OptionsAccess> optionsAccess(const QString& word) {
    if (word.isEmpty() || word == QLatin1String("main"))
        return project::OptionsAccess::Main;
    if (word == QLatin1String("free"))
        return project::OptionsAccess::Free;
    if (word == QLatin1String("own"))
        return project::OptionsAccess::Own;
    return std::nullopt;
}

} // namespace

int runProtect(const Invocation& invocation) {
    const QString output = invocation.options.value(QStringLiteral("output"));
    const QString passwordFile = invocation.options.value(QStringLiteral("password-file"));
    const QString optionsFile = invocation.options.value(QStringLiteral("options-password-file"));
    const bool remove = invocation.options.isSet(QStringLiteral("remove"));
    if (invocation.arguments.size() != 1 || output.isEmpty() || passwordFile.isEmpty())
        return usage(QStringLiteral("protect takes FILE.sps, -o OUT.sps and --password-file F"));
    const auto options = optionsAccess(invocation.options.value(QStringLiteral("options")));
    if (!options)
        return usage(QStringLiteral("--options takes main, free or own"));
    if (!remove && (*options == project::OptionsAccess::Own) == optionsFile.isEmpty())
        return usage(QStringLiteral(
            "--options own takes --options-password-file, and only --options own takes it"));

    const QString path = invocation.arguments[0];
    LoadedProject loaded = loadProject(path, libraryFiles(invocation));
    if (loaded.status != Ok)
        return loaded.status;
    // A change made by hand (a merge in version control, say) is taken as the
    // password's holder's once they have looked at it and say so; the
    // password below must still open the record as it stands.
    if (invocation.options.isSet(QStringLiteral("accept-changes")))
        if (const auto tampering = project::verifyProjectText(loaded.text))
            std::erase_if(loaded.diagnostics, [&](const lang::Diagnostic& d) {
                return d.line == tampering->line && d.message == tampering->message;
            });
    printDiagnostics(path, loaded.diagnostics);
    if (!loaded.ok())
        return Failed;
    // As written: block instances stay records, as the file has them.
    project::Project project = project::readProject(loaded.text).project;

    int status = Ok;
    const auto password = readPasswordFile(passwordFile, status);
    if (!password)
        return status;
    if (!writingKeys(invocation, path, project, status))
        return status;
    if (remove) {
        if (!project.protection) {
            std::fprintf(stderr, "rungsmith-cli: %s is not password protected\n", qPrintable(path));
            return Failed;
        }
        project.protection.reset();
        return writeProjectFile(output, project, {});
    }
    std::string optionsPassword;
    if (!optionsFile.isEmpty()) {
        const auto read = readPasswordFile(optionsFile, status);
        if (!read)
            return status;
        optionsPassword = *read;
    }
    project::NewProtection fresh = project::protectWith(*password, *options, optionsPassword);
    project.protection = fresh.record;
    return writeProjectFile(output, project, fresh.keys);
}

} // namespace rs::cli
