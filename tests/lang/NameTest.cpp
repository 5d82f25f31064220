// SPDX-License-Identifier: GPL-3.0-or-later
#include "lang/Name.h"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <string>
#include <thread>
#include <vector>

using rs::lang::Name;

TEST(Name, OneSpellingIsHeldOnceAndNamesOfItAreEqual) {
    const std::string written = "GuardOk577";
    const Name a(written);
    const Name b("GuardOk577");
    EXPECT_EQ(a, b);
    EXPECT_EQ(a.c_str(), b.c_str()) << "the two share one spelling";
    EXPECT_EQ(a.str(), written);
    EXPECT_NE(a, Name("GuardOk578"));
    EXPECT_NE(a, Name("guardok577")) << "spelling, not the folded name";
    EXPECT_EQ(a, "GuardOk577");
}

TEST(Name, TheEmptyNameIsTheDefault) {
    EXPECT_TRUE(Name().empty());
    EXPECT_EQ(Name(""), Name());
    EXPECT_EQ(Name().str(), "");
    EXPECT_EQ(Name().size(), 0u);
    EXPECT_FALSE(Name("x").empty());
}

TEST(Name, ReadsAsItsString) {
    const Name name("Lamp");
    EXPECT_EQ("'" + name + "'", "'Lamp'");
    EXPECT_EQ(name + ".Lo", "Lamp.Lo");
    EXPECT_EQ(std::string("the ") + name, "the Lamp");
    const std::string_view view = name;
    EXPECT_EQ(view, "Lamp");
    EXPECT_LT(Name("Alpha"), Name("Beta"));
    EXPECT_GT(Name("b"), Name("B"));
}

// Many spellings land in the same slot of a thread's table of recent ones;
// each still comes back as itself.
TEST(Name, EverySpellingComesBackAsItself) {
    std::mt19937 random(23);
    std::map<std::string, const char*> first;
    for (int i = 0; i < 20000; ++i) {
        std::string text(1 + random() % 20, ' ');
        for (char& c : text)
            c = static_cast<char>('A' + random() % 6);
        const Name name(text);
        ASSERT_EQ(name.str(), text);
        const auto [at, added] = first.emplace(text, name.c_str());
        ASSERT_EQ(at->second, name.c_str()) << text;
    }
}

// The IDE's workers parse while the window does: every thread gets the one
// spelling of a name.
TEST(Name, ThreadsShareOneSpellingOfEachName) {
    constexpr int kThreads = 4;
    constexpr int kNames = 3000;
    std::vector<std::vector<const char*>> seen(kThreads);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
        threads.emplace_back([&seen, t] {
            for (int round = 0; round < 3; ++round)
                for (int k = 0; k < kNames; ++k) {
                    const int n = (k * 7 + t * 101) % kNames;
                    const Name name("Shared" + std::to_string(n));
                    if (round == 2)
                        seen[t].push_back(name.c_str());
                }
        });
    for (auto& thread : threads)
        thread.join();
    for (int t = 0; t < kThreads; ++t)
        for (int k = 0; k < kNames; ++k) {
            const int n = (k * 7 + t * 101) % kNames;
            ASSERT_EQ(seen[t][k], Name("Shared" + std::to_string(n)).c_str());
        }
}
