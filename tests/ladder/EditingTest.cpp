// SPDX-License-Identifier: GPL-3.0-or-later
#include "ladder/Editing.h"
#include "StepText.h"
#include "ladder/LadderToText.h"
#include "ladder/TextToLadder.h"

#include <gtest/gtest.h>

namespace {

using namespace rs::ladder;
using rs::lang::Address;
using rs::lang::AddressKind;

Network networkOf(const std::string& body) {
    return toLadder(rs::test::stepWithCode(body)).networks.at(0);
}

std::string textOf(const Network& network) {
    return rs::test::printLines(toLines(StepLadder{{}, {network}}));
}

Contact contact(int input, ElementKind kind = ElementKind::NormallyOpen) {
    return {kind, {{}, Address{AddressKind::Input, 0, input}, {}}, false};
}

Output coil(int memory) {
    Output output;
    output.target = {{}, Address{AddressKind::Memory, 0, memory}, {}};
    return output;
}

TEST(Editing, InsertInSeriesBeforeAndAfter) {
    Network n = networkOf("Q0.1 = I0.1 * I0.2\n");
    ASSERT_TRUE(insertInSeries(n, {0, {0}}, contact(3), Side::After).done());
    EXPECT_EQ(textOf(n), "Q0.1 = I0.1 * I0.3 * I0.2\n");
    ASSERT_TRUE(insertInSeries(n, {0, {}}, contact(4), Side::Before).done());
    EXPECT_EQ(textOf(n), "Q0.1 = I0.4 * I0.1 * I0.3 * I0.2\n");
}

TEST(Editing, InsertInSeriesInsideABranchMakesTheBranchASeries) {
    Network n = networkOf("Q0.1 = I0.1 + I0.2\n");
    ASSERT_TRUE(insertInSeries(n, {0, {1}}, contact(3), Side::After).done());
    EXPECT_EQ(textOf(n), "Q0.1 = I0.1 + I0.2 * I0.3\n");
}

TEST(Editing, InsertIntoARungWithoutConditionGivesItOne) {
    Network n = networkOf("Q0.1\n");
    EXPECT_FALSE(insertInSeries(n, {0, {0}}, contact(1), Side::After).done());
    ASSERT_TRUE(insertInSeries(n, {0, {}}, contact(1), Side::After).done());
    EXPECT_EQ(textOf(n), "Q0.1 = I0.1\n");
}

TEST(Editing, InsertInParallelAroundAnElementOrSeveralSeriesParts) {
    Network n = networkOf("Q0.1 = I0.1 * I0.2 * I0.4\n");
    ASSERT_TRUE(insertInParallel(n, {0, {2}}, contact(5)).done());
    EXPECT_EQ(textOf(n), "Q0.1 = I0.1 * I0.2 * (I0.4 + I0.5)\n");
    ASSERT_TRUE(insertInParallel(n, {0, {0}}, contact(3), 2).done());
    EXPECT_EQ(textOf(n), "Q0.1 = (I0.1 * I0.2 + I0.3) * (I0.4 + I0.5)\n");
    // Around a branch of a parallel circuit: one more branch, not a nested one.
    ASSERT_TRUE(insertInParallel(n, {0, {1, 0}}, contact(6)).done());
    EXPECT_EQ(textOf(n), "Q0.1 = (I0.1 * I0.2 + I0.3) * (I0.4 + I0.6 + I0.5)\n");
    ASSERT_TRUE(insertInParallel(n, {0, {}}, contact(7)).done());
    EXPECT_EQ(textOf(n), "Q0.1 = (I0.1 * I0.2 + I0.3) * (I0.4 + I0.6 + I0.5) + I0.7\n");
}

TEST(Editing, InsertInParallelRefusesWhatIsNoSeriesRun) {
    Network n = networkOf("Q0.1 = I0.1 + I0.2\n");
    const Network before = n;
    EXPECT_FALSE(insertInParallel(n, {0, {0}}, contact(3), 2).done());
    EXPECT_FALSE(insertInParallel(n, {0, {1, 0}}, contact(3)).done());
    Network unconditional = networkOf("Q0.1\n");
    EXPECT_FALSE(insertInParallel(unconditional, {0, {}}, contact(3)).done());
    EXPECT_EQ(n, before);
}

TEST(Editing, RemovingCollapsesGroupsAndCanLeaveNoCondition) {
    Network n = networkOf("Q0.1 = I0.1 * (I0.2 + I0.3)\n");
    ASSERT_TRUE(removeNode(n, {0, {1, 1}}).done());
    EXPECT_EQ(textOf(n), "Q0.1 = I0.1 * I0.2\n");
    ASSERT_TRUE(removeNode(n, {0, {}}).done());
    EXPECT_EQ(textOf(n), "Q0.1\n");
    EXPECT_FALSE(removeNode(n, {0, {}}).done());
}

TEST(Editing, ReplacingChangesKindOrOperand) {
    Network n = networkOf("Q0.1 = I0.1 * P(/I0.2)\n");
    ASSERT_TRUE(replaceElement(n, {0, {0}}, contact(1, ElementKind::NotNegativeEdge)).done());
    Contact normal = std::get<Contact>(std::get<Rung>(n.items[0]).condition->parts[1].element);
    normal.kind = ElementKind::NormallyClosed; // an ordinary contact has no inverted edge operand
    ASSERT_TRUE(replaceElement(n, {0, {1}}, normal).done());
    EXPECT_EQ(textOf(n), "Q0.1 = /N(I0.1) * /I0.2\n");
    ComparisonBox box{{{}, Address{AddressKind::Register, 0, 1}, {}},
                      rs::lang::CompareOp::Less,
                      {std::nullopt, 100, {}},
                      false};
    ASSERT_TRUE(replaceElement(n, {0, {1}}, box).done());
    EXPECT_EQ(textOf(n), "Q0.1 = /N(I0.1) * (R0.1<100)\n");
    EXPECT_FALSE(replaceElement(n, {0, {}}, box).done()) << "a series is no element";
}

TEST(Editing, MoveWithinARungAndIntoABranch) {
    Network n = networkOf("Q0.1 = I0.1 * I0.2 * I0.3\n");
    ASSERT_TRUE(moveNode(n, {0, {0}}, n, {0, {2}}, Side::After).done());
    EXPECT_EQ(textOf(n), "Q0.1 = I0.2 * I0.3 * I0.1\n");
    Network p = networkOf("Q0.1 = I0.1 * (I0.2 + I0.3)\n");
    ASSERT_TRUE(moveNode(p, {0, {0}}, p, {0, {1, 0}}, Side::After).done());
    EXPECT_EQ(textOf(p), "Q0.1 = I0.2 * I0.1 + I0.3\n");
    // Taking an element out of a branch of two leaves the other one alone.
    Network q = networkOf("Q0.1 = I0.1 * (I0.2 + I0.3)\n");
    ASSERT_TRUE(moveNode(q, {0, {1, 1}}, q, {0, {0}}, Side::Before).done());
    EXPECT_EQ(textOf(q), "Q0.1 = I0.3 * I0.1 * I0.2\n");
}

TEST(Editing, MoveRefusesToPutAGroupIntoItself) {
    Network n = networkOf("Q0.1 = I0.1 * (I0.2 + I0.3)\n");
    const Network before = n;
    EXPECT_FALSE(moveNode(n, {0, {1}}, n, {0, {1, 0}}, Side::After).done());
    EXPECT_FALSE(moveNode(n, {0, {0}}, n, {0, {0}}, Side::After).done());
    EXPECT_EQ(n, before);
}

TEST(Editing, CopyLeavesTheSourceAndMayGoNextToItselfOrIntoItsOwnGroup) {
    Network n = networkOf("Q0.1 = I0.1 * (I0.2 + I0.3)\n");
    ASSERT_TRUE(copyNode(n, {0, {0}}, n, {0, {0}}, Side::After).done());
    EXPECT_EQ(textOf(n), "Q0.1 = I0.1 * I0.1 * (I0.2 + I0.3)\n");
    Network group = networkOf("Q0.1 = I0.1 * (I0.2 + I0.3)\n");
    ASSERT_TRUE(copyNode(group, {0, {1}}, group, {0, {1, 0}}, Side::After).done());
    EXPECT_EQ(textOf(group), "Q0.1 = I0.1 * (I0.2 * (I0.2 + I0.3) + I0.3)\n");
    const Network from = networkOf("Q0.1 = I0.1 * I0.2\n");
    Network to = networkOf("Q0.2 = I0.5\n");
    ASSERT_TRUE(copyNode(from, {0, {1}}, to, {0, {}}, Side::Before).done());
    EXPECT_EQ(textOf(to), "Q0.2 = I0.2 * I0.5\n");
    EXPECT_EQ(textOf(from), "Q0.1 = I0.1 * I0.2\n");
}

TEST(Editing, MoveBetweenNetworks) {
    Network from = networkOf("Q0.1 = I0.1 * I0.2\n");
    Network to = networkOf("Q0.2\n");
    ASSERT_TRUE(moveNode(from, {0, {1}}, to, {0, {}}, Side::Before).done());
    EXPECT_EQ(textOf(from), "Q0.1 = I0.1\n");
    EXPECT_EQ(textOf(to), "Q0.2 = I0.2\n");
}

TEST(Editing, OutputsInParallelShareTheCondition) {
    Network n = networkOf("Q0.1 = I0.1 * /I0.2\n");
    ASSERT_TRUE(addOutput(n, 0, coil(5)).done());
    EXPECT_EQ(textOf(n), ";@network comment=\"\"\nQ0.1 = I0.1 * /I0.2\nM0.5 = I0.1 * /I0.2\n");
    ASSERT_TRUE(removeOutput(n, 0, 0).done());
    EXPECT_EQ(textOf(n), "M0.5 = I0.1 * /I0.2\n") << "one statement again needs no record";
    ASSERT_TRUE(removeOutput(n, 0, 0).done());
    EXPECT_TRUE(n.items.empty());
}

TEST(Editing, ASharedConditionHoldsNoMemoryAndReadsNoOutputOfItsRung) {
    Network edge = networkOf("Q0.1 = P(I0.1)\n");
    EXPECT_FALSE(addOutput(edge, 0, coil(5)).done());
    // A self-holding rung: its second statement would read what its first wrote.
    Network reads = networkOf("M0.5 = I0.1 + M0.5\n");
    EXPECT_FALSE(addOutput(reads, 0, coil(6)).done());
    Network shared = networkOf("Q0.1 = I0.1\n");
    ASSERT_TRUE(addOutput(shared, 0, coil(5)).done());
    const Network before = shared;
    const TimerBox timer{rs::lang::TimerSpelling::TON, {std::nullopt, 100}, false};
    EXPECT_FALSE(insertInSeries(shared, {0, {}}, timer, Side::After).done());
    EXPECT_FALSE(replaceElement(shared, {0, {}}, contact(1, ElementKind::PositiveEdge)).done());
    EXPECT_EQ(shared, before);
}

TEST(Editing, AdjacentRungsWithOneConditionBecomeOneRung) {
    Network n = networkOf("Q0.1 = I0.1\n");
    Rung rung = std::get<Rung>(n.items[0]);
    rung.outputs = {coil(5)};
    ASSERT_TRUE(insertRung(n, 1, rung).done());
    ASSERT_EQ(n.items.size(), 1U);
    EXPECT_EQ(std::get<Rung>(n.items[0]).outputs.size(), 2U);
    EXPECT_FALSE(insertRung(n, 5, rung).done());
    EXPECT_FALSE(insertRung(n, 0, Rung{}).done()) << "a rung needs an output";
}

TEST(Editing, PathsThatLeadNowhereAreRefused) {
    Network n = networkOf("Q0.1 = I0.1 * I0.2\n; a note\n");
    const Network before = n;
    EXPECT_FALSE(insertInSeries(n, {0, {5}}, contact(3), Side::After).done());
    EXPECT_FALSE(insertInSeries(n, {1, {}}, contact(3), Side::After).done()) << "a note";
    EXPECT_FALSE(removeNode(n, {7, {}}).done());
    EXPECT_FALSE(replaceOutput(n, 0, 3, coil(1)).done());
    EXPECT_FALSE(removeItem(n, 2).done());
    EXPECT_EQ(n, before);
    ASSERT_TRUE(removeItem(n, 1).done());
    EXPECT_EQ(textOf(n), "Q0.1 = I0.1 * I0.2\n");
}

} // namespace
