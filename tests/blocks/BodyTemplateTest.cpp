// SPDX-License-Identifier: GPL-3.0-or-later
#include "blocks/BodyTemplate.h"
#include "project/Utf8Text.h"

#include <gtest/gtest.h>

using namespace rs::blocks;

TEST(BodyTemplate, FindsPinAndPrivatePlaceholders) {
    const ScannedLine scanned = scanPlaceholders("S({#m1}) = {In} * /{Out}");
    ASSERT_FALSE(scanned.fault);
    ASSERT_EQ(scanned.placeholders.size(), 3u);
    EXPECT_EQ(scanned.placeholders[0].name, "m1");
    EXPECT_TRUE(scanned.placeholders[0].isPrivate);
    EXPECT_EQ(scanned.placeholders[0].offset, 2u);
    EXPECT_EQ(scanned.placeholders[0].length, 5u);
    EXPECT_EQ(scanned.placeholders[1].name, "In");
    EXPECT_FALSE(scanned.placeholders[1].isPrivate);
    EXPECT_EQ(scanned.placeholders[2].name, "Out");
}

TEST(BodyTemplate, ReportsMalformedPlaceholders) {
    EXPECT_EQ(scanPlaceholders("Q0.1 = {In").fault->offset, 10u);
    EXPECT_EQ(scanPlaceholders("Q0.1 = {}").fault->message, "empty placeholder");
    EXPECT_EQ(scanPlaceholders("Q0.1 = {#}").fault->message, "empty placeholder");
    EXPECT_EQ(scanPlaceholders("Q0.1 = {In Out}").fault->offset, 10u);
    EXPECT_EQ(scanPlaceholders("Q0.1 = In}").fault->offset, 9u);
}

TEST(BodyTemplate, SubstitutesAndMapsBackToTheTemplate) {
    const SubstitutedLine line = substitute(
        "{Out} = {In}", [](const Placeholder& p) { return p.name == "Out" ? "Q0.17" : "I0.0"; });
    EXPECT_EQ(line.text, "Q0.17 = I0.0");
    ASSERT_EQ(line.templateOffset.size(), line.text.size());
    EXPECT_EQ(line.templateOffset[0], 0u); // inside {Out}
    EXPECT_EQ(line.templateOffset[5], 5u); // the space after it
    EXPECT_EQ(line.templateOffset[8], 8u); // {In}
}

TEST(BodyTemplate, ColumnsCountCharactersNotBytes) {
    EXPECT_EQ(rs::project::characterColumn("åäö x", 7), 5);
    EXPECT_EQ(byteOffset("åäö x", 5), 7u);
    EXPECT_EQ(byteOffset("ab", 9), 2u);
}
