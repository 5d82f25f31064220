// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QString>
#include <QStringList>

class QTemporaryDir;

namespace rs::test {

// What a program run by a test did.
struct ProgramRun {
    bool crashed = true; // killed by a signal, or not finished in time
    int exitCode = -1;   // -1 when crashed
    QByteArray out;
    QByteArray err;

    QString outText() const { return QString::fromUtf8(out); }
    QString errText() const { return QString::fromUtf8(err); }
};

struct RunOptions {
    QString standardOutputFile; // instead of capturing standard output
    int timeoutMs = 120'000;
};

// Runs `program` and waits for it; a run that does not finish in time is
// killed and counts as crashed.
ProgramRun runProgram(const QString& program, const QStringList& arguments,
                      const RunOptions& options = {});

// rungsmith-cli of this build.
ProgramRun runCli(const QStringList& arguments, const RunOptions& options = {});

// Writes `bytes` to `name` in `dir` (a failure fails the test) and returns its path.
QString writeFile(const QTemporaryDir& dir, const QString& name, const QByteArray& bytes);

// The file's bytes; empty, and the test failed, when it cannot be read.
QByteArray readFile(const QString& path);

} // namespace rs::test
