// SPDX-License-Identifier: GPL-3.0-or-later
// The shipped gateway libraries (docs/gateway.md): Ext01_1's ToGateway blocks
// and Ext01's Ext_Sig, Ext_Val and ExtVarBlock written as body-less ;@block
// records are expanded, compiled and run with a gateway on the bus.
#include "DiagnosticsText.h"
#include "blocks/LibraryReader.h"
#include "blocks/ProjectInstances.h"
#include "compiler/Compiler.h"
#include "gateway/GatewayNode.h"
#include "project/ProjectFile.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

using namespace rs;
using rs::test::addressOf;
using rs::test::diagnosticsText;

namespace {

blocks::LibrarySet gatewayLibraries() {
    blocks::LibrarySet set;
    for (const char* name : {"Ext01_1", "Ext01"}) {
        std::ifstream file(std::string(RUNGSMITH_LIBRARIES "/") + name + ".rslib",
                           std::ios::binary);
        std::stringstream text;
        text << file.rdbuf();
        const auto read = blocks::readLibrary(text.str());
        EXPECT_TRUE(read.ok()) << name << ": "
                               << (read.diagnostics.empty() ? "" : read.diagnostics[0].message);
        set.libraries.push_back(
            {read.library, QString::fromLatin1(name) + ".rslib", blocks::LibraryOrigin::Standard});
    }
    return set;
}

} // namespace

// Pluto 1 sends a user block to the gateway, which passes a fieldbus write
// on to Pluto 2; each block's open outputs take variables of its own.
TEST(GatewayLibraries, ABlockSendsAndAnotherReceivesThroughTheGateway) {
    const std::string text = "$name Line\n"
                             ";@gateway 0 type=\"GATE-E1\" to_pluto=\"0\"\n"
                             ";@gateway_area 0 0 pluto=\"1\" io_type=\"7\"\n"
                             "! id_pluto:01=000000000001\n"
                             "! id_pluto:02=000000000002\n"
                             "! pgm_pluto:01\n"
                             "S1.0_0\n"
                             ";@block ToGateway_User_C Send=\"I1.0\" No=\"7\" Reg_0=\"300\" "
                             "Bit_3=\"I1.1\" Q=\"M1.0\"\n"
                             ";@end\n"
                             "! pgm_pluto:02\n"
                             ";@ext_comm 02 0 gateway=\"0\" packet=\"0\"\n"
                             "S2.0_0\n"
                             ";@block Ext_Sig BlockNo=\"0\" Valid=\"M2.0\" Bit_15=\"Q2.10\"\n"
                             ";@end\n"
                             ";@block Ext_Val BlockNo=\"0\" Valid=\"M2.1\" Reg_1=\"R2.5\"\n"
                             ";@end\n";
    const auto read = blocks::readProjectWithInstances(text, gatewayLibraries());
    ASSERT_TRUE(read.read.ok()) << diagnosticsText(read.read.diagnostics);
    const compiler::CompileResult compiled =
        blocks::compileProject(read.read.project, read.read.diagnostics);
    ASSERT_EQ(compiled.errors(), 0) << diagnosticsText(compiled.diagnostics);
    sim::Simulation simulation(compiled.images);
    gateway::GatewayNode node(0, read.read.project.gateways.at(0));
    const auto scan = [&](int scans) {
        for (int i = 0; i < scans; ++i) {
            simulation.scan();
            node.exchange(simulation);
        }
    };
    simulation.set(addressOf("I1.0"), 1);
    simulation.set(addressOf("I1.1"), 1);
    scan(1);
    EXPECT_EQ(simulation.value(addressOf("M1.0")), 1);
    EXPECT_EQ(node.additionalData(0), 300u | (1u << 19)); // Reg_0, then Bit_3 at bit 16 + 3
    EXPECT_EQ(simulation.value(addressOf("M2.0")), 0);
    node.answer({1, 16, 1, 4, {0x0001, 0x8000, 0, 77}});
    scan(11);
    EXPECT_EQ(simulation.value(addressOf("M2.0")), 1);
    EXPECT_EQ(simulation.value(addressOf("Q2.10")), 1);
    EXPECT_EQ(simulation.value(addressOf("M2.1")), 1);
    EXPECT_EQ(simulation.value(addressOf("R2.5")), 77);
}
