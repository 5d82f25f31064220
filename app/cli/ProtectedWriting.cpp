// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProtectedWriting.h"

#include "Verbs.h"
#include "project/ProjectFile.h"
#include "project/ProtectedText.h"

#include <cstdio>

namespace rs::cli {

namespace {

// A password file holds one line; anything longer is not one.
constexpr qint64 kMaxPasswordFileBytes = 4096;

} // namespace

std::optional<std::string> readPasswordFile(const QString& path, int& status) {
    const project::FileText file = project::readTextFile(path, kMaxPasswordFileBytes);
    if (!file.error.isEmpty()) {
        std::fprintf(stderr, "rungsmith-cli: %s\n", qPrintable(file.error));
        status = UsageOrIo;
        return std::nullopt;
    }
    std::string password = file.text.substr(0, file.text.find('\n'));
    if (!password.empty() && password.back() == '\r')
        password.pop_back();
    if (password.empty()) {
        std::fprintf(stderr, "rungsmith-cli: %s: the first line, the password, is empty\n",
                     qPrintable(path));
        status = UsageOrIo;
        return std::nullopt;
    }
    return password;
}

std::optional<project::Keyring> writingKeys(const Invocation& invocation, const QString& path,
                                            const project::Project& project, int& status) {
    if (!project.protection)
        return project::Keyring{};
    const QString passwordFile = invocation.options.value(QStringLiteral("password-file"));
    if (passwordFile.isEmpty()) {
        std::fprintf(stderr,
                     "rungsmith-cli: %s is password protected; give its main password with "
                     "--password-file to write it\n",
                     qPrintable(path));
        status = Failed;
        return std::nullopt;
    }
    const auto password = readPasswordFile(passwordFile, status);
    if (!password)
        return std::nullopt;
    auto keys = project::unlock(*project.protection, project::Permission::Full, *password);
    if (!keys) {
        std::fprintf(stderr, "rungsmith-cli: %s: the password in %s is not its main password\n",
                     qPrintable(path), qPrintable(passwordFile));
        status = Failed;
    }
    return keys;
}

int writeProjectFile(const QString& output, const project::Project& project,
                     const project::Keyring& keys) {
    const QString error = project::writeTextFile(
        output, project::sealProjectText(project::writeProject(project), keys));
    if (error.isEmpty())
        return Ok;
    std::fprintf(stderr, "rungsmith-cli: %s\n", qPrintable(error));
    return UsageOrIo;
}

} // namespace rs::cli
