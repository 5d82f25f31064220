// SPDX-License-Identifier: GPL-3.0-or-later
#include "StepText.h"
#include "ladder/ConfigOption.h"
#include "ladder/Editing.h"
#include "ladder/ElementText.h"
#include "ladder/LadderToText.h"
#include "ladder/NetworkText.h"
#include "ladder/TextToLadder.h"
#include "ladder/UnitLadder.h"
#include "lang/Parser.h"
#include "project/Sequences.h"
#include "project/UnitSettings.h"

#include <gtest/gtest.h>

// What the ladder editor reads and writes besides the editing operations:
// elements typed in its properties dialog, networks on the clipboard, and
// Config Option networks.
namespace {

using namespace rs::ladder;
using rs::lang::Address;
using rs::lang::AddressKind;

rs::lang::Document editorDocument() {
    return rs::lang::parse("! id_pluto:00=000034AD4AE1\n"
                           "! I0.12=EStop\n"
                           "! pgm_pluto:00\n"
                           "! R0.1=Count\n"
                           "S0.0_0\n")
        .document;
}

TEST(ElementText, ReadsEveryElementKindWithTheUnitsNames) {
    const auto document = editorDocument();
    for (const char* text :
         {"EStop", "/I0.2", "R0.3.7", "P(I0.14)", "N(/I0.1)", "/P(I0.3)", "TON(2s50)", "/TPS(R0.5)",
          "TOF(1s50)", "(Count>=5)", "/(R0.4=R0.2)"}) {
        const ElementReading read = readElement(document, 0, text);
        ASSERT_TRUE(read.element) << text << ": " << read.error;
        EXPECT_EQ(elementText(*read.element), text);
    }
    const ElementReading named = readElement(document, 0, "estop");
    ASSERT_TRUE(named.element);
    EXPECT_EQ(std::get<Contact>(*named.element).operand.address,
              (Address{AddressKind::Input, 0, 12}));
}

TEST(ElementText, ReadsEveryOutputKind) {
    const auto document = editorDocument();
    for (const char* text : {"Q0.2", "S(Q0.2)", "R(M0.1)", "T(Q0.3)", "J(+1)", "J(0)", "J(-2)",
                             "R(S0.1)", "(Count += 2)", "(R0.4++)", "(R0.4 = R0.2 + R0.3)"}) {
        const OutputReading read = readOutput(document, 0, text);
        ASSERT_TRUE(read.output) << text << ": " << read.error;
        EXPECT_EQ(outputText(*read.output), text);
    }
}

TEST(ElementText, AnAddressTypedWhereTheUnitHasANameIsWrittenWithTheName) {
    const auto document = editorDocument();
    const ElementReading contact = readElement(document, 0, "/i0.12");
    ASSERT_TRUE(contact.element) << contact.error;
    EXPECT_EQ(elementText(*contact.element), "/EStop");
    const ElementReading compare = readElement(document, 0, "(r0.1>=r0.2)");
    ASSERT_TRUE(compare.element) << compare.error;
    EXPECT_EQ(elementText(*compare.element), "(Count>=R0.2)");
    const OutputReading assign = readOutput(document, 0, "(R0.2 = R0.1 + 1)");
    ASSERT_TRUE(assign.output) << assign.error;
    EXPECT_EQ(outputText(*assign.output), "(R0.2 = Count + 1)");
    const ElementReading timer = readElement(document, 0, "TON(R0.1)");
    ASSERT_TRUE(timer.element) << timer.error;
    EXPECT_EQ(elementText(*timer.element), "TON(Count)");
}

TEST(ElementText, RefusesWhatIsNotOneElementWithAReason) {
    const auto document = editorDocument();
    EXPECT_FALSE(readElement(document, 0, "I0.1 * I0.2").error.empty());
    EXPECT_FALSE(readElement(document, 0, "NoSuchName").error.empty());
    EXPECT_FALSE(readElement(document, 0, "").error.empty());
    EXPECT_FALSE(readOutput(document, 0, "Q0.2 = I0.1").error.empty());
    EXPECT_FALSE(readOutput(document, 0, "(").error.empty());
    // A preset typed as most languages write a number says how this one does.
    EXPECT_EQ(readElement(document, 0, "TON(0.5)").error,
              "a time is written with the decimal sign 's': 0s50, not 0.5");
}

TEST(NetworkText, NetworksGoThroughTheClipboardWithAddressesForNames) {
    const StepLadder step = toLadder(rs::test::stepWithCode(";@network comment=\"Start\"\n"
                                                            "Q0.2 = I0.12 * I0.13\n"
                                                            "Q0.3 = Q0.2\n"
                                                            "Q0.4 = /I0.5\n"));
    const std::string text = networksText(step.networks);
    const NetworksReading read = readNetworksText(text);
    ASSERT_TRUE(read.error.empty()) << read.error;
    ASSERT_EQ(read.networks.size(), step.networks.size());
    EXPECT_EQ(read.networks.front().comment, "Start");
    EXPECT_EQ(rs::test::printLines(toLines(StepLadder{{}, read.networks})), text);
    EXPECT_FALSE(readNetworksText("Q0.2 = (").error.empty());
}

TEST(ConfigOption, IsARecordAndTheStatementItStandsFor) {
    const ConfigOption option{
        "Door switch fitted", {{}, Address{AddressKind::Memory, 0, 5}, {}}, true};
    const Network network = configOptionNetwork(option);
    const std::string text = rs::test::printLines(toLines(StepLadder{{}, {network}}));
    EXPECT_EQ(text, ";@network comment=\"Door switch fitted\" option=\"on\"\nS(M0.5)\n");
    const StepLadder read = toLadder(rs::test::stepWithCode(text));
    ASSERT_EQ(read.networks.size(), 1U);
    EXPECT_EQ(configOptionOf(read.networks.front()), option);

    ConfigOption off = option;
    off.checked = false;
    EXPECT_EQ(rs::test::printLines(toLines(StepLadder{{}, {configOptionNetwork(off)}})),
              ";@network comment=\"Door switch fitted\" option=\"off\"\nR(M0.5)\n");
}

TEST(ConfigOption, OrdinaryNetworksAreNoOptions) {
    for (const char* text : {"S(M0.5)\n", ";@network comment=\"x\"\nS(M0.5)\n",
                             ";@network comment=\"x\" option=\"on\"\nR(M0.5)\n",
                             ";@network comment=\"x\" option=\"on\"\nS(Q0.5)\n",
                             ";@network comment=\"x\" option=\"on\"\nS(M0.5) = I0.1\n"}) {
        const StepLadder read = toLadder(rs::test::stepWithCode(text));
        ASSERT_FALSE(read.networks.empty());
        EXPECT_FALSE(configOptionOf(read.networks.front())) << text;
    }
}

} // namespace

namespace {

TEST(Steps, ANewStepFollowsTheSequencesLastAndAFirstOneStartsTheSequence) {
    rs::project::Project project = rs::test::projectWithCode("Q0.2 = I0.1\n");
    const rs::project::AddedStep first = rs::project::addStep(project, 0, 1);
    EXPECT_EQ(first.step, 0);
    const rs::project::AddedStep second = rs::project::addStep(project, 0, 1);
    EXPECT_EQ(second.step, 1);
    EXPECT_FALSE(rs::project::addStep(project, 0, 10).refusal.empty());
    std::vector<rs::lang::StepAddress> steps;
    for (const auto& step : rs::project::programOf(project, 0).steps)
        steps.push_back(step.address);
    EXPECT_EQ(steps, (std::vector<rs::lang::StepAddress>{{0, 0, 0}, {0, 1, 0}, {0, 1, 1}}));
}

TEST(Steps, ALadderIsWrittenBackIntoItsStep) {
    rs::project::Project project = rs::test::projectWithCode("Q0.2 = I0.1\n");
    rs::lang::UnitProgram& unit = rs::project::programOf(project, 0);
    StepLadder ladder = toLadder(unit.steps.front());
    ASSERT_TRUE(insertInSeries(ladder.networks.front(), {0, {}},
                               Contact{ElementKind::NormallyClosed,
                                       {{}, Address{AddressKind::Input, 0, 3}, {}},
                                       false},
                               Side::After)
                    .done());
    ASSERT_TRUE(setStepLadder(unit, {0, 0, 0}, ladder));
    EXPECT_EQ(rs::test::printLines(unit.steps.front().lines), "Q0.2 = I0.1 * /I0.3\n");
    EXPECT_FALSE(setStepLadder(unit, {0, 4, 0}, ladder));
}

} // namespace
