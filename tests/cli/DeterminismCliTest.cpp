// SPDX-License-Identifier: GPL-3.0-or-later
#include <QFile>
#include <QProcess>
#include <QProcessEnvironment>
#include <QTemporaryDir>

#include <gtest/gtest.h>

// The same scenario gives the same trace in every process, whether the
// simulator runs its machine code or its interpreter (RUNGSMITH_NO_JIT).

namespace {

QByteArray traceOf(const QString& vcd, bool interpreter) {
    QProcess process;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    if (interpreter)
        environment.insert(QStringLiteral("RUNGSMITH_NO_JIT"), QStringLiteral("1"));
    else
        environment.remove(QStringLiteral("RUNGSMITH_NO_JIT"));
    process.setProcessEnvironment(environment);
    process.start(QStringLiteral(RUNGSMITH_CLI),
                  {"test", QStringLiteral(RUNGSMITH_SCENARIOS "/muting.sps"),
                   QStringLiteral(RUNGSMITH_SCENARIOS "/muting_sequence.scn"), "--vcd", vcd});
    EXPECT_TRUE(process.waitForFinished(60000));
    EXPECT_EQ(process.exitCode(), 0) << process.readAllStandardError().toStdString();
    QFile file(vcd);
    EXPECT_TRUE(file.open(QIODevice::ReadOnly));
    return file.readAll();
}

} // namespace

TEST(DeterminismCli, TheSameScenarioGivesTheSameTraceInEveryProcessAndEngine) {
    QTemporaryDir dir;
    const QByteArray first = traceOf(dir.filePath("first.vcd"), false);
    ASSERT_TRUE(first.contains("$enddefinitions $end"));
    EXPECT_EQ(traceOf(dir.filePath("second.vcd"), false), first);
    EXPECT_EQ(traceOf(dir.filePath("interpreted.vcd"), true), first);
}
