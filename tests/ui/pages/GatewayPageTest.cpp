// SPDX-License-Identifier: GPL-3.0-or-later
// The gateway in the IDE (docs/gateway.md): New Gateway, its page, a unit's
// External Communication, and while simulating the Gateways dock and Serve
// Modbus TCP, answered for a real Modbus client (libmodbus) on loopback.
#include "WindowTest.h"

#include "DialogDriver.h"
#include "MessageBoxAnswerer.h"
#include "document/ProjectDocument.h"
#include "pages/GatewayPage.h"
#include "shell/Preferences.h"
#include "sim/GatewayView.h"
#include "sim/ModbusService.h"
#include "sim/SimulationMode.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>
#include <QTreeWidget>

#include <modbus.h>

#include <gtest/gtest.h>

namespace {

using rs::ui::PageRef;

const QByteArray kGatewayProject = "$name Line\n"
                                   "! id_pluto:00=000000000000\n"
                                   "! id_pluto:01=000000000001\n"
                                   "! pgm_pluto:00\n"
                                   "S0.0_0\n"
                                   "GM0.0 = I0.0\n"
                                   "! pgm_pluto:01\n"
                                   "S1.0_0\n"
                                   ";@system Ext_Val BlockNo=\"0\" Valid=\"GM1.0\" Reg_0=\"R1.0\" "
                                   "Reg_1=\"R1.1\"\n";

class GatewayPageTest : public WindowTest {
protected:
    void SetUp() override {
        WindowTest::SetUp();
        ASSERT_TRUE(
            window.loadFile(writeFile(QStringLiteral("line.sps"), kGatewayProject)).isEmpty());
        showWindow();
    }

    // Project > New Gateway, answered with `type` on node `node`.
    void newGateway(const QString& type, int node) {
        DialogDriver driver({[&](QDialog& dialog) {
            auto* types = dialog.findChild<QComboBox*>(QStringLiteral("newGatewayType"));
            auto* nodes = dialog.findChild<QComboBox*>(QStringLiteral("newGatewayNode"));
            types->setCurrentIndex(types->findText(type));
            nodes->setCurrentIndex(nodes->findData(node));
            QTest::mouseClick(dialog.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok),
                              Qt::LeftButton);
        }});
        action("newGatewayAction")->trigger();
        ASSERT_TRUE(driver.done());
    }

    template <typename T> T* find(const char* name) {
        T* found = window.findChild<T*>(QString::fromLatin1(name));
        EXPECT_NE(found, nullptr) << name;
        return found;
    }
};

TEST_F(GatewayPageTest, NewGatewayShowsItsPageWhoseEditsAreUndoSteps) {
    newGateway(QStringLiteral("GATE-E1"), 3);
    EXPECT_TRUE(projectText().contains(";@gateway 3 type=\"GATE-E1\"\n"));
    ASSERT_EQ(window.gatewayPage()->isVisible(), true);
    // Data to Pluto packet 1, a cycle time, an area: each one undo step.
    QTest::mouseClick(find<QCheckBox>("toPluto1"), Qt::LeftButton);
    auto* cycle = find<QSpinBox>("gatewayCycle");
    cycle->setValue(48);
    auto* pluto = find<QComboBox>("areaPluto2");
    pluto->setCurrentIndex(pluto->findData(1));
    emit pluto->activated(pluto->currentIndex());
    auto* ioType = find<QComboBox>("areaIoType2");
    ioType->setCurrentIndex(ioType->findData(101));
    emit ioType->activated(ioType->currentIndex());
    EXPECT_TRUE(projectText().contains(";@gateway 3 type=\"GATE-E1\" cycle_ms=\"48\" "
                                       "to_pluto=\"1\"\n;@gateway_area 3 2 pluto=\"1\" "
                                       "io_type=\"101\"\n"))
        << projectText().toStdString();
    // A timeout the GATE-E1 cannot take (500 ms) is not taken.
    auto* timeout = find<QSpinBox>("gatewayTimeout");
    timeout->setValue(500);
    EXPECT_EQ(timeout->value(), 0);
    EXPECT_FALSE(projectText().contains("timeout_ms"));
    for (int undo = 0; undo < 4; ++undo)
        action("undoAction")->trigger();
    EXPECT_TRUE(projectText().contains(";@gateway 3 type=\"GATE-E1\"\n"))
        << projectText().toStdString();
    action("undoAction")->trigger(); // the gateway itself
    EXPECT_FALSE(projectText().contains("@gateway"));
}

TEST_F(GatewayPageTest, AUnitsExternalCommunicationIsSetOnItsPage) {
    newGateway(QStringLiteral("GATE-P1"), 0);
    clickNode({PageRef::Kind::Unit, document(), 1});
    DialogDriver driver({[](QDialog& dialog) {
        dialog.findChild<QCheckBox*>(QStringLiteral("extBlock2"))->setChecked(true);
        dialog.findChild<QSpinBox*>(QStringLiteral("extPacket2"))->setValue(3);
        dialog.findChild<QSpinBox*>(QStringLiteral("extTimeout2"))->setValue(400);
        QTest::mouseClick(dialog.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok),
                          Qt::LeftButton);
    }});
    QTest::mouseClick(find<QPushButton>("externalCommButton"), Qt::LeftButton);
    ASSERT_TRUE(driver.done());
    EXPECT_TRUE(
        projectText().contains(";@ext_comm 01 2 gateway=\"0\" packet=\"3\" timeout_ms=\"400\"\n"))
        << projectText().toStdString();
    EXPECT_EQ(find<QLabel>("externalCommLabel")->text(),
              QStringLiteral("block 2 from gateway 0, packet 3"));
    action("undoAction")->trigger();
    EXPECT_FALSE(projectText().contains("@ext_comm"));
}

TEST_F(GatewayPageTest, WhileSimulatingAModbusClientFeedsAPlutoThroughTheServedGateway) {
    newGateway(QStringLiteral("GATE-E1"), 0);
    QTest::mouseClick(find<QCheckBox>("toPluto0"), Qt::LeftButton);
    clickNode({PageRef::Kind::Unit, document(), 1});
    DialogDriver driver({[](QDialog& dialog) {
        dialog.findChild<QCheckBox*>(QStringLiteral("extBlock0"))->setChecked(true);
        QTest::mouseClick(dialog.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok),
                          Qt::LeftButton);
    }});
    QTest::mouseClick(find<QPushButton>("externalCommButton"), Qt::LeftButton);
    ASSERT_TRUE(driver.done());

    // A free port the system picks is unknown beforehand: take one, free it, use it.
    rs::ui::Preferences preferences = rs::ui::Preferences::load();
    preferences.modbusPort = 15000 + static_cast<int>(QCoreApplication::applicationPid() % 5000);
    preferences.save();
    action("simulateAction")->trigger();
    rs::ui::SimulationMode* mode = window.simulation();
    ASSERT_TRUE(mode->session()->isActive());
    QAction* serve = mode->serveModbusAction();
    ASSERT_TRUE(serve->isEnabled());
    serve->trigger();
    ASSERT_TRUE(mode->modbusService()->isServing());

    modbus_t* client = modbus_new_tcp("127.0.0.1", preferences.modbusPort);
    ASSERT_NE(client, nullptr);
    ASSERT_EQ(modbus_connect(client), 0);
    modbus_set_slave(client, 1);
    const std::uint16_t toPluto[] = {0x0001, 0x0000, 1234, 0xFFFF};
    ASSERT_EQ(modbus_write_registers(client, 1, 4, toPluto), 4);
    QTRY_VERIFY(mode->modbusService()->clients().size() == 1);
    EXPECT_TRUE(
        find<QLabel>("modbusServing")->text().contains(QStringLiteral("clients: 127.0.0.1:")));
    // The gateway sends Data to Pluto once a cycle time (100 ms): 11 scans of 10 ms.
    for (int scan = 0; scan < 11; ++scan)
        action("simulationSingleScanAction")->trigger();
    // Pluto 1's Ext_Val got the packet: GM1.0 (Valid) is bit 20 of its global data.
    modbus_set_slave(client, 33);
    std::uint16_t pluto1[2] = {};
    ASSERT_EQ(modbus_read_registers(client, 5, 2, pluto1), 2);
    EXPECT_EQ(pluto1[0], 0x0010);
    const auto* simulation = mode->session()->simulation();
    EXPECT_EQ(simulation->value({rs::lang::AddressKind::Register, 1, 0}), 1234);
    EXPECT_EQ(simulation->value({rs::lang::AddressKind::Register, 1, 1}), -1);
    // The dock shows the gateway's data.
    QTreeWidget* tree = mode->gatewayView()->tree();
    const auto rows =
        tree->findItems(QStringLiteral("Data to Pluto 0"), Qt::MatchExactly | Qt::MatchRecursive);
    ASSERT_EQ(rows.size(), 1);
    EXPECT_EQ(rows.front()->text(rs::ui::GatewayView::BitsColumn),
              QStringLiteral("valid; register 0 = 1234, register 1 = -1"));
    modbus_close(client);
    modbus_free(client);
    // Back to editing: serving stops with the simulation.
    action("simulateAction")->trigger();
    EXPECT_FALSE(mode->modbusService()->isServing());
    EXPECT_FALSE(serve->isChecked());
}

} // namespace
