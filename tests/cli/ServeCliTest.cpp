// SPDX-License-Identifier: GPL-3.0-or-later
// rungsmith-cli serve against the real Modbus client mbpoll, on loopback
// (issue 20; docs/gateway.md).
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QThread>

#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <csignal>

namespace {

const QByteArray kServeProject = "$name Gateway line\n"
                                 ";@gateway 0 type=\"GATE-E1\"\n"
                                 "! id_pluto:00=000000000000\n"
                                 "! id_pluto:01=000000000001\n"
                                 "! type_pluto:00=A20,is3\n"
                                 "! type_pluto:01=A20,is3\n"
                                 "! pgm_pluto:00\n"
                                 "! I0.0,static\n"
                                 "S0.0_0\n"
                                 "GM0.0 = I0.0\n"
                                 "! pgm_pluto:01\n"
                                 "S1.0_0\n";

// The inputs come on after 200 ms of simulated time.
const QByteArray kScenario = "run 200ms\nset I0.0 1\nrun 100ms\nexpect GM0.0 1\n";

// A plain TCP connection to the server on loopback; -1 when refused.
int connectTo(int port) {
    const int s = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<std::uint16_t>(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(s, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
        ::close(s);
        return -1;
    }
    return s;
}

void send(int s, const QByteArray& bytes) {
    ASSERT_EQ(::send(s, bytes.data(), static_cast<std::size_t>(bytes.size()), 0), bytes.size());
}

class ServeCliTest : public ::testing::Test {
protected:
    void SetUp() override {
        if (QStandardPaths::findExecutable(QStringLiteral("mbpoll")).isEmpty())
            GTEST_SKIP() << "mbpoll is not installed (scripts/dev installs it)";
        ASSERT_TRUE(directory.isValid());
        write(QStringLiteral("line.sps"), kServeProject);
        write(QStringLiteral("line.scn"), kScenario);
    }

    void TearDown() override {
        if (server.state() != QProcess::NotRunning) {
            server.kill();
            server.waitForFinished(5000);
        }
    }

    void write(const QString& name, const QByteArray& bytes) {
        QFile file(directory.filePath(name));
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        file.write(bytes);
    }

    // Starts the server on a port the system picks; the port it listens on.
    int start(const QStringList& extra = {}) {
        server.setProcessChannelMode(QProcess::SeparateChannels);
        server.start(QStringLiteral(RUNGSMITH_CLI),
                     QStringList{QStringLiteral("serve"), directory.filePath("line.sps"),
                                 QStringLiteral("--modbus"), QStringLiteral("127.0.0.1:0")} +
                         extra);
        EXPECT_TRUE(server.waitForStarted(5000));
        QElapsedTimer waited;
        waited.start();
        while (!server.canReadLine() && waited.elapsed() < 10000)
            server.waitForReadyRead(200);
        const QString first = QString::fromUtf8(server.readLine());
        const auto match =
            QRegularExpression(QStringLiteral(":(\\d+) for gateway 0 \\(GATE-E1\\)")).match(first);
        EXPECT_TRUE(match.hasMatch()) << first.toStdString();
        return match.captured(1).toInt();
    }

    // mbpoll once, as the research notes' recipes: -0 makes -r the manual's address.
    // Values after the host are written (function 16 for several).
    QString poll(int port, const QStringList& arguments, const QStringList& values = {}) {
        QProcess mbpoll;
        mbpoll.start(QStringLiteral("mbpoll"),
                     QStringList{QStringLiteral("-m"), QStringLiteral("tcp"), QStringLiteral("-p"),
                                 QString::number(port), QStringLiteral("-0"), QStringLiteral("-1"),
                                 QStringLiteral("-o"), QStringLiteral("2")} +
                         arguments + QStringList{QStringLiteral("127.0.0.1")} + values);
        EXPECT_TRUE(mbpoll.waitForFinished(10000));
        return QString::fromUtf8(mbpoll.readAllStandardOutput() + mbpoll.readAllStandardError());
    }

    int stop() {
        ::kill(static_cast<pid_t>(server.processId()), SIGTERM);
        EXPECT_TRUE(server.waitForFinished(10000));
        return server.exitCode();
    }

    QTemporaryDir directory;
    QProcess server;
};

TEST_F(ServeCliTest, MbpollReadsNodeStatusAndGlobalDataWhileAScenarioDrivesTheInputs) {
    const int port = start({QStringLiteral("--scenario"), directory.filePath("line.scn")});
    ASSERT_GT(port, 0);
    const QStringList nodeAndPluto0 = {
        QStringLiteral("-a"), QStringLiteral("33"), QStringLiteral("-r"), QStringLiteral("1"),
        QStringLiteral("-c"), QStringLiteral("4"),  QStringLiteral("-t"), QStringLiteral("4:hex")};
    // Node status: Plutos 0 and 1 in register 2.
    EXPECT_TRUE(poll(port, nodeAndPluto0).contains(QStringLiteral("[2]: \t0x0003")));
    // I0.0 and GM0.0 come on once the scenario sets the input.
    QElapsedTimer waited;
    waited.start();
    QString answer;
    while (waited.elapsed() < 10000) {
        answer = poll(port, nodeAndPluto0);
        if (answer.contains(QStringLiteral("[4]: \t0x0001")))
            break;
        QThread::msleep(100);
    }
    EXPECT_TRUE(answer.contains(QStringLiteral("[3]: \t0x0010"))) << answer.toStdString();
    EXPECT_TRUE(answer.contains(QStringLiteral("[4]: \t0x0001"))) << answer.toStdString();
    // What the manual does not allow is a Modbus exception, and the server goes on.
    EXPECT_TRUE(poll(port, {QStringLiteral("-a"), QStringLiteral("33"), QStringLiteral("-r"),
                            QStringLiteral("0"), QStringLiteral("-c"), QStringLiteral("2")})
                    .contains(QStringLiteral("Illegal data address")));
    EXPECT_TRUE(poll(port, {QStringLiteral("-a"), QStringLiteral("33"), QStringLiteral("-r"),
                            QStringLiteral("1"), QStringLiteral("-c"), QStringLiteral("101")})
                    .contains(QStringLiteral("Illegal data value")));
    // Data to Pluto (unit 1): written with function 16, as mbpoll does for several values.
    const QString written =
        poll(port,
             {QStringLiteral("-a"), QStringLiteral("1"), QStringLiteral("-r"), QStringLiteral("0")},
             {QStringLiteral("13"), QStringLiteral("3"), QStringLiteral("255"),
              QStringLiteral("100"), QStringLiteral("200")});
    EXPECT_TRUE(written.contains(QStringLiteral("Written 5 references"))) << written.toStdString();
    const QString back =
        poll(port, {QStringLiteral("-a"), QStringLiteral("1"), QStringLiteral("-r"),
                    QStringLiteral("0"), QStringLiteral("-c"), QStringLiteral("5")});
    EXPECT_TRUE(back.contains(QStringLiteral("[1]: \t3")) &&
                back.contains(QStringLiteral("[4]: \t200")))
        << back.toStdString();
    EXPECT_EQ(stop(), 0);
    const QString log = QString::fromUtf8(server.readAllStandardOutput());
    EXPECT_TRUE(log.contains(QStringLiteral(" connected\n")));
    EXPECT_TRUE(log.endsWith(QStringLiteral("stopped\n"))) << log.toStdString();
}

// The gateway's other data: an additional data area configured through unit 4
// takes Pluto 0's ToGateway_User_A block; Data to Pluto reaches Pluto 1's
// Ext_Sig, whose outputs come back in its global data (Valid GM1.0, bit 0
// Q1.1); a local data request reads a register.
TEST_F(ServeCliTest, MbpollReadsAdditionalDataFeedsAPlutoAndAsksForLocalData) {
    write(QStringLiteral("line.sps"),
          "$name Gateway line\n"
          ";@gateway 0 type=\"GATE-E1\" to_pluto=\"0\" cycle_ms=\"20\"\n"
          "! id_pluto:00=000000000000\n"
          "! id_pluto:01=000000000001\n"
          "! pgm_pluto:00\n"
          "S0.0_0\n"
          "M0.1 = /M0.99\n"
          "(R0.10 = 4660) = M0.1\n"
          ";@system ToGateway_User_A No=\"12\" Send=\"M0.1\" Reg_0=\"R0.10\" Reg_1=\"7\" "
          "Q=\"M0.2\"\n"
          "! pgm_pluto:01\n"
          ";@ext_comm 01 0 gateway=\"0\" packet=\"0\"\n"
          "S1.0_0\n"
          ";@system Ext_Sig BlockNo=\"0\" Valid=\"GM1.0\" Bit_0=\"Q1.1\" Bit_1=\"M1.1\" "
          "Bit_2=\"M1.2\" Bit_3=\"M1.3\" Bit_4=\"M1.4\" Bit_5=\"M1.5\" Bit_6=\"M1.6\" "
          "Bit_7=\"M1.7\" Bit_8=\"M1.8\" Bit_9=\"M1.9\" Bit_10=\"M1.10\" Bit_11=\"M1.11\" "
          "Bit_12=\"M1.12\" Bit_13=\"M1.13\" Bit_14=\"M1.14\" Bit_15=\"M1.15\"\n");
    const int port = start();
    ASSERT_GT(port, 0);
    const auto until = [&](const QStringList& arguments, const QString& wanted) {
        QElapsedTimer waited;
        waited.start();
        QString answer;
        while (waited.elapsed() < 10000 && !(answer = poll(port, arguments)).contains(wanted))
            QThread::msleep(50);
        return answer;
    };
    // Additional Data 0 is not used until unit 4 gives it Pluto 0 (high
    // byte) and the user block's number 12 (low byte).
    EXPECT_TRUE(poll(port, {QStringLiteral("-a"), QStringLiteral("33"), QStringLiteral("-r"),
                            QStringLiteral("67"), QStringLiteral("-c"), QStringLiteral("2")})
                    .contains(QStringLiteral("[68]: \t0")));
    EXPECT_TRUE(
        poll(port,
             {QStringLiteral("-a"), QStringLiteral("4"), QStringLiteral("-r"), QStringLiteral("5")},
             {QStringLiteral("12"), QStringLiteral("0")})
            .contains(QStringLiteral("Written 2 references")));
    // Additional Data 0 at 67 (MSW: Reg_1) and 68 (LSW: Reg_0).
    const QString additional = until(
        {QStringLiteral("-a"), QStringLiteral("33"), QStringLiteral("-r"), QStringLiteral("67"),
         QStringLiteral("-c"), QStringLiteral("2"), QStringLiteral("-t"), QStringLiteral("4:hex")},
        QStringLiteral("[68]: \t0x1234"));
    EXPECT_TRUE(additional.contains(QStringLiteral("[67]: \t0x0007")) &&
                additional.contains(QStringLiteral("[68]: \t0x1234")))
        << additional.toStdString();
    // Area 0 valid with bit 0 set: Pluto 1's Ext_Sig sets GM1.0 (bit 4 of its
    // MSW, register 5) and Q1.1 (bit 1).
    EXPECT_TRUE(
        poll(port,
             {QStringLiteral("-a"), QStringLiteral("1"), QStringLiteral("-r"), QStringLiteral("1")},
             {QStringLiteral("1"), QStringLiteral("1")})
            .contains(QStringLiteral("Written 2 references")));
    const QString pluto1 =
        until({QStringLiteral("-a"), QStringLiteral("33"), QStringLiteral("-r"),
               QStringLiteral("5"), QStringLiteral("-t"), QStringLiteral("4:hex")},
              QStringLiteral("[5]: \t0x0012"));
    EXPECT_TRUE(pluto1.contains(QStringLiteral("[5]: \t0x0012"))) << pluto1.toStdString();
    // R10 of Pluto 0 is local register address 110: flag 3, then 6 with the value.
    EXPECT_TRUE(
        poll(port,
             {QStringLiteral("-a"), QStringLiteral("2"), QStringLiteral("-r"), QStringLiteral("0")},
             {QStringLiteral("3"), QStringLiteral("0"), QStringLiteral("2"), QStringLiteral("110")})
            .contains(QStringLiteral("Written 4 references")));
    const QString response =
        until({QStringLiteral("-a"), QStringLiteral("34"), QStringLiteral("-r"),
               QStringLiteral("0"), QStringLiteral("-c"), QStringLiteral("7")},
              QStringLiteral("[0]: \t6"));
    EXPECT_TRUE(response.contains(QStringLiteral("[4]: \t1")) &&
                response.contains(QStringLiteral("[6]: \t4660")))
        << response.toStdString();
    // Unit 4 is write only; a cycle time below 4 ms is refused.
    EXPECT_TRUE(poll(port, {QStringLiteral("-a"), QStringLiteral("4"), QStringLiteral("-r"),
                            QStringLiteral("37")})
                    .contains(QStringLiteral("Illegal function")));
    EXPECT_TRUE(poll(port,
                     {QStringLiteral("-a"), QStringLiteral("4"), QStringLiteral("-r"),
                      QStringLiteral("37")},
                     {QStringLiteral("2"), QStringLiteral("0")})
                    .contains(QStringLiteral("Illegal data value")));
    EXPECT_EQ(stop(), 0);
}

TEST_F(ServeCliTest, AThousandDroppedConnectionsAndGarbageLeaveItAnswering) {
    const int port = start();
    ASSERT_GT(port, 0);
    for (int i = 0; i < 1000; ++i) {
        const int socket = connectTo(port);
        ASSERT_GE(socket, 0) << i;
        if (i % 100 == 0) // a malformed frame: a length the header cannot have
            send(socket, QByteArray::fromHex("0001000000ff21030001000200ff"));
        ::close(socket);
    }
    const int stalled = connectTo(port); // half a frame, then nothing
    ASSERT_GE(stalled, 0);
    send(stalled, QByteArray::fromHex("000100000006"));
    EXPECT_TRUE(poll(port, {QStringLiteral("-a"), QStringLiteral("33"), QStringLiteral("-r"),
                            QStringLiteral("1"), QStringLiteral("-c"), QStringLiteral("2"),
                            QStringLiteral("-t"), QStringLiteral("4:hex")})
                    .contains(QStringLiteral("[2]: \t0x0003")));
    ::close(stalled);
    EXPECT_EQ(stop(), 0);
}

TEST_F(ServeCliTest, AProjectWithoutAnEthernetGatewayIsRefused) {
    write(QStringLiteral("plain.sps"), "! id_pluto:00=000000000000\n! pgm_pluto:00\nS0.0_0\n");
    QProcess plain;
    plain.start(QStringLiteral(RUNGSMITH_CLI),
                {QStringLiteral("serve"), directory.filePath("plain.sps")});
    ASSERT_TRUE(plain.waitForFinished(10000));
    EXPECT_EQ(plain.exitCode(), 2);
    EXPECT_TRUE(plain.readAllStandardError().contains("has no Ethernet gateway"));
}

} // namespace
