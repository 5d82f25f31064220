// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProgramRun.h"

#include <QFile>
#include <QProcess>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace rs::test {

ProgramRun runProgram(const QString& program, const QStringList& arguments,
                      const RunOptions& options) {
    QProcess process;
    if (!options.standardOutputFile.isEmpty())
        process.setStandardOutputFile(options.standardOutputFile);
    process.start(program, arguments);
    ProgramRun run;
    if (!process.waitForFinished(options.timeoutMs)) {
        ADD_FAILURE() << program.toStdString() << " did not finish in " << options.timeoutMs / 1000
                      << " s";
        process.kill();
        process.waitForFinished();
    } else {
        run.crashed = process.exitStatus() != QProcess::NormalExit;
        run.exitCode = run.crashed ? -1 : process.exitCode();
    }
    run.out = process.readAllStandardOutput();
    run.err = process.readAllStandardError();
    return run;
}

ProgramRun runCli(const QStringList& arguments, const RunOptions& options) {
    return runProgram(QStringLiteral(RUNGSMITH_CLI), arguments, options);
}

QString writeFile(const QTemporaryDir& dir, const QString& name, const QByteArray& bytes) {
    QFile file(dir.filePath(name));
    EXPECT_TRUE(file.open(QIODevice::WriteOnly)) << file.fileName().toStdString();
    EXPECT_EQ(file.write(bytes), bytes.size());
    return file.fileName();
}

QByteArray readFile(const QString& path) {
    QFile file(path);
    EXPECT_TRUE(file.open(QIODevice::ReadOnly)) << path.toStdString();
    return file.readAll();
}

} // namespace rs::test
