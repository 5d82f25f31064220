// SPDX-License-Identifier: GPL-3.0-or-later
#include "RandomProgram.h"

#include "pl110/ProgramText.h"
#include "pl110/RungLayout.h"

#include <gtest/gtest.h>

#include <set>

namespace rs::pl110 {
namespace {

int leaves(const Circuit& circuit) {
    if (circuit.isElement())
        return 1;
    int count = 0;
    for (const Circuit& part : circuit.parts)
        count += leaves(part);
    return count;
}

Rung rungOf(std::string_view line) {
    const ProgramReading reading = readProgram("$target PL110\nMAIN\n" + std::string(line) + "\n");
    EXPECT_TRUE(reading.diagnostics.empty());
    return std::get<Rung>(reading.program.main.at(0).body);
}

TEST(Pl110RungLayout, DrawsEachElementAsItsShapeWithItsLabels) {
    const ladder::NetworkLayout layout =
        layoutRung(rungOf("TON(T1, 100ms, 50) = I1 * /I2 * P * (VW1>=3) + NOT"), {});
    ASSERT_EQ(layout.elements.size(), 6U);
    const auto& e = layout.elements;
    EXPECT_EQ(e[0].shape, ladder::Shape::Contact);
    EXPECT_EQ(e[0].address, QStringLiteral("I1"));
    EXPECT_EQ(e[1].mark, QStringLiteral("/"));
    EXPECT_EQ(e[2].mark, QStringLiteral("P"));
    EXPECT_EQ(e[3].shape, ladder::Shape::Box);
    EXPECT_EQ(e[3].text, QStringLiteral(">= 3"));
    EXPECT_EQ(e[3].address, QStringLiteral("VW1"));
    EXPECT_EQ(e[4].text, QStringLiteral("NOT"));
    EXPECT_EQ(e[5].text, QStringLiteral("TON 100ms"));
    EXPECT_EQ(e[5].address, QStringLiteral("T1 PT 50"));
    // The parallel branch with NOT stands below the series; the output at the right.
    EXPECT_EQ(e[4].row, 1);
    EXPECT_GT(e[5].cell.left(), e[3].cell.right() - 1);
    // Numbered in pre-order as the scan engine counts its edge memories: the
    // OR is 1, the AND 2, its elements 3.., NOT last.
    EXPECT_EQ(e[0].element, 3);
    EXPECT_EQ(e[4].element, 7);
}

TEST(Pl110RungLayout, RandomRungsLayOutWithoutOverlaps) {
    std::mt19937 random(22);
    for (int i = 0; i < 300; ++i) {
        const Program program = testing::randomProgram(random, false);
        for (const Line& line : program.main) {
            const auto* rung = std::get_if<Rung>(&line.body);
            if (!rung)
                continue;
            const ladder::NetworkLayout layout = layoutRung(*rung, {});
            const int expected = 1 + (rung->condition ? leaves(*rung->condition) : 0);
            ASSERT_EQ(static_cast<int>(layout.elements.size()), expected) << printProgram(program);
            std::set<std::pair<int, int>> cells;
            for (const auto& element : layout.elements) {
                for (int column = 0; column < element.columnSpan; ++column)
                    ASSERT_TRUE(cells.insert({element.row, element.column + column}).second)
                        << printProgram(program);
                ASSERT_TRUE(QRectF(QPointF(0, 0), layout.size).contains(element.cell));
            }
        }
    }
}

} // namespace
} // namespace rs::pl110
