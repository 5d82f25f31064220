// SPDX-License-Identifier: GPL-3.0-or-later
#include "UserLibraryFile.h"

#include "LibraryLimits.h"
#include "LibraryReader.h"
#include "LibraryWriter.h"
#include "project/ProjectFile.h"
#include "project/SaveFileCommit.h"

#include <QFileInfo>
#include <QSaveFile>

namespace rs::blocks {

QString addBlockToLibraryFile(const QString& path, const BlockDefinition& block,
                              const std::string& newLibraryName) {
    BlockLibrary library{newLibraryName, "1.0", {"Blocks made in Rungsmith.", {}, {}}, {}};
    if (QFileInfo::exists(path)) {
        const project::FileText file = project::readTextFile(path, kMaxLibraryBytes);
        if (!file.error.isEmpty())
            return file.error;
        LibraryReadResult read = readLibrary(file.text);
        for (const auto& problem : read.diagnostics)
            if (problem.severity == lang::Severity::Error)
                return QStringLiteral("%1:%2:%3: %4")
                    .arg(path)
                    .arg(problem.line)
                    .arg(problem.column)
                    .arg(QString::fromStdString(problem.message));
        library = std::move(read.library);
        if (library.findBlock(block.name))
            return QStringLiteral("%1 already has a block %2")
                .arg(path, QString::fromStdString(block.name));
    }
    library.blocks.push_back(block);
    const std::string text = writeLibrary(library);
    if (!readLibrary(text).ok())
        return QStringLiteral("the block does not read back as a library block");
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return QStringLiteral("%1: %2").arg(path, file.errorString());
    file.write(text.data(), static_cast<qint64>(text.size()));
    return project::commitSaveFile(file);
}

} // namespace rs::blocks
