// SPDX-License-Identifier: GPL-3.0-or-later
#include "ladder/CursorNavigation.h"
#include "StepText.h"
#include "ladder/UnitLadder.h"

#include <gtest/gtest.h>

#include <deque>

namespace {

using namespace rs::ladder;

// Every network of a unit's PLC code laid out, to be arranged into steps.
class CursorNavigationTest : public ::testing::Test {
protected:
    void layOut(const std::string& body) {
        project = rs::test::projectWithCode(body);
        const auto pages = unitLadder(project.program.units.front());
        const auto symbols = SymbolTable::of(project.program, 0);
        const StepPage& page = pages.front();
        for (std::size_t n = 0; n < page.ladder.networks.size(); ++n) {
            LayoutContext context;
            context.number = static_cast<int>(n) + 1;
            context.firstStatement = page.firstStatements[n];
            context.symbols = &symbols;
            layouts.push_back(layoutNetwork(page.ladder.networks[n], context));
        }
    }

    // The laid-out networks, `counts[s]` of them in step s.
    LaidOutPage arranged(const std::vector<int>& counts) const {
        LaidOutPage page;
        std::size_t next = 0;
        for (int count : counts) {
            page.emplace_back();
            for (int n = 0; n < count; ++n)
                page.back().push_back({&layouts.at(next++), false});
        }
        return page;
    }

    // The cursor on the element with this address (a contact, or the output),
    // which stands in network `network` of step `step`.
    Cursor on(int step, int network, const QString& address, bool output = false) const {
        for (const auto& layout : layouts)
            for (const auto& element : layout.elements)
                if (element.address == address && (element.output >= 0) == output)
                    return cursorOn(step, network, element);
        ADD_FAILURE() << "no element " << address.toStdString();
        return {};
    }

    rs::project::Project project;
    std::deque<NetworkLayout> layouts;
};

Cursor whole(int step, int network) {
    return {step, network, std::nullopt, std::nullopt, -1};
}

TEST_F(CursorNavigationTest, WithoutASelectionAnyMoveSelectsTheFirstNetwork) {
    layOut("Q0.2 = I0.1\nQ0.3 = I0.2\n");
    const LaidOutPage page = arranged({2});
    for (CursorMove move : {CursorMove::Left, CursorMove::Right, CursorMove::Up, CursorMove::Down})
        EXPECT_EQ(movedCursor(page, {}, move), whole(0, 0));
    EXPECT_EQ(movedCursor(LaidOutPage{}, {}, CursorMove::Down), std::nullopt);
    EXPECT_EQ(movedCursor(LaidOutPage{{}}, {}, CursorMove::Down), std::nullopt);
}

TEST_F(CursorNavigationTest, RightOrDownEntersANetworkAtItsFirstElement) {
    layOut("Q0.2 = I0.1 * I0.2\n");
    const LaidOutPage page = arranged({1});
    EXPECT_EQ(movedCursor(page, whole(0, 0), CursorMove::Right), on(0, 0, "I0.1"));
    EXPECT_EQ(movedCursor(page, whole(0, 0), CursorMove::Down), on(0, 0, "I0.1"));
    EXPECT_EQ(movedCursor(page, whole(0, 0), CursorMove::Left), std::nullopt);
}

TEST_F(CursorNavigationTest, RightWalksTheSeriesToTheOutputAndStopsThere) {
    layOut("Q0.2 = I0.1 * I0.2 * I0.3\n");
    const LaidOutPage page = arranged({1});
    EXPECT_EQ(movedCursor(page, on(0, 0, "I0.1"), CursorMove::Right), on(0, 0, "I0.2"));
    EXPECT_EQ(movedCursor(page, on(0, 0, "I0.2"), CursorMove::Right), on(0, 0, "I0.3"));
    EXPECT_EQ(movedCursor(page, on(0, 0, "I0.3"), CursorMove::Right), on(0, 0, "Q0.2", true));
    EXPECT_EQ(movedCursor(page, on(0, 0, "Q0.2", true), CursorMove::Right), std::nullopt);
    EXPECT_EQ(movedCursor(page, on(0, 0, "Q0.2", true), CursorMove::Left), on(0, 0, "I0.3"));
    EXPECT_EQ(movedCursor(page, on(0, 0, "I0.1"), CursorMove::Left), std::nullopt);
}

TEST_F(CursorNavigationTest, UpAndDownChangeBranchesWithinAParallelCircuit) {
    layOut("Q0.2 = (I0.1 + I0.2 + I0.3) * I0.4\n");
    const LaidOutPage page = arranged({1});
    EXPECT_EQ(movedCursor(page, on(0, 0, "I0.1"), CursorMove::Down), on(0, 0, "I0.2"));
    EXPECT_EQ(movedCursor(page, on(0, 0, "I0.2"), CursorMove::Down), on(0, 0, "I0.3"));
    EXPECT_EQ(movedCursor(page, on(0, 0, "I0.3"), CursorMove::Up), on(0, 0, "I0.2"));
    // From a lower branch, right goes along that branch's row only: nothing there.
    EXPECT_EQ(movedCursor(page, on(0, 0, "I0.2"), CursorMove::Right), std::nullopt);
    EXPECT_EQ(movedCursor(page, on(0, 0, "I0.1"), CursorMove::Right), on(0, 0, "I0.4"));
}

TEST_F(CursorNavigationTest, UpFromTheTopRowSelectsTheNetworkAndThenThePreviousOne) {
    layOut("Q0.2 = I0.1\nQ0.3 = I0.2\n");
    const LaidOutPage page = arranged({2});
    EXPECT_EQ(movedCursor(page, on(0, 1, "I0.2"), CursorMove::Up), whole(0, 1));
    EXPECT_EQ(movedCursor(page, whole(0, 1), CursorMove::Up), whole(0, 0));
    // Above the first network there is nothing: the selection stays.
    EXPECT_EQ(movedCursor(page, whole(0, 0), CursorMove::Up), whole(0, 0));
}

TEST_F(CursorNavigationTest, DownFromTheBottomRowGoesToTheNextNetworkAcrossSteps) {
    layOut("Q0.2 = I0.1\nQ0.3 = I0.2\nQ0.4 = I0.3\n");
    // Step 1 has no networks: it is passed over.
    const LaidOutPage page = arranged({2, 0, 1});
    EXPECT_EQ(movedCursor(page, on(0, 0, "I0.1"), CursorMove::Down), whole(0, 1));
    EXPECT_EQ(movedCursor(page, whole(0, 1), CursorMove::Down), on(0, 1, "I0.2"));
    EXPECT_EQ(movedCursor(page, on(0, 1, "I0.2"), CursorMove::Down), whole(2, 0));
    EXPECT_EQ(movedCursor(page, whole(2, 0), CursorMove::Up), whole(0, 1));
    // Below the last network the element stays selected.
    EXPECT_EQ(movedCursor(page, on(2, 0, "I0.3"), CursorMove::Down), on(2, 0, "I0.3"));
}

TEST_F(CursorNavigationTest, ACollapsedNetworkIsPassedOverDownwards) {
    layOut("Q0.2 = I0.1\nQ0.3 = I0.2\n");
    LaidOutPage page = arranged({2});
    page[0][0].collapsed = true;
    EXPECT_EQ(movedCursor(page, whole(0, 0), CursorMove::Down), whole(0, 1));
    EXPECT_EQ(movedCursor(page, whole(0, 0), CursorMove::Right), std::nullopt);
}

TEST_F(CursorNavigationTest, OutSelectsTheEnclosingGroupAndNetworkTheWholeNetwork) {
    layOut("Q0.2 = I0.1 * (I0.2 + I0.3)\n");
    const LaidOutPage page = arranged({1});
    const Cursor contact = on(0, 0, "I0.2");
    ASSERT_TRUE(contact.node);
    const auto group = movedCursor(page, contact, CursorMove::Out);
    ASSERT_TRUE(group && group->node);
    EXPECT_EQ(group->node->node.size() + 1, contact.node->node.size());
    // Left from the group goes by the group's cells: to the contact before it.
    EXPECT_EQ(movedCursor(page, *group, CursorMove::Left), on(0, 0, "I0.1"));
    Cursor root = *group;
    while (auto out = movedCursor(page, root, CursorMove::Out))
        root = *out;
    EXPECT_TRUE(root.node && root.node->node.empty());
    EXPECT_EQ(movedCursor(page, on(0, 0, "Q0.2", true), CursorMove::Out), std::nullopt);
    EXPECT_EQ(movedCursor(page, contact, CursorMove::Network), whole(0, 0));
    EXPECT_EQ(movedCursor(page, {}, CursorMove::Network), std::nullopt);
}

TEST_F(CursorNavigationTest, TheElementUnderTheCursorAndAGroupsCells) {
    layOut("Q0.2 = I0.1 * (I0.2 + I0.3)\n");
    const NetworkLayout& layout = layouts.front();
    const Cursor contact = on(0, 0, "I0.3");
    const ElementLayout* under = elementUnder(layout, contact);
    ASSERT_NE(under, nullptr);
    EXPECT_EQ(under->address, QStringLiteral("I0.3"));
    EXPECT_EQ(elementUnder(layout, whole(0, 0)), nullptr);
    Cursor group = contact;
    group.node->node.pop_back();
    EXPECT_EQ(elementUnder(layout, group), nullptr);
    const QRectF cells = groupCell(layout, *group.node);
    EXPECT_TRUE(cells.contains(under->cell));
    EXPECT_TRUE(cells.contains(elementUnder(layout, on(0, 0, "I0.2"))->cell));
    EXPECT_FALSE(cells.contains(elementUnder(layout, on(0, 0, "I0.1"))->cell));
}

} // namespace
