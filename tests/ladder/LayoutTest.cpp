// SPDX-License-Identifier: GPL-3.0-or-later
#include "ladder/Layout.h"
#include "ManualNetworks.h"
#include "RandomProgram.h"
#include "StepText.h"
#include "compiler/Compiler.h"
#include "ladder/ElementVocabulary.h"
#include "ladder/TextToLadder.h"
#include "ladder/UnitLadder.h"

#include <gtest/gtest.h>

#include <set>
#include <tuple>

namespace {

using namespace rs::ladder;

struct Laid {
    rs::project::Project project;
    NetworkLayout layout;
};

// The first network of the PLC code of projectWithCode(body).
Laid layOut(const std::string& body, int network = 1) {
    Laid laid{rs::test::projectWithCode(body), {}};
    const auto pages = unitLadder(laid.project.program.units.front());
    const auto symbols = SymbolTable::of(laid.project.program, 0);
    LayoutContext context;
    context.number = network;
    context.firstStatement =
        pages.front().firstStatements.at(static_cast<std::size_t>(network - 1));
    context.symbols = &symbols;
    laid.layout = layoutNetwork(
        pages.front().ladder.networks.at(static_cast<std::size_t>(network - 1)), context);
    return laid;
}

const ElementLayout& find(const NetworkLayout& layout, std::uint16_t element, int output = -1) {
    for (const auto& e : layout.elements)
        if (e.element == element && e.output == output)
            return e;
    throw std::out_of_range("no element " + std::to_string(element));
}

const WireLayout& wireAt(const NetworkLayout& layout, QLineF line) {
    for (const auto& w : layout.wires)
        if (w.line == line || QLineF(w.line.p2(), w.line.p1()) == line)
            return w;
    throw std::out_of_range("no such wire");
}

TEST(Layout, TheMutingStartCircuitOnTheGrid) {
    const Laid laid = layOut("Q0.2 = I0.12 * (I0.13 + M0.0) * (P(I0.14) * I0.2 + Q0.2)\n");
    const NetworkLayout& l = laid.layout;
    EXPECT_EQ(l.conditionColumns, 4);
    EXPECT_EQ(l.outputColumns, 1);
    EXPECT_EQ(l.size, QSizeF(656, 186));
    // Pre-order numbers: 1 the whole series, 3 and 6 the parallel circuits, 7 a series branch.
    struct Expected {
        std::uint16_t element;
        int column, row;
        const char* address;
    };
    const Expected expected[] = {{2, 0, 0, "I0.12"}, {4, 1, 0, "I0.13"}, {5, 1, 1, "M0.0"},
                                 {8, 2, 0, "I0.14"}, {9, 3, 0, "I0.2"},  {10, 2, 1, "Q0.2"}};
    ASSERT_EQ(l.elements.size(), std::size(expected) + 1);
    for (const auto& x : expected) {
        const ElementLayout& e = find(l, x.element);
        EXPECT_EQ(e.column, x.column) << x.address;
        EXPECT_EQ(e.row, x.row) << x.address;
        EXPECT_EQ(e.cell, QRectF(8 + 128 * x.column, 34 + 72 * x.row, 128, 72)) << x.address;
        EXPECT_EQ(e.address, x.address);
        EXPECT_EQ(e.statement, 0U);
    }
    EXPECT_EQ(find(l, 8).kind, ElementKind::PositiveEdge);
    EXPECT_EQ(find(l, 2).symbolRect, QRectF(60, 57, 24, 26));
    EXPECT_EQ(find(l, 2).name, "EStop")
        << "the name comes from the table when the text uses the address";
    const ElementLayout& coil = find(l, 0, 0);
    EXPECT_EQ(coil.kind, ElementKind::Coil);
    EXPECT_EQ(coil.cell, QRectF(520, 34, 128, 72));
    EXPECT_EQ(coil.path.item, 0U);
    // The short branch Q0.2 is drawn out to the join, which any branch end powers.
    EXPECT_EQ(wireAt(l, QLineF(392, 142, 520, 142)).feed.elements, std::vector<std::uint16_t>{10});
    const WireLayout& join = wireAt(l, QLineF(520, 70, 520, 142));
    EXPECT_EQ(join.feed.kind, PowerFeed::Kind::Elements);
    EXPECT_EQ(join.feed.elements, (std::vector<std::uint16_t>{9, 10}));
    EXPECT_EQ(wireAt(l, QLineF(8, 34, 8, 178)).feed.kind, PowerFeed::Kind::Rail);
    EXPECT_TRUE(wireAt(l, QLineF(8, 34, 8, 178)).rail);
}

TEST(Layout, LabelsShowNameAndAddressAndWhatABoxDoes) {
    const Laid laid =
        layOut(";@network comment=\"Boxes\"\n(R0.1 += 77) = EStop * TON(2s5) * /TPS(R0.4) * "
               "(R0.98>=4) * P(/I0.3)\n");
    const NetworkLayout& l = laid.layout;
    EXPECT_EQ(find(l, 2).name, "EStop");
    EXPECT_EQ(find(l, 2).address, "I0.12");
    EXPECT_EQ(find(l, 3).text, "TON");
    EXPECT_EQ(find(l, 3).address, "2s50");
    EXPECT_FALSE(find(l, 3).negated);
    EXPECT_TRUE(find(l, 4).negated);
    EXPECT_EQ(find(l, 4).address, "R0.4");
    EXPECT_EQ(find(l, 5).kind, ElementKind::Comparison);
    EXPECT_EQ(find(l, 5).text, ">= 4");
    EXPECT_EQ(find(l, 5).address, "R0.98");
    EXPECT_EQ(find(l, 6).address, "/I0.3");
    const ElementLayout& box = find(l, 0, 0);
    EXPECT_EQ(box.kind, ElementKind::Arithmetic);
    EXPECT_EQ(box.text, "+= 77");
    EXPECT_EQ(box.address, "R0.1");
    EXPECT_EQ(l.texts.at(0).text, "Network 1");
    EXPECT_EQ(l.texts.at(1).role, TextLayout::Role::Comment);
    EXPECT_EQ(l.texts.at(1).text, "Boxes");
}

TEST(Layout, OutputsLineUpAtTheRightAndStackWhenARungHasSeveral) {
    const Laid laid = layOut(";@network comment=\"\"\nQ0.2 = I0.1 * I0.2 * I0.3   ; long one\n"
                             "Lamp = I0.4\nM0.0 = I0.4\n; a note\nJ(+1)\n");
    const NetworkLayout& l = laid.layout;
    EXPECT_EQ(l.conditionColumns, 3);
    std::vector<const ElementLayout*> outputs;
    for (const auto& e : l.elements)
        if (isOutput(e.kind))
            outputs.push_back(&e);
    ASSERT_EQ(outputs.size(), 4U);
    for (const auto* output : outputs)
        EXPECT_EQ(output->cell.left(), 8 + 3 * 128);
    EXPECT_EQ(outputs[0]->statement, 0U);
    EXPECT_EQ(outputs[1]->statement, 1U);
    EXPECT_EQ(outputs[2]->statement, 2U);
    EXPECT_EQ(outputs[3]->statement, 3U);
    // Lamp and M0.0 are one rung: stacked, sharing the condition of statement 1.
    EXPECT_EQ(outputs[1]->name, "Lamp");
    EXPECT_EQ(outputs[1]->address, "Q0.17");
    EXPECT_EQ(outputs[2]->cell.top(), outputs[1]->cell.bottom());
    EXPECT_EQ(outputs[2]->row, 1);
    EXPECT_EQ(outputs[2]->output, 1);
    EXPECT_EQ(find(l, 1).statement, 1U) << "I0.4, numbered in the rung's first statement";
    EXPECT_EQ(outputs[3]->kind, ElementKind::Jump);
    EXPECT_EQ(outputs[3]->address, "step +1");
    // The note stands between the rungs; the trailing comment beside its output.
    const auto note = std::find_if(l.texts.begin(), l.texts.end(), [](const TextLayout& t) {
        return t.role == TextLayout::Role::Note;
    });
    ASSERT_NE(note, l.texts.end());
    EXPECT_EQ(note->text, "a note");
    EXPECT_EQ(note->rect.top(), outputs[2]->cell.bottom());
    EXPECT_EQ(outputs[3]->cell.top(), note->rect.bottom());
    const auto comment = std::find_if(l.texts.begin(), l.texts.end(), [](const TextLayout& t) {
        return t.role == TextLayout::Role::OutputComment;
    });
    ASSERT_NE(comment, l.texts.end());
    EXPECT_EQ(comment->text, "long one");
    EXPECT_GT(comment->rect.left(), outputs[0]->cell.right());
    EXPECT_EQ(comment->rect.center().y(), outputs[0]->cell.center().y());
}

TEST(Layout, ANetworkWithoutRungsStillShowsItsTitleAndNotes) {
    const Laid laid = layOut(";@network comment=\"To do\"\n; nothing here yet\n");
    const NetworkLayout& l = laid.layout;
    EXPECT_TRUE(l.elements.empty());
    ASSERT_EQ(l.texts.size(), 3U);
    for (const auto& t : l.texts)
        EXPECT_TRUE(QRectF(QPointF(0, 0), l.size).contains(t.rect)) << t.text.toStdString();
    EXPECT_GE(l.size.width(), l.texts[0].rect.right());
}

TEST(Layout, AWideBoxTakesTwoColumns) {
    const Laid laid = layOut("(DR0.4 = DR0.6 * -2147483647) = (R0.1=R0.2)\n");
    const NetworkLayout& l = laid.layout;
    EXPECT_EQ(find(l, 1).columnSpan, 1);
    EXPECT_EQ(find(l, 0, 0).columnSpan, 2);
    EXPECT_EQ(find(l, 0, 0).text, "= DR0.6 * -2147483647");
    EXPECT_EQ(l.outputColumns, 2);
    EXPECT_EQ(find(l, 0, 0).cell.right(), l.size.width() - l.metrics.margin);
}

// The layout numbers elements exactly as the compiler numbers the
// instructions made from them, so the simulator's power reaches the right
// element: checked on every network of every manual example.
TEST(Layout, ElementNumbersAreTheCompilersInEveryManualExample) {
    using Key = std::tuple<int, std::uint32_t, std::uint16_t>; // station, statement, element
    int checked = 0;
    for (const auto& path : rs::test::manualExamples()) {
        const auto project = rs::test::readExample(path);
        const auto compiled = rs::compiler::compile(project);
        ASSERT_EQ(compiled.errors(), 0) << path;
        std::set<Key> instructions;
        for (const auto& image : compiled.images)
            for (const auto& in : image.code) {
                using rs::compiler::Op;
                const bool leaf = in.op == Op::Contact || in.op == Op::Edge || in.op == Op::Timer ||
                                  in.op == Op::Compare;
                const bool output = in.op >= Op::Coil;
                if (leaf || output)
                    instructions.insert({image.station, in.statement, in.element});
            }
        std::set<Key> drawn;
        for (const auto& network : rs::test::layOutEveryNetwork(project))
            for (const auto& e : network.layout.elements)
                drawn.insert({network.station, e.statement, e.element});
        EXPECT_EQ(drawn, instructions) << path;
        checked += static_cast<int>(drawn.size());
    }
    EXPECT_GT(checked, 300);
}

// Everything lies inside the picture, and no two elements share a cell.
TEST(Layout, NothingIsClippedOrOverlapsInAnyManualExample) {
    int networks = 0;
    for (const auto& path : rs::test::manualExamples())
        for (const auto& network : rs::test::layOutEveryNetwork(rs::test::readExample(path))) {
            const QRectF picture(QPointF(0, 0), network.layout.size);
            const std::string where = path.filename().string() + " " + network.describe();
            for (const auto& e : network.layout.elements) {
                EXPECT_TRUE(picture.contains(e.cell)) << where;
                EXPECT_TRUE(e.cell.contains(e.symbolRect)) << where;
                EXPECT_TRUE(e.cell.contains(e.nameRect)) << where;
                EXPECT_TRUE(e.cell.contains(e.addressRect)) << where;
                EXPECT_FALSE(e.nameRect.intersects(e.symbolRect)) << where;
                EXPECT_FALSE(e.addressRect.intersects(e.symbolRect)) << where;
                for (const auto& other : network.layout.elements) {
                    if (&other != &e) {
                        EXPECT_FALSE(e.cell.intersects(other.cell)) << where;
                    }
                }
            }
            for (const auto& w : network.layout.wires) {
                EXPECT_TRUE(picture.contains(w.line.p1())) << where;
                EXPECT_TRUE(picture.contains(w.line.p2())) << where;
            }
            for (const auto& t : network.layout.texts)
                EXPECT_TRUE(picture.contains(t.rect)) << where;
            ++networks;
        }
    EXPECT_GT(networks, 150);
}

} // namespace

// An edit above a network moves it (issue 23): its layout moved to another
// number and first statement is the layout made there, for random networks.
TEST(Layout, ANetworkMovedIsLaidOutAsIfLaidOutWhereItIsNow) {
    int networks = 0;
    for (unsigned seed = 1; seed <= 150; ++seed) {
        rs::test::RandomProgram program(seed);
        for (const auto& unit : program.document().units)
            for (const auto& step : unit.steps)
                for (const auto& network : toLadder(step).networks) {
                    LayoutContext from;
                    from.number = static_cast<int>(seed % 7) + 1;
                    from.firstStatement = seed * 3;
                    LayoutContext to;
                    to.number = from.number + 12;
                    to.firstStatement = seed * 3 + seed % 5 * 100;
                    if (seed % 3 == 0)
                        to.title = QStringLiteral("Netzwerk %1").arg(to.number);
                    NetworkLayout moved = layoutNetwork(network, from);
                    moveLayout(moved, from, to);
                    ASSERT_EQ(moved, layoutNetwork(network, to)) << "seed " << seed;
                    ++networks;
                }
    }
    EXPECT_GT(networks, 300);
}
