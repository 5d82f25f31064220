// SPDX-License-Identifier: GPL-3.0-or-later
#include "blocks/LibraryReader.h"
#include "blocks/LibraryWords.h"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

// Every block of Rungsmith_Safety documents each state its body can enter,
// and no other, in the three languages: the `state` records are what the
// block's page shows for a DiagCode, so one missing is a code the user
// cannot look up.

using namespace rs::blocks;

namespace {

BlockLibrary readSafetyLibrary() {
    std::ifstream file(RUNGSMITH_LIBRARIES "/Rungsmith_Safety.rslib", std::ios::binary);
    std::stringstream text;
    text << file.rdbuf();
    LibraryReadResult read = readLibrary(text.str());
    EXPECT_TRUE(read.ok());
    return std::move(read.library);
}

// The codes a body assigns to {#next} or compares {#state} with, as 16-bit
// patterns (the register is signed: -32767 is 16#8001).
std::set<std::string> bodyStates(const BlockDefinition& block) {
    static const std::regex kState(R"(\{#(next|state)\}\s*=\s*(-?[0-9]+)\))");
    std::set<std::string> codes;
    for (const std::string& line : block.body) {
        const std::string code = line.substr(0, line.find(';'));
        for (auto it = std::sregex_iterator(code.begin(), code.end(), kState);
             it != std::sregex_iterator(); ++it)
            codes.insert(stateCodeWord(std::stoi((*it)[2]) & 0xFFFF));
    }
    return codes;
}

} // namespace

TEST(SafetyStates, EveryBlockHasAStateRecordForEachStateOfItsBodyAndNoOther) {
    const BlockLibrary library = readSafetyLibrary();
    ASSERT_EQ(library.blocks.size(), 15u);
    for (const BlockDefinition& block : library.blocks) {
        std::set<std::string> recorded;
        for (const StateMeaning& state : block.states)
            recorded.insert(stateCodeWord(state.code));
        const std::set<std::string> entered = bodyStates(block);
        EXPECT_TRUE(entered.count("16#0000") && entered.count("16#8000")) << block.name;
        EXPECT_EQ(recorded, entered) << block.name;
    }
}

TEST(SafetyStates, EveryStateMeansSomethingInEnglishSwedishAndGerman) {
    for (const BlockDefinition& block : readSafetyLibrary().blocks)
        for (const StateMeaning& state : block.states) {
            const std::string what = block.name + " " + stateCodeWord(state.code);
            EXPECT_FALSE(state.meaning.english.empty()) << what;
            EXPECT_FALSE(state.meaning.swedish.empty()) << what;
            EXPECT_FALSE(state.meaning.german.empty()) << what;
        }
}
