// SPDX-License-Identifier: GPL-3.0-or-later
#include "lang/AddressSet.h"
#include "Sanitized.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

namespace {

using rs::lang::Address;
using rs::lang::AddressKind;
using rs::lang::AddressSet;

// Addresses from a small range, so that many are inserted twice, with now
// and then an invalid one.
Address randomAddress(std::mt19937& random) {
    auto uniform = [&random](int low, int high) {
        return std::uniform_int_distribution<int>(low, high)(random);
    };
    Address a;
    a.kind = static_cast<AddressKind>(uniform(0, static_cast<int>(AddressKind::Sequence)));
    a.unit = uniform(0, 3);
    a.index = uniform(0, 40);
    a.bit = uniform(-1, 2);
    a.asiB = uniform(0, 9) == 0;
    return a;
}

TEST(AddressSet, DoesWhatAnOrderedSetDoes) {
    for (unsigned seed = 1; seed <= rs::test::randomCases(50); ++seed) {
        std::mt19937 random(seed);
        AddressSet set;
        std::set<Address> reference;
        const int inserts = std::uniform_int_distribution<int>(0, 3000)(random);
        for (int i = 0; i < inserts; ++i) {
            const Address a = randomAddress(random);
            ASSERT_EQ(set.insert(a), reference.insert(a).second) << "seed " << seed;
            const Address asked = randomAddress(random);
            ASSERT_EQ(set.contains(asked), reference.count(asked) != 0) << "seed " << seed;
        }
        EXPECT_EQ(set.size(), reference.size());
        EXPECT_EQ(set.sorted(), std::vector<Address>(reference.begin(), reference.end()));
    }
}

TEST(AddressSet, AnEmptySetHoldsNothing) {
    const AddressSet set;
    EXPECT_FALSE(set.contains(Address{}));
    EXPECT_FALSE(set.contains(Address{AddressKind::Memory, 0, 1, -1, false}));
    EXPECT_TRUE(set.sorted().empty());
}

} // namespace
