// SPDX-License-Identifier: GPL-3.0-or-later
#include "ManualNetworks.h"
#include "NetworkPicture.h"
#include "StepText.h"
#include "ladder/UnitLadder.h"

#include <QFontMetricsF>
#include <QSvgRenderer>

#include <gtest/gtest.h>

namespace {

using namespace rs::ladder;
using rs::render::LadderStyle;
using rs::render::PowerSnapshot;

NetworkLayout layOut(const std::string& body) {
    const auto project = rs::test::projectWithCode(body);
    const auto symbols = SymbolTable::of(project.program, 0);
    LayoutContext context;
    context.symbols = &symbols;
    return layoutNetwork(unitLadder(project.program.units.front()).front().ladder.networks.front(),
                         context);
}

const ElementLayout& element(const NetworkLayout& layout, std::uint16_t number) {
    for (const auto& e : layout.elements)
        if (e.element == number && e.output < 1)
            return e;
    throw std::out_of_range("no element");
}

// What a line looks like where it crosses a column of pixels near y.
struct Stroke {
    int thickness = 0; // pixels that are not background
    QColor colour;     // the strongest of them
};

Stroke strokeAt(const QImage& image, int x, int y, bool vertical = false) {
    Stroke stroke;
    int strongest = 0;
    for (int d = -8; d <= 8; ++d) {
        const QColor c = vertical ? image.pixelColor(x + d, y) : image.pixelColor(x, y + d);
        const int distance = 3 * 255 - c.red() - c.green() - c.blue();
        if (distance > 40)
            ++stroke.thickness;
        if (distance > strongest) {
            strongest = distance;
            stroke.colour = c;
        }
    }
    return stroke;
}

bool isPoweredColour(const QColor& c) {
    return c.green() > c.red() + 60 && c.green() > c.blue() + 40;
}

bool isInk(const QColor& c) {
    return std::abs(c.red() - c.green()) < 20 && std::abs(c.green() - c.blue()) < 20;
}

class Conduction : public ::testing::Test {
protected:
    const NetworkLayout layout = layOut("Q0.1 = I0.0 * I0.1\n");
    const LadderStyle style{};
    const int wireY = static_cast<int>(element(layout, 2).cell.center().y());

    // x of the wire in front of an element's symbol, and behind it.
    int before(std::uint16_t number) const {
        const auto& e = element(layout, number);
        return static_cast<int>((e.cell.left() + e.symbolRect.left()) / 2);
    }
    int after(std::uint16_t number) const {
        const auto& e = element(layout, number);
        return static_cast<int>((e.symbolRect.right() + e.cell.right()) / 2);
    }
};

TEST_F(Conduction, ConductingWiresDifferInColourAndWeight) {
    PowerSnapshot power;
    power.statements[0].conducting = {2}; // I0.0 closed, I0.1 open
    const QImage still = rs::render::networkImage(layout, style);
    const QImage live = rs::render::networkImage(layout, style, &power);

    const Stroke off = strokeAt(still, before(2), wireY);
    const Stroke on = strokeAt(live, before(2), wireY);
    EXPECT_TRUE(isInk(off.colour));
    EXPECT_TRUE(isPoweredColour(on.colour));
    EXPECT_GE(on.thickness, off.thickness + 2) << "readable without colour";

    EXPECT_TRUE(isPoweredColour(strokeAt(live, after(2), wireY).colour)) << "I0.0 conducts";
    EXPECT_TRUE(isPoweredColour(strokeAt(live, before(3), wireY).colour));
    const Stroke blocked = strokeAt(live, after(3), wireY);
    EXPECT_TRUE(isInk(blocked.colour)) << "I0.1 does not conduct";
    EXPECT_EQ(blocked.thickness, off.thickness);
    // The contact that conducts is drawn powered, the other one not.
    const auto bar = [&](std::uint16_t n) {
        return strokeAt(live, static_cast<int>(element(layout, n).symbolRect.left()), wireY - 8,
                        true);
    };
    EXPECT_TRUE(isPoweredColour(bar(2).colour));
    EXPECT_TRUE(isInk(bar(3).colour));
}

TEST_F(Conduction, AnEnergisedOutputIsDrawnPoweredAndAStatementThatDidNotRunIsNot) {
    const ElementLayout& coil = element(layout, 0);
    const int x = static_cast<int>(coil.symbolRect.left()) + 1;
    PowerSnapshot energised;
    energised.statements[0] = {{2, 3}, true};
    EXPECT_TRUE(isPoweredColour(
        strokeAt(rs::render::networkImage(layout, style, &energised), x, wireY, true).colour));

    PowerSnapshot otherStatement; // statement 0 did not run: its step was not active
    otherStatement.statements[1] = {{1, 2, 3}, true};
    const QImage idle = rs::render::networkImage(layout, style, &otherStatement);
    EXPECT_TRUE(isInk(strokeAt(idle, before(2), wireY).colour));
    EXPECT_TRUE(isInk(strokeAt(idle, x, wireY, true).colour));
}

TEST(ConductionJoin, AParallelCircuitConductsWhenAnyBranchDoes) {
    const NetworkLayout layout = layOut("Q0.1 = (I0.0 + I0.1) * I0.2\n");
    PowerSnapshot power;
    power.statements[0].conducting = {4}; // only the lower branch, I0.1
    const QImage live = rs::render::networkImage(layout, LadderStyle{}, &power);
    const ElementLayout& upper = element(layout, 3);
    const ElementLayout& lower = element(layout, 4);
    const int joinX = static_cast<int>(upper.cell.right());
    const int middle = static_cast<int>((upper.cell.center().y() + lower.cell.center().y()) / 2);
    EXPECT_TRUE(isPoweredColour(strokeAt(live, joinX, middle, true).colour));
    EXPECT_TRUE(isInk(strokeAt(live, static_cast<int>(upper.symbolRect.right()) + 6,
                               static_cast<int>(upper.cell.center().y()))
                          .colour));
}

TEST(Svg, IsAValidDocumentWithNamesAddressesAndThePoweredStyle) {
    const NetworkLayout layout = layOut("Q0.1 = EStop * TON(2s50)\n");
    PowerSnapshot power;
    power.statements[0] = {{1, 2}, false};
    const QByteArray svg = rs::render::networkSvg(layout, LadderStyle{}, &power, "net");
    QSvgRenderer renderer(svg);
    ASSERT_TRUE(renderer.isValid());
    EXPECT_EQ(renderer.viewBoxF(), QRectF(QPointF(0, 0), layout.size));
    for (const char* text : {"EStop", "I0.12", "TON", "2s50", "Q0.1", "Network 1"})
        EXPECT_TRUE(svg.contains(text)) << text;
    EXPECT_TRUE(svg.contains("#00963c")) << "the powered colour";
    EXPECT_FALSE(rs::render::networkSvg(layout, LadderStyle{}).contains("#00963c"));
}

// Every contact and coil carries the mark its kind has in the vocabulary.
TEST(Svg, ContactsAndCoilsShowTheirKindsMark) {
    struct Case {
        const char* code;
        std::vector<const char*> marks;
    };
    const Case cases[] = {
        {"S(Q0.1) = P(I0.0) * /P(I0.2) * /N(I0.3) * /I0.4 * N(I0.1)\n",
         {">S<", ">P<", ">/P<", ">/N<", ">N<"}},
        {"R(Q0.1) = I0.0\n", {">R<"}},
        {"T(Q0.1) = I0.0\n", {">T<"}},
    };
    for (const auto& c : cases) {
        const QByteArray svg = rs::render::networkSvg(layOut(c.code), LadderStyle{}, nullptr, "n");
        for (const char* mark : c.marks)
            EXPECT_EQ(svg.count(mark), 1) << c.code << mark;
        EXPECT_FALSE(svg.contains(">/<")) << c.code << " a slash is drawn, not written";
    }
}

TEST(Pictures, TheFileNameSaysTheFormat) {
    EXPECT_TRUE(rs::render::isPictureFileName("a/b.svg"));
    EXPECT_TRUE(rs::render::isPictureFileName("B.PNG"));
    EXPECT_FALSE(rs::render::isPictureFileName("b.pdf"));
    const NetworkLayout layout = layOut("Q0.1 = I0.0\n");
    EXPECT_FALSE(rs::render::writeNetworkPicture("/tmp/x.jpg", layout, {}).isEmpty());
    EXPECT_FALSE(rs::render::writeNetworkPicture("/nonexistent-dir/x.png", layout, {}).isEmpty());
}

// Every network of every manual example draws, as PNG and as SVG, and every
// name, address and box text fits its place without being shortened.
TEST(ManualExamples, EveryNetworkRendersWithReadableLabels) {
    const LadderStyle style{};
    const QFontMetricsF names(style.font(style.labelPixelSize, true));
    const QFontMetricsF addresses(style.font(style.labelPixelSize));
    const QFontMetricsF boxes(style.font(style.textPixelSize, true));
    int drawn = 0;
    for (const auto& path : rs::test::manualExamples())
        for (const auto& network : rs::test::layOutEveryNetwork(rs::test::readExample(path))) {
            const std::string where = path.filename().string() + " " + network.describe();
            const QImage image = rs::render::networkImage(network.layout, style, nullptr, 2);
            ASSERT_FALSE(image.isNull()) << where;
            EXPECT_EQ(image.width(), static_cast<int>(std::ceil(network.layout.size.width() * 2)));
            QSvgRenderer svg(rs::render::networkSvg(network.layout, style));
            EXPECT_TRUE(svg.isValid()) << where;
            for (const auto& e : network.layout.elements) {
                EXPECT_LE(names.horizontalAdvance(e.name), e.nameRect.width()) << where;
                EXPECT_LE(addresses.horizontalAdvance(e.address), e.addressRect.width()) << where;
                EXPECT_LE(boxes.horizontalAdvance(e.text), e.symbolRect.width() - 6) << where;
            }
            ++drawn;
        }
    EXPECT_GT(drawn, 150);
}

} // namespace
