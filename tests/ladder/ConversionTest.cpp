// SPDX-License-Identifier: GPL-3.0-or-later
#include "StepText.h"
#include "ladder/LadderToText.h"
#include "ladder/TextToLadder.h"

#include <gtest/gtest.h>

namespace {

using namespace rs::ladder;
using rs::test::printLines;
using rs::test::stepWithCode;

// The one rung of a step's text; the ladder is kept so the rung stays valid.
struct OnlyRung {
    StepLadder ladder;
    const Rung& rung() const { return std::get<Rung>(ladder.networks.at(0).items.at(0)); }
};

OnlyRung onlyRung(const std::string& body) {
    OnlyRung only{toLadder(stepWithCode(body))};
    EXPECT_EQ(only.ladder.networks.size(), 1U);
    return only;
}

const Element& elementAt(const Circuit& circuit, std::size_t part) {
    return circuit.parts.at(part).element;
}

// Reading a step into ladder form and writing it back gives its text again.
void expectRoundTrip(const std::string& body) {
    const rs::lang::Step step = stepWithCode(body);
    EXPECT_EQ(printLines(toLines(toLadder(step))), body);
}

TEST(TextToLadder, ContactsAndEdgesKeepTheirKindAndOperand) {
    const std::string body =
        "Q0.1 = I0.1 * /I0.2 * P(I0.3) * N(I0.4) * /P(I0.5) * /N(/I0.6) * P(/EStop)\n";
    const OnlyRung only = onlyRung(body);
    const Rung& rung = only.rung();
    ASSERT_EQ(rung.condition->kind, Circuit::Kind::Series);
    const ElementKind kinds[] = {ElementKind::NormallyOpen,    ElementKind::NormallyClosed,
                                 ElementKind::PositiveEdge,    ElementKind::NegativeEdge,
                                 ElementKind::NotPositiveEdge, ElementKind::NotNegativeEdge,
                                 ElementKind::PositiveEdge};
    for (std::size_t i = 0; i < std::size(kinds); ++i) {
        const auto& contact = std::get<Contact>(elementAt(*rung.condition, i));
        EXPECT_EQ(contact.kind, kinds[i]) << i;
        EXPECT_EQ(contact.operandNegated, i >= 5) << i;
    }
    const auto& named = std::get<Contact>(elementAt(*rung.condition, 6));
    EXPECT_EQ(named.operand.name, "EStop");
    EXPECT_EQ(rs::lang::toString(named.operand.address), "I0.12");
    expectRoundTrip(body);
}

TEST(TextToLadder, TimersKeepSpellingPresetAndNegation) {
    const std::string body =
        "Q0.1 = I0.1 * TON(2s50) * /TPS(R0.5) * TOF(0s10) * T(1s00) * /IT(R0.1)\n";
    const OnlyRung only = onlyRung(body);
    const Rung& rung = only.rung();
    const auto& ton = std::get<TimerBox>(elementAt(*rung.condition, 1));
    EXPECT_EQ(ton.spelling, rs::lang::TimerSpelling::TON);
    EXPECT_EQ(ton.preset.hundredths, 250);
    EXPECT_FALSE(ton.negated);
    const auto& tps = std::get<TimerBox>(elementAt(*rung.condition, 2));
    EXPECT_TRUE(tps.negated);
    ASSERT_TRUE(tps.preset.registerOperand);
    EXPECT_EQ(rs::lang::toString(tps.preset.registerOperand->address), "R0.5");
    EXPECT_EQ(std::get<TimerBox>(elementAt(*rung.condition, 4)).spelling,
              rs::lang::TimerSpelling::T);
    expectRoundTrip(body);
}

TEST(TextToLadder, ComparisonsAreBoxes) {
    const std::string body = "Q0.1 = (R0.1>=5) * /(R0.2=R0.3)\n";
    const OnlyRung only = onlyRung(body);
    const Rung& rung = only.rung();
    const auto& first = std::get<ComparisonBox>(elementAt(*rung.condition, 0));
    EXPECT_EQ(first.op, rs::lang::CompareOp::GreaterEqual);
    EXPECT_EQ(first.right.constant, 5);
    EXPECT_FALSE(first.negated);
    EXPECT_TRUE(std::get<ComparisonBox>(elementAt(*rung.condition, 1)).negated);
    expectRoundTrip(body);
}

TEST(TextToLadder, AndIsSeriesAndOrIsParallel) {
    const std::string body = "Q0.2 = EStop * (I0.13 + M0.0) * (P(I0.14) * I0.2 + Q0.2)\n";
    const OnlyRung only = onlyRung(body);
    const Rung& rung = only.rung();
    const Circuit& c = *rung.condition;
    ASSERT_EQ(c.kind, Circuit::Kind::Series);
    ASSERT_EQ(c.parts.size(), 3U);
    EXPECT_TRUE(c.parts[0].isElement());
    EXPECT_EQ(c.parts[1].kind, Circuit::Kind::Parallel);
    EXPECT_EQ(c.parts[1].parts.size(), 2U);
    EXPECT_EQ(c.parts[2].kind, Circuit::Kind::Parallel);
    EXPECT_EQ(c.parts[2].parts[0].kind, Circuit::Kind::Series);
    EXPECT_EQ(c.parts[2].parts[0].parts.size(), 2U);
    expectRoundTrip(body);
}

TEST(TextToLadder, EveryOutputKind) {
    const std::string body = "S(Q0.1) = I0.1\nR(Q0.1) = I0.2\nT(Q0.1) = I0.3\nJ(+1) = I0.4\n"
                             "R(S0.1) = I0.5\n(R0.1 += 2) = I0.6\nQ0.2\n(R0.1++)\n"
                             "(R0.3 = R0.1 * R0.2)\nLamp = /I0.7\n";
    const StepLadder ladder = toLadder(stepWithCode(body));
    ASSERT_EQ(ladder.networks.size(), 10U);
    using rs::lang::StatementKind;
    const StatementKind kinds[] = {StatementKind::Set,           StatementKind::Reset,
                                   StatementKind::Toggle,        StatementKind::Jump,
                                   StatementKind::SequenceReset, StatementKind::Assign,
                                   StatementKind::Coil,          StatementKind::Assign,
                                   StatementKind::Assign,        StatementKind::Coil};
    for (std::size_t i = 0; i < std::size(kinds); ++i) {
        const Rung& rung = std::get<Rung>(ladder.networks[i].items.at(0));
        ASSERT_EQ(rung.outputs.size(), 1U);
        EXPECT_EQ(rung.outputs[0].kind, kinds[i]) << i;
        EXPECT_EQ(rung.condition.has_value(), i != 6 && i != 7 && i != 8) << i;
    }
    expectRoundTrip(body);
}

TEST(TextToLadder, HandWrittenStatementsAreOneNetworkEach) {
    const std::string body = "; before the first statement\n\nQ0.1 = I0.1   ; trailing\n"
                             "                              ; explains the line above\n\n"
                             "Q0.2 = I0.2\nQ0.3 = I0.2\n";
    const StepLadder ladder = toLadder(stepWithCode(body));
    EXPECT_EQ(ladder.leading.size(), 2U);
    ASSERT_EQ(ladder.networks.size(), 3U);
    EXPECT_EQ(ladder.networks[0].items.size(), 3U); // the rung, the comment line, the blank line
    EXPECT_EQ(std::get<Rung>(ladder.networks[0].items[0]).outputs[0].comment, " trailing");
    EXPECT_FALSE(ladder.networks[0].record);
    // Equal conditions, but without a record they are separate networks.
    EXPECT_EQ(statementCount(ladder.networks[1]), 1);
    EXPECT_EQ(statementCount(ladder.networks[2]), 1);
    expectRoundTrip(rs::test::printLines(stepWithCode(body).lines));
}

TEST(TextToLadder, ARecordGroupsAndAdjacentStatementsWithOneConditionShareARung) {
    const std::string body = ";@network comment=\"Both channels\"\n"
                             "Q0.2 = EStop * I0.13           ; channel A\n"
                             "Q0.3 = EStop * I0.13           ; channel B\n"
                             ";@network comment=\"Lamps\"\nM0.0\nLamp\n";
    const StepLadder ladder = toLadder(stepWithCode(body));
    ASSERT_EQ(ladder.networks.size(), 2U);
    EXPECT_EQ(ladder.networks[0].comment, "Both channels");
    ASSERT_EQ(ladder.networks[0].items.size(), 1U);
    const Rung& rung = std::get<Rung>(ladder.networks[0].items[0]);
    ASSERT_EQ(rung.outputs.size(), 2U);
    EXPECT_EQ(rung.outputs[1].comment, " channel B");
    EXPECT_EQ(std::get<Rung>(ladder.networks[1].items.at(0)).outputs.size(), 2U);
    expectRoundTrip(body);
}

TEST(TextToLadder, StatementsThatMeanMoreThanTheirConditionKeepTheirOwnRungs) {
    const char* const bodies[] = {
        // each edge and each timer occurrence has its own memory
        ";@network\nQ0.1 = P(I0.1)\nQ0.2 = P(I0.1)\n",
        ";@network\nQ0.1 = I0.1 * TON(1s00)\nQ0.2 = I0.1 * TON(1s00)\n",
        // the second statement reads what the first writes
        ";@network\nM0.1 = I0.1 + M0.1\nQ0.3 = I0.1 + M0.1\n",
        ";@network\nIQ0.14 = I0.1 + Q0.14\nQ0.15 = I0.1 + Q0.14\n", // the button's lamp is Q0.14
        ";@network\n(R0.1 += 1) = (R0.1<5)\nQ0.1 = (R0.1<5)\n",
        ";@network\nR0.2.3 = (R0.2>1)\nQ0.1 = (R0.2>1)\n",
        // a comment line stands between them
        ";@network\nQ0.1 = I0.1\n; between\nQ0.2 = I0.1\n",
    };
    for (const char* body : bodies) {
        const StepLadder ladder = toLadder(stepWithCode(body));
        ASSERT_EQ(ladder.networks.size(), 1U) << body;
        for (const auto& item : ladder.networks[0].items) {
            if (const auto* rung = std::get_if<Rung>(&item)) {
                EXPECT_EQ(rung->outputs.size(), 1U) << body;
            }
        }
        expectRoundTrip(body);
    }
}

TEST(TextToLadder, AMalformedRecordIsAComment) {
    const std::string body = "Q0.1 = I0.1\n;@network comment=\"open\nQ0.2 = I0.2\n";
    rs::lang::Step step = stepWithCode("Q0.1 = I0.1\nQ0.2 = I0.2\n");
    step.lines.insert(step.lines.begin() + 1,
                      {rs::lang::CommentLine{"@network comment=\"open", false}, std::nullopt, {}});
    const StepLadder ladder = toLadder(step);
    ASSERT_EQ(ladder.networks.size(), 2U);
    EXPECT_EQ(ladder.networks[0].items.size(), 2U);
    EXPECT_EQ(printLines(toLines(ladder)), body);
}

TEST(LadderToText, ARecordIsKeptAsWrittenAndUpdatedWithItsComment) {
    const std::string body =
        "Q0.1 = I0.1\n                               ;@network comment=\"old\" zoom=\"2\"\n"
        "Q0.2 = I0.2\n";
    StepLadder ladder = toLadder(stepWithCode(body));
    ASSERT_EQ(ladder.networks.size(), 2U);
    EXPECT_EQ(printLines(toLines(ladder)), body);
    ladder.networks[1].comment = "new";
    EXPECT_EQ(printLines(toLines(ladder)),
              "Q0.1 = I0.1\n                               ;@network comment=\"new\" zoom=\"2\"\n"
              "Q0.2 = I0.2\n");
}

TEST(LadderToText, GroupingAStepOfSingleStatementsRecordsEveryNetwork) {
    StepLadder ladder = toLadder(stepWithCode("Q0.1 = I0.1\nQ0.2 = I0.2\nQ0.3 = I0.3\n"));
    ladder.networks[1].comment = "Second";
    EXPECT_EQ(printLines(toLines(ladder)), ";@network comment=\"\"\nQ0.1 = I0.1\n"
                                           ";@network comment=\"Second\"\nQ0.2 = I0.2\n"
                                           ";@network comment=\"\"\nQ0.3 = I0.3\n");
}

TEST(LadderToText, ANetworkAfterARecordedOneGetsARecordToStaySeparate) {
    StepLadder ladder = toLadder(stepWithCode(";@network comment=\"A\"\nQ0.1 = I0.1\n"));
    Network second;
    second.items.emplace_back(
        toRung(std::get<rs::lang::Statement>(stepWithCode("Q0.2 = I0.2\n").lines.at(0).body),
               std::nullopt));
    ladder.networks.push_back(second);
    const std::string text = printLines(toLines(ladder));
    EXPECT_EQ(text, ";@network comment=\"A\"\nQ0.1 = I0.1\n;@network comment=\"\"\nQ0.2 = I0.2\n");
    EXPECT_EQ(toLadder(stepWithCode(text)).networks.size(), 2U);
}

} // namespace
