// SPDX-License-Identifier: GPL-3.0-or-later
#include "RandomProgram.h"

#include "pl110/ProgramText.h"
#include "pl110/RungEditing.h"
#include "pl110/Rungs.h"

#include <gtest/gtest.h>

namespace rs::pl110 {
namespace {

Program read(std::string_view text) {
    ProgramReading reading = readProgram(text);
    EXPECT_TRUE(reading.diagnostics.empty()) << text;
    return std::move(reading.program);
}

Line rungLine(const Program& program, std::string_view text) {
    RungReading reading = readRung(program, text);
    EXPECT_TRUE(reading.line.has_value()) << text;
    return *reading.line;
}

Element contact(const char* address, ElementKind kind = ElementKind::NormallyOpen) {
    Element element;
    element.kind = kind;
    element.operand.address = readAddress(address).address;
    return element;
}

const char* const kStation = R"($target PL110
! I1=Start
INIT
(VW0 = 1)
MAIN
; first
Q1 = Start * I2
; second, two lines
; of comment
Q2 = I3 + I4

Q3 = Q1 * Q2
)";

std::vector<std::string> rungTexts(const Program& program) {
    std::vector<std::string> texts;
    for (const NumberedRung& rung : numberedRungs(program))
        texts.push_back(printRungLine(*rung.line) +
                        (rung.comment.empty() ? "" : " ;" + rung.comment));
    return texts;
}

TEST(Pl110Rungs, ATextLineNamesTheRungWrittenThereOrAboveAndAnAddressItsName) {
    const Program program = read(kStation);
    EXPECT_EQ(rungAtLine(program, 1), 1);  // above every rung
    EXPECT_EQ(rungAtLine(program, 4), 1);  // (VW0 = 1)
    EXPECT_EQ(rungAtLine(program, 7), 2);  // Q1 = Start * I2
    EXPECT_EQ(rungAtLine(program, 9), 2);  // the comment above Q2
    EXPECT_EQ(rungAtLine(program, 12), 4); // Q3
    EXPECT_EQ(declaredName(program, readAddress("I1").address), "Start");
    EXPECT_EQ(declaredName(program, readAddress("I2").address), "");
}

TEST(Pl110RungEditing, ARungGoesAfterTheChosenOneOrFirstInItsPart) {
    Program program = read(kStation);
    ASSERT_EQ(insertRung(program, 2, rungLine(program, "Q4 = Start")), "");
    ASSERT_EQ(insertRung(program, 0, rungLine(program, "Q5 = I5")), "");
    ASSERT_EQ(insertRung(program, 0, rungLine(program, "(VW1 = 2)"), true), "");
    EXPECT_EQ(printProgram(program), R"($target PL110
! I1=Start
INIT
(VW1 = 2)
(VW0 = 1)
MAIN
Q5 = I5
; first
Q1 = Start * I2
Q4 = Start
; second, two lines
; of comment
Q2 = I3 + I4

Q3 = Q1 * Q2
)");
}

TEST(Pl110RungEditing, ARungGoesWithItsCommentAndMovesWithIt) {
    Program program = read(kStation);
    ASSERT_EQ(moveRung(program, 3, -1), "");
    EXPECT_EQ(rungTexts(program),
              (std::vector<std::string>{"(VW0 = 1)", "Q2 = I3 + I4 ;second, two lines\nof comment",
                                        "Q1 = Start * I2 ;first", "Q3 = Q1 * Q2"}));
    ASSERT_EQ(moveRung(program, 2, 1), "");
    EXPECT_EQ(printProgram(program), kStation);
    ASSERT_EQ(removeRung(program, 2), "");
    EXPECT_EQ(printProgram(program), R"($target PL110
! I1=Start
INIT
(VW0 = 1)
MAIN
; second, two lines
; of comment
Q2 = I3 + I4

Q3 = Q1 * Q2
)");
}

TEST(Pl110RungEditing, ARungDoesNotMoveOutOfItsPartOrBeyondTheEnds) {
    Program program = read(kStation);
    const Program before = program;
    EXPECT_EQ(moveRung(program, 2, -1), "it is the first rung of its part");
    EXPECT_EQ(moveRung(program, 4, 1), "it is the last rung of its part");
    EXPECT_EQ(moveRung(program, 1, 1), "it is the last rung of its part");
    EXPECT_EQ(removeRung(program, 9), "there is no rung there");
    EXPECT_EQ(printProgram(program), printProgram(before));
}

TEST(Pl110RungEditing, ElementsGoInSeriesAndInParallelAndComeOut) {
    Program program = read(kStation);
    ASSERT_EQ(insertInSeries(program, 2, {1},
                             Circuit::of(contact("I9", ElementKind::NormallyClosed)),
                             ladder::Side::After),
              "");
    ASSERT_EQ(insertInParallel(program, 2, {0}, Circuit::of(contact("M1"))), "");
    EXPECT_EQ(printRungLine(*numberedRungs(program)[1].line), "Q1 = (Start + M1) * I2 * /I9");
    Element rising;
    rising.kind = ElementKind::RisingEdge;
    ASSERT_EQ(replaceNode(program, 2, {2}, Circuit::of(rising)), "");
    EXPECT_EQ(printRungLine(*numberedRungs(program)[1].line), "Q1 = (Start + M1) * I2 * P");
    ASSERT_EQ(removeElement(program, 2, {0}), "");
    ASSERT_EQ(removeElement(program, 2, {0}), "");
    EXPECT_EQ(printRungLine(*numberedRungs(program)[1].line), "Q1 = P");
    ASSERT_EQ(removeElement(program, 2, {}), "");
    EXPECT_EQ(printRungLine(*numberedRungs(program)[1].line), "Q1");
    // The condition is gone: the next contact becomes it.
    ASSERT_EQ(insertInSeries(program, 2, {}, Circuit::of(contact("I1")), ladder::Side::After), "");
    EXPECT_EQ(printRungLine(*numberedRungs(program)[1].line), "Q1 = I1");

    const Program before = program;
    EXPECT_EQ(removeElement(program, 2, {3}), "there is no element there");
    EXPECT_EQ(replaceNode(program, 7, {}, Circuit::of(rising)), "there is no rung there");
    EXPECT_EQ(program, before);
}

TEST(Pl110RungEditing, AConditionIsReadAsWrittenInARung) {
    const Program program = read(kStation);
    const ConditionReading good = readCondition(program, " start * (VW1 >= 10) + NOT");
    ASSERT_TRUE(good.circuit.has_value());
    Program edited = program;
    ASSERT_EQ(insertInSeries(edited, 4, {}, *good.circuit, ladder::Side::Before), "");
    EXPECT_EQ(printRungLine(*numberedRungs(edited)[3].line),
              "Q3 = (Start * (VW1>=10) + NOT) * Q1 * Q2");
    const ConditionReading bad = readCondition(program, "I1 * ");
    ASSERT_FALSE(bad.circuit.has_value());
    EXPECT_EQ(bad.diagnostics.at(0).column, 5);
    EXPECT_FALSE(readCondition(program, "I1 ; comment").circuit.has_value());
    EXPECT_FALSE(readCondition(program, "").circuit.has_value());
}

TEST(Pl110RungEditing, ARungIsReadAsItsLineIsWrittenWithTheDeclaredNames) {
    const Program program = read(kStation);
    const RungReading good = readRung(program, "  q4 = start * /i2   ; a comment");
    ASSERT_TRUE(good.line.has_value());
    EXPECT_EQ(printRungLine(*good.line), "Q4 = Start * /I2               ; a comment");
    const RungReading bad = readRung(program, "Q4 = Stop");
    ASSERT_FALSE(bad.line.has_value());
    ASSERT_EQ(bad.diagnostics.size(), 1u);
    EXPECT_EQ(bad.diagnostics[0].column, 6);
    EXPECT_FALSE(readRung(program, "").line.has_value());
    EXPECT_FALSE(readRung(program, "Q4 = I1\nQ5 = I2").line.has_value());
}

// Any sequence of edits leaves a program whose printed text reads back as
// the same program: the ladder's edits never produce a text that does not
// read, nor one that reads as something else.
TEST(Pl110RungEditing, RandomEditsOfRandomProgramsStayExactlyPrintable) {
    std::mt19937 random(1101);
    const auto pick = [&](int low, int high) {
        return std::uniform_int_distribution<int>(low, high)(random);
    };
    int made = 0;
    for (int i = 0; i < 200; ++i) {
        Program program = testing::randomProgram(random, false);
        for (int step = 0; step < 25; ++step) {
            const std::vector<NumberedRung> rungs = numberedRungs(program);
            const int count = static_cast<int>(rungs.size());
            const int number = pick(0, count + 1);
            // A path to some node of the rung's condition, or a bad one.
            ElementNodePath path;
            if (number >= 1 && number <= count &&
                rungs[static_cast<std::size_t>(number - 1)].rung->condition) {
                const Circuit* node = &*rungs[static_cast<std::size_t>(number - 1)].rung->condition;
                while (!node->isElement() && pick(0, 2) > 0) {
                    path.push_back(static_cast<std::size_t>(
                        pick(0, static_cast<int>(node->parts.size()) - 1)));
                    node = &node->parts[path.back()];
                }
            } else if (pick(0, 1) == 0) {
                path.push_back(static_cast<std::size_t>(pick(0, 3)));
            }
            Element element =
                contact(pick(0, 1) ? "I7" : "M3",
                        pick(0, 1) ? ElementKind::NormallyOpen : ElementKind::NormallyClosed);
            if (pick(0, 4) == 0) {
                element = Element();
                element.kind = pick(0, 2) == 0 ? ElementKind::Not
                               : pick(0, 1)    ? ElementKind::RisingEdge
                                               : ElementKind::FallingEdge;
            }
            // A whole circuit goes in as well as one element.
            const Circuit parallelPart = *readCondition(program, "I5 * (VW3 > 2) + /M1").circuit;
            const Program before = program;
            std::string refusal;
            switch (pick(0, 8)) {
            case 0:
                refusal = insertInSeries(program, number, path, Circuit::of(element),
                                         pick(0, 1) ? ladder::Side::Before : ladder::Side::After);
                break;
            case 1:
                refusal = insertInParallel(program, number, path,
                                           pick(0, 3) == 0 ? parallelPart : Circuit::of(element));
                break;
            case 2:
                refusal = removeElement(program, number, path);
                break;
            case 3:
                refusal = replaceNode(program, number, path,
                                      pick(0, 3) == 0 ? parallelPart : Circuit::of(element));
                break;
            case 4:
                refusal = moveRung(program, number, pick(0, 1) ? 1 : -1);
                break;
            case 5:
                refusal = removeRung(program, number);
                break;
            case 6:
                refusal =
                    count > 0
                        ? insertRung(program, number,
                                     *rungs[static_cast<std::size_t>(pick(0, count - 1))].line,
                                     pick(0, 1) == 0)
                        : insertRung(program, 0, rungLine(program, "Q1 = I1"));
                break;
            case 7:
                if (count > 0)
                    refusal = replaceRung(
                        program, number, *rungs[static_cast<std::size_t>(pick(0, count - 1))].line);
                break;
            default:
                if (count > 0)
                    refusal = replaceOutput(
                        program, number,
                        rungs[static_cast<std::size_t>(pick(0, count - 1))].rung->output);
                break;
            }
            if (!refusal.empty()) {
                ASSERT_EQ(program, before) << refusal;
                continue;
            }
            ++made;
            const std::string text = printProgram(program);
            const ProgramReading reading = readProgram(text);
            ASSERT_TRUE(reading.diagnostics.empty()) << text << reading.diagnostics.front().line
                                                     << ":" << reading.diagnostics.front().column
                                                     << ": " << reading.diagnostics.front().message;
            ASSERT_EQ(reading.program, program) << text;
        }
    }
    EXPECT_GT(made, 2000);
}

} // namespace
} // namespace rs::pl110
