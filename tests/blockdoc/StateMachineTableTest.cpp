// SPDX-License-Identifier: GPL-3.0-or-later
#include "blockdoc/StateMachineTable.h"
#include "blocks/LibraryReader.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace rs::blockdoc {
namespace {

blocks::BlockLibrary shippedLibrary(const std::string& file) {
    std::ifstream in(std::string(RUNGSMITH_LIBRARIES) + "/" + file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    const blocks::LibraryReadResult read = blocks::readLibrary(text.str());
    EXPECT_TRUE(read.ok()) << file;
    return read.library;
}

struct Row {
    std::string condition;
    std::string to;
    friend bool operator==(const Row&, const Row&) = default;
};

std::vector<Row> rowsFrom(const StateMachineTable& table, int state) {
    std::vector<Row> rows;
    for (const Transition* t : table.transitionsFrom(state))
        rows.push_back({t->condition, stateCode(t->to)});
    return rows;
}

TEST(StateMachineTable, ReadsTheTransitionsOfAStateInTheOrderTheyAreTried) {
    const blocks::BlockLibrary safety = shippedLibrary("Rungsmith_Safety.rslib");
    const StateMachineTable table = stateMachineOf(*safety.findBlock("SF_Equivalent"));
    ASSERT_FALSE(table.empty());
    // Activate off first, then 8004's own list as docs/safety-blocks.md gives it.
    const std::vector<Row> expected{{"/Activate", "16#0000"},
                                    {"elapsed", "16#C001"},
                                    {"/S_ChannelA", "16#8001"},
                                    {"S_ChannelB", "16#8000"}};
    EXPECT_EQ(rowsFrom(table, 0x8004), expected);
    const std::vector<Row> fromErrors{{"/Activate", "16#0000"},
                                      {"/S_ChannelA * /S_ChannelB", "16#8001"}};
    EXPECT_EQ(rowsFrom(table, 0xC002), fromErrors);
    EXPECT_TRUE(table.diagCodeIsState);
}

TEST(StateMachineTable, KnowsWhichOutputsEachStateSwitchesOn) {
    const blocks::BlockLibrary safety = shippedLibrary("Rungsmith_Safety.rslib");
    const StateMachineTable table = stateMachineOf(*safety.findBlock("SF_Equivalent"));
    const std::vector<std::string> outputs{"Ready", "S_EquivalentOut", "Error"};
    ASSERT_EQ(table.outputs, outputs);
    ASSERT_EQ(table.outputsOn.size(), table.states.size());
    for (std::size_t i = 0; i < table.states.size(); ++i) {
        const int state = table.states[i];
        SCOPED_TRACE(stateCode(state));
        EXPECT_EQ(table.outputsOn[i][0], state != 0);
        EXPECT_EQ(table.outputsOn[i][1], state == 0x8000);
        EXPECT_EQ(table.outputsOn[i][2], state >= 0xC001 && state <= 0xC003);
    }
    const std::vector<int> every{0x0000, 0x8001, 0x8004, 0x8014, 0x8000,
                                 0x8005, 0xC001, 0xC002, 0xC003};
    for (const int state : every)
        EXPECT_NE(std::find(table.states.begin(), table.states.end(), state), table.states.end())
            << stateCode(state);
    EXPECT_EQ(table.states.size(), every.size());
}

TEST(StateMachineTable, KeepsTheSignalsTheConditionsUse) {
    const blocks::BlockLibrary safety = shippedLibrary("Rungsmith_Safety.rslib");
    const StateMachineTable table = stateMachineOf(*safety.findBlock("SF_EmergencyStop"));
    bool edge = false;
    for (const Definition& d : table.definitions)
        edge = edge || (d.name == "resetEdge" && d.expression == "P(Reset)");
    EXPECT_TRUE(edge);
    const std::vector<Row> waiting{{"/Activate", "16#0000"},
                                   {"Reset * /resetEdge", "16#C001"},
                                   {"/S_EStopIn", "16#8002"},
                                   {"resetEdge", "16#8000"}};
    EXPECT_EQ(rowsFrom(table, 0x8003), waiting);
}

TEST(StateMachineTable, EverySafetyBlockReadsAsAStateMachine) {
    const blocks::BlockLibrary safety = shippedLibrary("Rungsmith_Safety.rslib");
    ASSERT_EQ(safety.blocks.size(), 15u);
    for (const blocks::BlockDefinition& block : safety.blocks) {
        SCOPED_TRACE(block.name);
        const StateMachineTable table = stateMachineOf(block);
        ASSERT_FALSE(table.empty());
        // Every state but 0000 is entered by some transition, and every state
        // is left by Activate off at least.
        for (const int state : table.states) {
            EXPECT_FALSE(table.transitionsFrom(state).empty()) << stateCode(state);
            if (state != 0) {
                EXPECT_TRUE(std::any_of(table.transitions.begin(), table.transitions.end(),
                                        [state](const Transition& t) { return t.to == state; }))
                    << stateCode(state);
            }
        }
        for (const Transition& t : table.transitions)
            EXPECT_EQ(t.condition.find('{'), std::string::npos) << t.condition;
    }
}

TEST(StateMachineTable, ABodyWithoutStateRegistersHasNone) {
    const blocks::BlockLibrary basics = shippedLibrary("Rungsmith_Basics.rslib");
    for (const blocks::BlockDefinition& block : basics.blocks)
        EXPECT_TRUE(stateMachineOf(block).empty()) << block.name;
    const blocks::BlockLibrary analog = shippedLibrary("Analog01.rslib");
    EXPECT_TRUE(stateMachineOf(*analog.findBlock("ReadCurrent")).empty());
}

TEST(StateMachineTable, WritesStatesAsTheirPattern) {
    EXPECT_EQ(stateCode(-32767), "16#8001");
    EXPECT_EQ(stateCode(0xC001), "16#C001");
    EXPECT_EQ(stateCode(0), "16#0000");
    EXPECT_EQ(readable("({#next} = -32767) = ({#state}=-32768) * /{S_ChannelA}"),
              "(next = -32767) = (state=16#8000) * /S_ChannelA");
    EXPECT_EQ(readable("{Ready} = ({#state}<0)"), "Ready = (state<0)");
}

} // namespace
} // namespace rs::blockdoc
