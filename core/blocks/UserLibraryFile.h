// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "BlockLibrary.h"

#include <QString>

// A user library's file in the project's folder, as Make Block… writes it.
namespace rs::blocks {

// Adds the block to the library in the file, or writes a new library named
// `newLibraryName` when there is no file yet. The file is replaced whole or
// left as it was. Returns why it could not, empty when written: the file
// does not read as a library, or already has a block of that name.
QString addBlockToLibraryFile(const QString& path, const BlockDefinition& block,
                              const std::string& newLibraryName);

} // namespace rs::blocks
