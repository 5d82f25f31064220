// SPDX-License-Identifier: GPL-3.0-or-later
#include "ManualNetworks.h"
#include "NetworkPicture.h"
#include "StepText.h"
#include "ladder/UnitLadder.h"
#include "sim/Conduction.h"

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
    energised.statements[0] = {{2, 3}, true, {}};
    EXPECT_TRUE(isPoweredColour(
        strokeAt(rs::render::networkImage(layout, style, &energised), x, wireY, true).colour));

    PowerSnapshot otherStatement; // statement 0 did not run: its step was not active
    otherStatement.statements[1] = {{1, 2, 3}, true, {}};
    const QImage idle = rs::render::networkImage(layout, style, &otherStatement);
    EXPECT_TRUE(isInk(strokeAt(idle, before(2), wireY).colour));
    EXPECT_TRUE(isInk(strokeAt(idle, x, wireY, true).colour));
}

// Each element shows its own state apart from the power: filled when closed
// (a contact), true (a box) or 1 (an output's variable), whatever reaches it.
class ElementStates : public Conduction {
protected:
    static constexpr std::uint8_t kClosed = rs::sim::ElementState::Closed;

    // The fill at the middle of an element's symbol, between its bars.
    QColor fillOf(const QImage& image, std::uint16_t number) const {
        const QPointF c = element(layout, number).symbolRect.center();
        return image.pixelColor(static_cast<int>(c.x()), static_cast<int>(c.y()) + 4);
    }
    bool filled(const QImage& image, std::uint16_t number) const {
        return fillOf(image, number) == style.closedFill;
    }
};

TEST_F(ElementStates, AClosedContactWithNoPowerArrivingIsDrawnClosed) {
    PowerSnapshot power; // I0.0 open, I0.1 closed: no power reaches I0.1
    power.statements[0].states = {0, 0, 0, kClosed};
    const QImage live = rs::render::networkImage(layout, style, &power);
    EXPECT_FALSE(filled(live, 2));
    EXPECT_TRUE(filled(live, 3)) << "closed though no power reaches it";
    const Stroke left = strokeAt(live, before(3), wireY);
    EXPECT_TRUE(isInk(left.colour)) << "no power on its left wire";
    EXPECT_EQ(left.thickness,
              strokeAt(rs::render::networkImage(layout, style), before(3), wireY).thickness);
    EXPECT_TRUE(isInk(strokeAt(live, after(3), wireY).colour));
}

TEST_F(ElementStates, AnOpenContactReceivingPowerIsDrawnOpenWithPowerOnItsLeft) {
    PowerSnapshot power; // I0.0 closed and conducting, I0.1 open
    power.statements[0].conducting = {2};
    power.statements[0].states = {0, 0, kClosed, 0};
    const QImage live = rs::render::networkImage(layout, style, &power);
    EXPECT_TRUE(filled(live, 2));
    EXPECT_EQ(fillOf(live, 3), style.background) << "open: hollow";
    const Stroke left = strokeAt(live, before(3), wireY);
    EXPECT_TRUE(isPoweredColour(left.colour));
    EXPECT_GE(left.thickness, 4) << "power on its left, heavy";
    EXPECT_TRUE(isInk(strokeAt(live, after(3), wireY).colour));
}

TEST_F(ElementStates, AnOutputWhoseVariableIsOneIsDrawnOnWithItsRungOff) {
    PowerSnapshot power; // Q0.1 forced to 1 (or set elsewhere); nothing conducts
    power.statements[0].states = {kClosed, 0, 0, 0};
    const QImage live = rs::render::networkImage(layout, style, &power);
    EXPECT_TRUE(filled(live, 0));
    const ElementLayout& coil = element(layout, 0);
    EXPECT_TRUE(isInk(strokeAt(live, static_cast<int>(coil.symbolRect.left()) - 6, wireY).colour))
        << "the rung is off";

    PowerSnapshot off; // driven, but forced to 0: power, and the coil hollow
    off.statements[0] = {{1, 2, 3}, true, {0, 0, kClosed, kClosed}};
    const QImage forcedOff = rs::render::networkImage(layout, style, &off);
    EXPECT_EQ(fillOf(forcedOff, 0), style.background);
    EXPECT_TRUE(isPoweredColour(
        strokeAt(forcedOff, static_cast<int>(coil.symbolRect.left()) - 6, wireY).colour));
}

// In greyscale a filled symbol stands apart from a hollow one, and a powered
// wire from an unpowered one by its weight; in the dark theme's colours too.
TEST_F(ElementStates, StatesReadInGreyscale) {
    for (const bool dark : {false, true}) {
        LadderStyle look = style;
        if (dark) {
            look.background = QColor(30, 30, 30);
            look.ink = QColor(220, 220, 220);
            look.powered = QColor(70, 210, 110);
            look.closedFill = look.powered;
            look.closedInk = look.background;
        }
        PowerSnapshot power;
        power.statements[0].conducting = {2};
        power.statements[0].states = {0, 0, kClosed, 0};
        QImage grey = rs::render::networkImage(layout, look, &power)
                          .convertToFormat(QImage::Format_Grayscale8);
        const auto greyAt = [&](QPointF p) {
            return qGray(grey.pixel(static_cast<int>(p.x()), static_cast<int>(p.y()) + 4));
        };
        const int closedGrey = greyAt(element(layout, 2).symbolRect.center());
        const int openGrey = greyAt(element(layout, 3).symbolRect.center());
        EXPECT_GE(std::abs(closedGrey - openGrey), 80) << "dark " << dark;
    }
}

TEST(ElementStatesOfBoxes, ATrueComparisonIsFilledAndACountingTimerHasABar) {
    const NetworkLayout layout = layOut("Q0.1 = (R0.1 > 4) * TON(2s00)\n");
    const LadderStyle style{};
    PowerSnapshot power;
    power.statements[0].states = {0, 0, rs::sim::ElementState::Closed,
                                  rs::sim::ElementState::Running};
    const QImage live = rs::render::networkImage(layout, style, &power);
    const QRectF comparison = element(layout, 2).symbolRect;
    const QRectF timer = element(layout, 3).symbolRect;
    EXPECT_EQ(live.pixelColor(static_cast<int>(comparison.left()) + 4,
                              static_cast<int>(comparison.top()) + 4),
              style.closedFill);
    EXPECT_EQ(
        live.pixelColor(static_cast<int>(timer.left()) + 4, static_cast<int>(timer.top()) + 4),
        style.background)
        << "the timer's output is off";
    EXPECT_EQ(
        live.pixelColor(static_cast<int>(timer.center().x()), static_cast<int>(timer.bottom()) - 4),
        style.closedFill)
        << "it counts";
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
    power.statements[0] = {{1, 2}, false, {}};
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
