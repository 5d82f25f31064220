// SPDX-License-Identifier: GPL-3.0-or-later
// rungsmith-cli with a PL110 program: check, format, and serve --modbus-rtu
// against the real Modbus client mbpoll on a pseudo-terminal (docs/pl110.md).
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QThread>

#include "ProgramRun.h"

#include <gtest/gtest.h>

#include <csignal>

namespace {

// Q1 shows RUN; Q2 comes on when a master writes 1234 into VW10.
const QByteArray kProgram = "$target PL110\n"
                            "$name Filling station\n"
                            "! VW10=Setpoint\n"
                            "MAIN\n"
                            "Q1 = SM0.0\n"
                            "Q2 = (Setpoint=1234)\n";

struct CliRun {
    int exitCode = -1;
    QString out;
};

class Pl110CliTest : public ::testing::Test {
protected:
    void SetUp() override { ASSERT_TRUE(directory.isValid()); }

    void TearDown() override {
        if (server.state() != QProcess::NotRunning) {
            server.kill();
            server.waitForFinished(5000);
        }
    }

    QString write(const QString& name, const QByteArray& bytes) {
        return rs::test::writeFile(directory, name, bytes);
    }

    // Standard output and error together, as a user sees them.
    static CliRun cli(const QStringList& arguments) {
        const rs::test::ProgramRun run = rs::test::runCli(arguments);
        return {run.exitCode, run.outText() + run.errText()};
    }

    // mbpoll once over RTU: -0 makes -r the datasheet's address; values after
    // the device are written.
    static QString poll(const QString& device, const QStringList& arguments,
                        const QStringList& values = {}) {
        QProcess mbpoll;
        mbpoll.start(QStringLiteral("mbpoll"),
                     QStringList{QStringLiteral("-m"), QStringLiteral("rtu"), QStringLiteral("-b"),
                                 QStringLiteral("19200"), QStringLiteral("-P"),
                                 QStringLiteral("none"), QStringLiteral("-a"), QStringLiteral("1"),
                                 QStringLiteral("-0"), QStringLiteral("-1"), QStringLiteral("-o"),
                                 QStringLiteral("2")} +
                         arguments + QStringList{device} + values);
        EXPECT_TRUE(mbpoll.waitForFinished(10000));
        return QString::fromUtf8(mbpoll.readAllStandardOutput() + mbpoll.readAllStandardError());
    }

    QTemporaryDir directory;
    QProcess server;
};

TEST_F(Pl110CliTest, CheckAndFormatReadThePl110TextForm) {
    const QString good =
        write(QStringLiteral("good.sps"), "$target pl110\nmain\nq1 = i1*/i2 ; run\n");
    CliRun run = cli({QStringLiteral("check"), good});
    EXPECT_EQ(run.exitCode, 0) << run.out.toStdString();
    EXPECT_EQ(run.out, QStringLiteral("0 Error(s) detected Result=OK\n"));
    run = cli({QStringLiteral("format"), good});
    EXPECT_EQ(run.exitCode, 0);
    EXPECT_EQ(run.out,
              QStringLiteral("$target PL110\nINIT\nMAIN\nQ1 = I1 * /I2                  ; run\n"));

    const QString bad =
        write(QStringLiteral("bad.sps"), "$target PL110\nMAIN\nI1 = Q1\nQ2 = I300\n");
    run = cli({QStringLiteral("check"), bad});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_TRUE(
        run.out.contains(bad + QStringLiteral(":3:1: error: a coil writes Q, M or B, not I1")))
        << run.out.toStdString();
    EXPECT_TRUE(
        run.out.contains(bad + QStringLiteral(":4:6: error: I300 is out of range: I1-I256")))
        << run.out.toStdString();
    EXPECT_TRUE(run.out.contains(QStringLiteral("2 Error(s) detected Result=FAILED\n")));
    run = cli({QStringLiteral("format"), bad});
    EXPECT_EQ(run.exitCode, 1); // printing would drop the bad line
}

TEST_F(Pl110CliTest, TestRunsTheExampleScenariosAndReportsAFailureByLine) {
    const QString example = QStringLiteral(RUNGSMITH_EXAMPLES "/pl110/filling-station");
    CliRun run =
        cli({QStringLiteral("test"), example + ".sps", example + ".scn", example + "-overrun.scn"});
    EXPECT_EQ(run.exitCode, 0) << run.out.toStdString();
    EXPECT_EQ(run.out, QStringLiteral("13 passed, 0 failed\n"));
    const QString wrong =
        write(QStringLiteral("wrong.scn"), "set Start 1\nscans 1\nexpect Pump 1\n");
    run = cli({QStringLiteral("test"), example + ".sps", wrong});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_EQ(run.out,
              wrong + QStringLiteral(
                          ":3: expect Pump 1 failed: got 0 at t=0.010s\n0 passed, 1 failed\n"));
    // The trace: what the scenario touches and what the program writes.
    const QString vcd = directory.filePath(QStringLiteral("t.vcd"));
    run = cli(
        {QStringLiteral("test"), example + ".sps", example + ".scn", QStringLiteral("--vcd"), vcd});
    EXPECT_EQ(run.exitCode, 0) << run.out.toStdString();
    QFile trace(vcd);
    ASSERT_TRUE(trace.open(QIODevice::ReadOnly));
    const QByteArray text = trace.readAll();
    EXPECT_TRUE(text.contains("$scope module pl110 $end")) << text.toStdString();
    EXPECT_TRUE(text.contains(" Q1 $end")) << text.toStdString();
    EXPECT_TRUE(text.contains("$var integer 32 ")) << text.toStdString(); // VW10
    EXPECT_TRUE(text.contains(" T1_value $end")) << text.toStdString();
}

TEST_F(Pl110CliTest, LadderDrawsARungAsAPicture) {
    const QString example = QStringLiteral(RUNGSMITH_EXAMPLES "/pl110/filling-station.sps");
    const QString png = directory.filePath(QStringLiteral("rung.png"));
    CliRun run = cli({QStringLiteral("ladder"), example, QStringLiteral("--network"),
                      QStringLiteral("2"), QStringLiteral("-o"), png});
    EXPECT_EQ(run.exitCode, 0) << run.out.toStdString();
    QFile picture(png);
    ASSERT_TRUE(picture.open(QIODevice::ReadOnly));
    EXPECT_TRUE(picture.read(4) == "\x89PNG");
    run = cli({QStringLiteral("ladder"), example, QStringLiteral("--network"), QStringLiteral("99"),
               QStringLiteral("-o"), png});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_TRUE(run.out.contains(QStringLiteral("the program has 9 rung(s), not 99")))
        << run.out.toStdString();
    // Live, as a scenario leaves it; its failures are printed as `test` prints them.
    const QString wrong =
        write(QStringLiteral("wrong.scn"), "set Start 1\nscans 1\nexpect Pump 1\n");
    run = cli({QStringLiteral("ladder"), example, QStringLiteral("--network"), QStringLiteral("2"),
               QStringLiteral("--scenario"), wrong, QStringLiteral("-o"), png});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_TRUE(run.out.contains(QStringLiteral(":3: expect Pump 1 failed: got 0 at t=0.010s")))
        << run.out.toStdString();
}

TEST_F(Pl110CliTest, VarsExportAndImportTheNamesAsCsv) {
    const QString program =
        write(QStringLiteral("p.sps"), "$target PL110\n! I1=Start ; green\nMAIN\nQ1 = Start\n");
    const QString csv = directory.filePath(QStringLiteral("names.csv"));
    CliRun run =
        cli({QStringLiteral("vars"), QStringLiteral("export"), program, QStringLiteral("-o"), csv});
    EXPECT_EQ(run.exitCode, 0) << run.out.toStdString();
    QFile exported(csv);
    ASSERT_TRUE(exported.open(QIODevice::ReadOnly));
    EXPECT_EQ(exported.readAll(), QByteArray("\xEF\xBB\xBFVariable,Symbolic Name,Description\r\n"
                                             "I1,Start,green\r\n"));
    const QString in =
        write(QStringLiteral("in.csv"), "I1,Go,\nQ1,Lamp,lit while running\nQ9,9x,\n");
    const QString out = directory.filePath(QStringLiteral("out.sps"));
    run = cli(
        {QStringLiteral("vars"), QStringLiteral("import"), program, in, QStringLiteral("-o"), out});
    EXPECT_EQ(run.exitCode, 1); // the bad row is reported and nothing is written
    EXPECT_TRUE(run.out.contains(in + QStringLiteral(":3:4: error: '9x' is not a name")))
        << run.out.toStdString();
    EXPECT_FALSE(QFile::exists(out));
    write(QStringLiteral("in.csv"), "I1,Go,\nQ1,Lamp,lit while running\n");
    run = cli(
        {QStringLiteral("vars"), QStringLiteral("import"), program, in, QStringLiteral("-o"), out});
    EXPECT_EQ(run.exitCode, 0) << run.out.toStdString();
    QFile result(out);
    ASSERT_TRUE(result.open(QIODevice::ReadOnly));
    EXPECT_EQ(result.readAll(),
              QByteArray("$target PL110\n! I1=Go\n! Q1=Lamp                      ; lit "
                         "while running\nINIT\nMAIN\nQ1 = Go\n"));
}

TEST_F(Pl110CliTest, VerbsForPlutoProjectsSayWhatTheFileIs) {
    const QString example = QStringLiteral(RUNGSMITH_EXAMPLES "/pl110/filling-station.sps");
    for (const QStringList& arguments :
         {QStringList{QStringLiteral("compile"), example},
          QStringList{QStringLiteral("prove"), example, QStringLiteral("station.prop")},
          QStringList{QStringLiteral("diff"), QStringLiteral(RUNGSMITH_EXAMPLES "/estop.sps"),
                      example}}) {
        const CliRun run = cli(arguments);
        EXPECT_EQ(run.exitCode, 2) << run.out.toStdString();
        EXPECT_TRUE(run.out.contains(arguments.front() + QStringLiteral(" takes Pluto projects; ") +
                                     example + QStringLiteral(" is a PL110 program")))
            << run.out.toStdString();
    }
}

TEST_F(Pl110CliTest, MbpollReadsTheOutputsAndWritesAVariableOverRtu) {
    if (QStandardPaths::findExecutable(QStringLiteral("mbpoll")).isEmpty())
        GTEST_SKIP() << "mbpoll is not installed (scripts/dev installs it)";
    server.start(QStringLiteral(RUNGSMITH_CLI),
                 {QStringLiteral("serve"), write(QStringLiteral("station.sps"), kProgram),
                  QStringLiteral("--modbus-rtu")});
    ASSERT_TRUE(server.waitForStarted(5000));
    QElapsedTimer waited;
    waited.start();
    while (!server.canReadLine() && waited.elapsed() < 10000)
        server.waitForReadyRead(200);
    const QString first = QString::fromUtf8(server.readLine());
    const auto match =
        QRegularExpression(QStringLiteral("^serving Modbus RTU on (/dev/\\S+) as slave 1$"))
            .match(first.trimmed());
    ASSERT_TRUE(match.hasMatch()) << first.toStdString();
    const QString device = match.captured(1);

    const QStringList outputs = {QStringLiteral("-t"),   QStringLiteral("0"),  QStringLiteral("-r"),
                                 QStringLiteral("2400"), QStringLiteral("-c"), QStringLiteral("2")};
    QString answer = poll(device, outputs);
    EXPECT_TRUE(answer.contains(QStringLiteral("[2400]: \t1"))) << answer.toStdString();
    EXPECT_TRUE(answer.contains(QStringLiteral("[2401]: \t0"))) << answer.toStdString();

    const QString written = poll(
        device,
        {QStringLiteral("-t"), QStringLiteral("4"), QStringLiteral("-r"), QStringLiteral("2010")},
        {QStringLiteral("1234")});
    EXPECT_TRUE(written.contains(QStringLiteral("Written 1 references"))) << written.toStdString();
    waited.restart();
    while (waited.elapsed() < 5000) {
        answer = poll(device, outputs);
        if (answer.contains(QStringLiteral("[2401]: \t1")))
            break;
        QThread::msleep(50);
    }
    EXPECT_TRUE(answer.contains(QStringLiteral("[2401]: \t1"))) << answer.toStdString();
    const QString back = poll(device, {QStringLiteral("-t"), QStringLiteral("4"),
                                       QStringLiteral("-r"), QStringLiteral("2010")});
    EXPECT_TRUE(back.contains(QStringLiteral("[2010]: \t1234"))) << back.toStdString();
    // What the map does not allow is a Modbus exception, and the server goes on.
    const QString refused = poll(device, {QStringLiteral("-t"), QStringLiteral("4"),
                                          QStringLiteral("-r"), QStringLiteral("6")});
    EXPECT_TRUE(refused.contains(QStringLiteral("Illegal data address"))) << refused.toStdString();

    ::kill(static_cast<pid_t>(server.processId()), SIGTERM);
    ASSERT_TRUE(server.waitForFinished(10000));
    EXPECT_EQ(server.exitCode(), 0);
    EXPECT_TRUE(server.readAll().contains("stopped"));
}

TEST_F(Pl110CliTest, AScenarioDrivesTheInputsTheRtuClientSees) {
    if (QStandardPaths::findExecutable(QStringLiteral("mbpoll")).isEmpty())
        GTEST_SKIP() << "mbpoll is not installed (scripts/dev installs it)";
    const QString program =
        write(QStringLiteral("relay.sps"), "$target PL110\nMAIN\nQ1 = I1\nQ2 = I2\n");
    // I1 comes on at once; I2 only after a minute of the simulated clock.
    const QString scenario =
        write(QStringLiteral("drive.scn"), "set I1 1\nrun 60s\nset I2 1\nrun 1s\nexpect Q2 1\n");
    server.start(QStringLiteral(RUNGSMITH_CLI),
                 {QStringLiteral("serve"), program, QStringLiteral("--modbus-rtu"),
                  QStringLiteral("--scenario"), scenario});
    ASSERT_TRUE(server.waitForStarted(5000));
    QElapsedTimer waited;
    waited.start();
    while (!server.canReadLine() && waited.elapsed() < 10000)
        server.waitForReadyRead(200);
    const auto match =
        QRegularExpression(QStringLiteral("^serving Modbus RTU on (/dev/\\S+) as slave 1$"))
            .match(QString::fromUtf8(server.readLine()).trimmed());
    ASSERT_TRUE(match.hasMatch());
    const QStringList outputs = {QStringLiteral("-t"),   QStringLiteral("0"),  QStringLiteral("-r"),
                                 QStringLiteral("2400"), QStringLiteral("-c"), QStringLiteral("2")};
    QString answer;
    waited.restart();
    while (waited.elapsed() < 5000) {
        answer = poll(match.captured(1), outputs);
        if (answer.contains(QStringLiteral("[2400]: \t1")))
            break;
        QThread::msleep(50);
    }
    EXPECT_TRUE(answer.contains(QStringLiteral("[2400]: \t1"))) << answer.toStdString();
    EXPECT_TRUE(answer.contains(QStringLiteral("[2401]: \t0"))) << answer.toStdString();
    // Stopped in the middle of the scenario's minute: it ends at once.
    ::kill(static_cast<pid_t>(server.processId()), SIGTERM);
    ASSERT_TRUE(server.waitForFinished(10000));
    EXPECT_EQ(server.exitCode(), 0);
    EXPECT_TRUE(server.readAll().contains("stopped"));
}

TEST_F(Pl110CliTest, AScenarioWithErrorsIsNotServed) {
    const QString program = write(QStringLiteral("relay.sps"), "$target PL110\nMAIN\nQ1 = I1\n");
    const QString scenario = write(QStringLiteral("bad.scn"), "set I0 1\n");
    server.start(QStringLiteral(RUNGSMITH_CLI),
                 {QStringLiteral("serve"), program, QStringLiteral("--modbus-rtu"),
                  QStringLiteral("--scenario"), scenario});
    ASSERT_TRUE(server.waitForFinished(10000));
    EXPECT_EQ(server.exitCode(), 1);
    EXPECT_TRUE(server.readAllStandardError().contains("bad.scn:1:5: error:"));
}

} // namespace
