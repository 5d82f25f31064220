// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Invocation.h"
#include "project/Project.h"
#include "project/ProtectionKeys.h"

#include <QString>

#include <optional>
#include <string>

// How a verb writes a project that may be password protected (cli.md): it
// reads freely, but writes only with the main password (--password-file),
// and then seals what it writes.
namespace rs::cli {

// The password in a file: its first line, without the line break. Nothing,
// with the message printed and `status` set, when it cannot be read or is empty.
std::optional<std::string> readPasswordFile(const QString& path, int& status);

// The keys to write `project` (read from `path`) back: none needed when it is
// not protected; else those --password-file opens it with, full permission.
// Nothing, with the message printed and `status` set, when the password is
// missing or does not open the project.
std::optional<project::Keyring> writingKeys(const Invocation& invocation, const QString& path,
                                            const project::Project& project, int& status);

// Writes the project's text, sealed with `keys` when it is protected.
int writeProjectFile(const QString& output, const project::Project& project,
                     const project::Keyring& keys);

} // namespace rs::cli
