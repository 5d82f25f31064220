// SPDX-License-Identifier: GPL-3.0-or-later
// A block instance in the ladder model: one network, written back as it was
// read, closed to rungs, pasted as a new instance, and laid out as a box.
#include "StepText.h"
#include "ladder/Editing.h"
#include "ladder/LadderToText.h"
#include "ladder/Layout.h"
#include "ladder/NetworkText.h"
#include "ladder/TextToLadder.h"
#include "ladder/UnitLadder.h"

#include <gtest/gtest.h>

namespace {

using namespace rs::ladder;
using rs::test::printLines;
using rs::test::stepWithCode;

// A step with a network, an expanded instance, a comment after it, and a network.
const std::string kStep = "Q0.1 = I0.1\n"
                          ";@block Latch S=\"EStop\" Q=\"Q0.2\" lib=\"Test\" version=\"2.0\" "
                          "#q=\"M0.599\"\n"
                          "S(M0.599) = I0.12\n"
                          "Q0.2 = M0.599\n"
                          ";@end\n"
                          "; after the block\n"
                          "Q0.3 = I0.3\n";

rs::blocks::BlockDefinition latch() {
    rs::blocks::BlockDefinition block;
    block.name = "Latch";
    block.version = "2.0";
    block.description.english = "Q is set by S, reset by R.";
    block.pins = {{"S",
                   rs::blocks::PinDirection::In,
                   rs::blocks::PinKind::Bit,
                   rs::blocks::PinRole::Primary,
                   std::nullopt,
                   {}},
                  {"R",
                   rs::blocks::PinDirection::In,
                   rs::blocks::PinKind::Bit,
                   rs::blocks::PinRole::Primary,
                   std::string("0"),
                   {}},
                  {"Q",
                   rs::blocks::PinDirection::Out,
                   rs::blocks::PinKind::Bit,
                   rs::blocks::PinRole::Primary,
                   std::nullopt,
                   {}}};
    return block;
}

TEST(BlockNetwork, AnInstanceIsOneNetworkAndWritesBackAsItWasRead) {
    const rs::lang::Step step = stepWithCode(kStep);
    const StepLadder ladder = toLadder(step);
    ASSERT_EQ(ladder.networks.size(), 3U);
    const Network& block = ladder.networks[1];
    ASSERT_TRUE(block.block.has_value());
    EXPECT_EQ(block.block->instance.type, "Latch");
    EXPECT_EQ(block.block->lines.size(), 4U) << "record, two statements, end";
    EXPECT_EQ(statementCount(block), 2);
    ASSERT_EQ(block.items.size(), 1U) << "the comment after ;@end stays with the block";
    EXPECT_FALSE(ladder.networks[2].block.has_value());
    EXPECT_EQ(printLines(toLines(ladder)), kStep);

    const auto pages = unitLadder(rs::test::projectWithCode(kStep).program.units.front());
    EXPECT_EQ(pages.front().firstStatements, (std::vector<std::uint32_t>{0, 1, 3}))
        << "the statements of the instance are numbered as the compiler numbers them";
}

TEST(BlockNetwork, AnInstanceNotShownAsABoxIsItsStatements) {
    const StepLadder ladder =
        toLadder(stepWithCode(kStep), [](const rs::blocks::BlockInstance&) { return false; });
    for (const auto& network : ladder.networks)
        EXPECT_FALSE(network.block.has_value());
    EXPECT_EQ(ladder.networks.size(), 4U);
    EXPECT_EQ(printLines(toLines(ladder)), kStep);
}

TEST(BlockNetwork, ABlockNetworkTakesNoRung) {
    StepLadder ladder = toLadder(stepWithCode(kStep));
    Network& block = ladder.networks[1];
    const Network before = block;
    Rung rung;
    rung.outputs.push_back(std::get<Rung>(ladder.networks[0].items[0]).outputs[0]);
    EXPECT_FALSE(insertRung(block, 0, rung).done());
    EXPECT_FALSE(insertRung(block, 1, rung).done());
    EXPECT_EQ(block, before);
}

TEST(BlockNetwork, APastedInstanceComesWithoutItsStatementsAndPrivateVariables) {
    const StepLadder ladder = toLadder(stepWithCode(kStep));
    const std::string copied = networksText({ladder.networks[1]});
    EXPECT_NE(copied.find("#q=\"M0.599\""), std::string::npos) << copied;
    const NetworksReading pasted = readNetworksText(copied);
    ASSERT_TRUE(pasted.error.empty()) << pasted.error;
    ASSERT_EQ(pasted.networks.size(), 1U);
    const auto& call = pasted.networks[0].block;
    ASSERT_TRUE(call.has_value());
    EXPECT_TRUE(call->instance.privates.empty());
    EXPECT_FALSE(call->instance.hasExpansion());
    EXPECT_EQ(printLines(call->lines),
              ";@block Latch S=\"EStop\" Q=\"Q0.2\" lib=\"Test\" version=\"2.0\"\n;@end\n");
}

TEST(BlockNetwork, TheBoxHasInputsLeftOutputsRightAndOpenPinsShowWhatTheyTake) {
    const auto project = rs::test::projectWithCode(kStep);
    const auto pages = unitLadder(project.program.units.front());
    const auto symbols = SymbolTable::of(project.program, 0);
    const rs::blocks::BlockDefinition block = latch();
    LayoutContext context;
    context.number = 2;
    context.firstStatement = pages.front().firstStatements[1];
    context.symbols = &symbols;
    context.block = &block;
    const NetworkLayout layout = layoutNetwork(pages.front().ladder.networks[1], context);
    ASSERT_TRUE(layout.block.has_value());
    EXPECT_TRUE(layout.elements.empty());
    const BlockLayout& box = *layout.block;
    EXPECT_EQ(box.type, QStringLiteral("Latch"));
    ASSERT_EQ(box.pins.size(), 3U);
    const PinLayout& s = box.pins[0];
    const PinLayout& r = box.pins[1];
    const PinLayout& q = box.pins[2];
    EXPECT_TRUE(s.power) << "the first bit input takes the rung's power";
    EXPECT_EQ(s.name, QStringLiteral("EStop"));
    EXPECT_EQ(s.operand, QStringLiteral("I0.12"));
    EXPECT_LT(s.contactRect.right(), box.box.left());
    EXPECT_FALSE(r.power);
    EXPECT_TRUE(r.open);
    EXPECT_EQ(r.operand, QStringLiteral("(0)")) << "an open input shows the default it takes";
    EXPECT_LT(r.stub.x1(), box.box.left());
    EXPECT_EQ(q.operand, QStringLiteral("Q0.2"));
    EXPECT_GT(q.stub.x2(), box.box.right());
    EXPECT_GT(q.operandRect.left(), box.box.right());
    for (const auto& pin : box.pins)
        EXPECT_TRUE(box.box.contains(pin.pinRect)) << pin.pin.toStdString();
    EXPECT_LE(r.pinRect.bottom(), box.box.bottom());
    EXPECT_GE(layout.size.width(), q.operandRect.right());
    // No two labels of the box cover each other.
    std::vector<QRectF> labels;
    for (const auto& pin : box.pins)
        for (const QRectF& rect : {pin.nameRect, pin.operandRect, pin.contactRect, pin.pinRect})
            if (!rect.isEmpty())
                labels.push_back(rect);
    for (std::size_t i = 0; i < labels.size(); ++i)
        for (std::size_t j = i + 1; j < labels.size(); ++j)
            EXPECT_FALSE(labels[i].intersects(labels[j])) << i << " and " << j;
    bool described = false;
    for (const auto& text : layout.texts)
        described = described || text.text == QStringLiteral("Q is set by S, reset by R.");
    EXPECT_TRUE(described) << "the block's description is the network's comment";
}

TEST(BlockNetwork, AnOpenPinWithoutDefaultIsQuestionMarksAndAnOpenSecondaryOutputBlank) {
    rs::blocks::BlockDefinition block = latch();
    block.pins[1].defaultValue.reset();
    block.pins.push_back({"Fault",
                          rs::blocks::PinDirection::Out,
                          rs::blocks::PinKind::Bit,
                          rs::blocks::PinRole::Secondary,
                          std::nullopt,
                          {}});
    const auto project = rs::test::projectWithCode(";@block Latch S=\"I0.1\"\n;@end\n");
    const auto pages = unitLadder(project.program.units.front());
    LayoutContext context;
    context.block = &block;
    const NetworkLayout layout = layoutNetwork(pages.front().ladder.networks.at(0), context);
    ASSERT_TRUE(layout.block.has_value());
    ASSERT_EQ(layout.block->pins.size(), 4U);
    EXPECT_EQ(layout.block->pins[1].operand, QStringLiteral("???")) << "R must be bound";
    EXPECT_EQ(layout.block->pins[2].operand, QStringLiteral("???")) << "Q is primary";
    EXPECT_EQ(layout.block->pins[3].operand, QString()) << "Fault may stay open";
    EXPECT_TRUE(layout.block->pins[3].open);
    EXPECT_FALSE(layout.block->pins[3].missing);
    EXPECT_TRUE(layout.block->pins[1].missing);
}

TEST(BlockNetwork, AnAnalogueInputOnAPinIsANumberAndTakesNoRungPower) {
    const std::string code = ";@block Latch S=\"IA0.1\" Q=\"Q0.2\" lib=\"Test\"\n;@end\n";
    const auto project = rs::test::projectWithCode(code);
    const auto pages = unitLadder(project.program.units.front());
    const rs::blocks::BlockDefinition block = latch();
    LayoutContext context;
    context.block = &block;
    const NetworkLayout layout = layoutNetwork(pages.front().ladder.networks.at(0), context);
    ASSERT_TRUE(layout.block.has_value());
    const PinLayout& s = layout.block->pins.at(0);
    EXPECT_FALSE(s.power);
    EXPECT_EQ(s.kind, rs::blocks::PinKind::Register);
    EXPECT_EQ(s.operand, QStringLiteral("IA0.1"));
    EXPECT_EQ(layout.block->pins.at(1).operand, QStringLiteral("(0)"));
    const PinLayout& r = layout.block->pins.at(1);
    EXPECT_TRUE(r.power) << "R is the first bit input now";
    EXPECT_TRUE(r.contactRect.isEmpty()) << "open, it switches nothing: the rung runs to it";
    bool straight = false;
    for (const auto& wire : layout.wires)
        straight =
            straight || (wire.line.p2() == QPointF(layout.block->box.left(), wire.line.y1()) &&
                         wire.feed.kind == PowerFeed::Kind::Rail);
    EXPECT_TRUE(straight);
}

} // namespace
