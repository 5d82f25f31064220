// SPDX-License-Identifier: GPL-3.0-or-later
#include "ladder/Cursor.h"

#include <gtest/gtest.h>

namespace {

using rs::ladder::Cursor;
using rs::ladder::ElementPath;

TEST(Cursor, NothingIsSelectedUntilANetworkIs) {
    const Cursor none{};
    EXPECT_FALSE(none.valid());
    EXPECT_FALSE(none.wholeNetwork());
    const Cursor network{1, 2, std::nullopt, std::nullopt, -1};
    EXPECT_TRUE(network.valid());
    EXPECT_TRUE(network.wholeNetwork());
    EXPECT_TRUE(network.sameNetwork(1, 2));
    EXPECT_FALSE(network.sameNetwork(2, 1));
}

TEST(Cursor, AnElementOrAnOutputIsPartOfItsNetwork) {
    const Cursor element{0, 3, ElementPath{1, {0, 2}}, std::nullopt, -1};
    EXPECT_TRUE(element.valid());
    EXPECT_FALSE(element.wholeNetwork());
    EXPECT_TRUE(element.sameNetwork(0, 3));
    const Cursor output{0, 3, std::nullopt, ElementPath{1, {}}, 0};
    EXPECT_FALSE(output.wholeNetwork());
    EXPECT_NE(element, output);
    EXPECT_EQ(output, (Cursor{0, 3, std::nullopt, ElementPath{1, {}}, 0}));
}

} // namespace
