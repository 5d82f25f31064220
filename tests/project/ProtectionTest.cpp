// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProjectText.h"
#include "project/ProjectFile.h"
#include "project/ProtectedText.h"
#include "project/ProtectionKeys.h"

#include <gtest/gtest.h>

#include <random>

namespace {

using namespace rs::project;

const char* const kPress = "$name Press\n"
                           "! id_pluto:00=000034AD4AE1\n"
                           "! pgm_pluto:00\n"
                           "S0.0_0\n"
                           ";@network comment=\"Door switch fitted\" option=\"on\"\n"
                           "S(M0.5)\n"
                           ";@network comment=\"Light curtain fitted\" option=\"off\"\n"
                           "R(M0.6)\n"
                           ";@network comment=\"Both outputs\"\n"
                           "Q0.0 = I0.0 * M0.5\n"
                           "Q0.1 = I0.1 * (M0.6 + I0.2)\n"
                           "M0.7 = I0.3\n";

// The project protected with `options`, sealed by the keys it was protected with.
struct Sealed {
    std::string text;
    Keyring keys;
};

Sealed protectPress(OptionsAccess options, const char* optionsPassword = "") {
    Project project = projectFrom(kPress);
    NewProtection fresh = protectWith("machine-7 main", options, optionsPassword);
    project.protection = fresh.record;
    return {sealProjectText(writeProject(project), fresh.keys), fresh.keys};
}

int lineOf(const std::string& text, const std::string& what) {
    const auto at = text.find(what);
    EXPECT_NE(at, std::string::npos) << what;
    return 1 +
           static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    text.replace(text.find(from), from.size(), to);
    return text;
}

TEST(Protection, ASealedFileVerifiesReadsBackAndHoldsNoPassword) {
    const Sealed sealed = protectPress(OptionsAccess::Own, "options-12");
    EXPECT_EQ(verifyProjectText(sealed.text), std::nullopt);
    EXPECT_EQ(sealed.text.find("machine-7"), std::string::npos);
    EXPECT_EQ(sealed.text.find("options-12"), std::string::npos);
    const ProjectReadResult read = readProject(sealed.text);
    ASSERT_TRUE(read.ok());
    ASSERT_TRUE(read.project.protection.has_value());
    EXPECT_EQ(read.project.protection->options, OptionsAccess::Own);
    // The record sits after $name and is written back as it was read.
    EXPECT_EQ(lineOf(sealed.text, ";@protected"), 2);
    EXPECT_EQ(writeProject(read.project), sealed.text);
}

TEST(Protection, EachPasswordOpensWhatTheManualSays) {
    const Project own = projectFrom(protectPress(OptionsAccess::Own, "options-12").text);
    const Protection& record = *own.protection;
    EXPECT_TRUE(unlock(record, Permission::Full, "machine-7 main"));
    EXPECT_FALSE(unlock(record, Permission::Full, "options-12"));
    EXPECT_FALSE(unlock(record, Permission::Full, ""));
    EXPECT_TRUE(unlock(record, Permission::Configure, "options-12"));
    EXPECT_TRUE(unlock(record, Permission::Configure, "machine-7 main"));
    EXPECT_FALSE(unlock(record, Permission::Configure, "wrong"));
    EXPECT_TRUE(unlock(record, Permission::ReadOnly, ""));

    const Project main = projectFrom(protectPress(OptionsAccess::Main).text);
    EXPECT_TRUE(needsPassword(*main.protection, Permission::Configure));
    EXPECT_TRUE(unlock(*main.protection, Permission::Configure, "machine-7 main"));
    EXPECT_FALSE(unlock(*main.protection, Permission::Configure, ""));

    const Project free = projectFrom(protectPress(OptionsAccess::Free).text);
    EXPECT_FALSE(needsPassword(*free.protection, Permission::Configure));
    EXPECT_TRUE(needsPassword(*free.protection, Permission::Full));
    EXPECT_TRUE(unlock(*free.protection, Permission::Configure, ""));
}

TEST(Protection, AnyLineChangedByHandIsReportedAtThatLine) {
    const Sealed sealed = protectPress(OptionsAccess::Main);
    const std::string& text = sealed.text;
    const auto changedAt = [&](const std::string& changed) {
        const auto error = verifyProjectText(changed);
        return error ? error->line : 0;
    };
    EXPECT_EQ(changedAt(replaced(text, "I0.1 * (M0.6", "I0.1 * (M0.4")),
              lineOf(text, "Q0.1 = I0.1"));
    EXPECT_EQ(changedAt(replaced(text, "M0.7 = I0.3\n", "M0.7 = I0.3\nQ0.3 = I0.4\n")),
              lineOf(text, "M0.7 = I0.3") + 1);
    EXPECT_EQ(changedAt(replaced(text, "Q0.0 = I0.0 * M0.5\n", "")), lineOf(text, "Q0.0 ="));
    EXPECT_EQ(changedAt(replaced(text, "$name Press", "$name Presse")), 1);
    // An option switched by hand is a change too: nobody signed its new state.
    EXPECT_EQ(changedAt(replaced(replaced(text, "option=\"on\"", "option=\"off\""), "S(M0.5)",
                                 "R(M0.5)")),
              lineOf(text, "option=\"on\""));
    // Removing the last line.
    std::string shorter = text.substr(0, text.size() - 1);
    shorter = shorter.substr(0, shorter.rfind('\n') + 1);
    EXPECT_EQ(changedAt(shorter), lineOf(text, "Q0.1 = I0.1"));
}

TEST(Protection, RandomHandEditsAreFoundAtTheFirstLineTheyTouch) {
    const Sealed sealed = protectPress(OptionsAccess::Own, "o");
    std::vector<std::string> lines;
    for (std::size_t start = 0; start < sealed.text.size();) {
        const auto end = sealed.text.find('\n', start);
        lines.push_back(sealed.text.substr(start, end - start));
        start = end + 1;
    }
    const int record = lineOf(sealed.text, ";@protected") - 1;
    std::mt19937 random(7);
    for (int round = 0; round < 200; ++round) {
        std::vector<std::string> edited = lines;
        int at = 0;
        do
            at = static_cast<int>(random() % lines.size());
        while (at == record);
        switch (random() % 3) {
        case 0:
            edited[static_cast<std::size_t>(at)] += " ";
            break;
        case 1:
            edited.insert(edited.begin() + at, "M0.9 = I0.9");
            break;
        default:
            edited.erase(edited.begin() + at);
        }
        std::string text;
        for (const auto& line : edited)
            text += line + '\n';
        const auto error = verifyProjectText(text);
        ASSERT_TRUE(error.has_value()) << round;
        // A removed last line is reported at the line that is last now.
        const int expected = std::min(at, static_cast<int>(edited.size()) - 1) + 1;
        EXPECT_EQ(error->line, expected) << "round " << round << " at " << at;
        EXPECT_EQ(error->column, 1);
    }
}

TEST(Protection, TheOptionsKeyResealsOptionsButNothingElse) {
    const Sealed sealed = protectPress(OptionsAccess::Own, "options-12");
    const Project read = projectFrom(sealed.text);
    const Keyring configure = *unlock(*read.protection, Permission::Configure, "options-12");

    const std::string toggled = sealProjectText(
        replaced(replaced(sealed.text, "option=\"on\"", "option=\"off\""), "S(M0.5)", "R(M0.5)"),
        configure);
    EXPECT_EQ(verifyProjectText(toggled), std::nullopt);

    const std::string code =
        sealProjectText(replaced(sealed.text, "M0.7 = I0.3", "M0.7 = I0.4"), configure);
    const auto error = verifyProjectText(code);
    ASSERT_TRUE(error.has_value());
    EXPECT_EQ(error->line, lineOf(code, "M0.7 = I0.4"));

    // The main key reseals anything, options included.
    EXPECT_EQ(verifyProjectText(
                  sealProjectText(replaced(replaced(sealed.text, "option=\"on\"", "option=\"off\""),
                                           "M0.7 = I0.3", "M0.7 = I0.4"),
                                  sealed.keys)),
              std::nullopt);
}

TEST(Protection, FreeOptionsNeedNoKey) {
    const Sealed sealed = protectPress(OptionsAccess::Free);
    const std::string toggled = sealProjectText(
        replaced(replaced(sealed.text, "option=\"off\"", "option=\"on\""), "R(M0.6)", "S(M0.6)"),
        Keyring{});
    EXPECT_EQ(verifyProjectText(toggled), std::nullopt);
    EXPECT_TRUE(
        verifyProjectText(sealProjectText(replaced(sealed.text, "I0.3", "I0.4"), Keyring{})));
}

TEST(Protection, TheRecordItselfIsCovered) {
    const Sealed sealed = protectPress(OptionsAccess::Main);
    const int record = lineOf(sealed.text, ";@protected");
    // Freeing the options by hand would let anybody change them.
    const auto freed =
        verifyProjectText(replaced(sealed.text, "options=\"main\"", "options=\"free\""));
    ASSERT_TRUE(freed.has_value());
    EXPECT_EQ(freed->line, record);
    const auto garbled = verifyProjectText(replaced(sealed.text, "signature=\"", "signature=\"0"));
    ASSERT_TRUE(garbled.has_value());
    EXPECT_EQ(garbled->line, record);
    EXPECT_NE(garbled->message.find("signature"), std::string::npos);
    // A project that states an absurd cost is refused, not worked through.
    const std::string costly = replaced(sealed.text, "argon2id:2:", "argon2id:4000:");
    const auto refused = verifyProjectText(costly);
    ASSERT_TRUE(refused.has_value());
    EXPECT_NE(refused->message.find("1-10 passes"), std::string::npos) << refused->message;
    EXPECT_FALSE(readProject(costly).ok());
}

TEST(Protection, MaskingHidesOnlyTheStatesOfOptions) {
    const std::string on = kPress;
    const std::string off =
        replaced(replaced(on, "option=\"on\"", "option=\"off\""), "S(M0.5)", "R(M0.5)");
    EXPECT_EQ(withoutOptionStates(on), withoutOptionStates(off));
    EXPECT_NE(withoutOptionStates(on), withoutOptionStates(replaced(on, "S(M0.5)", "S(M0.4)")));
    // A set that is not an option's stays as it is.
    const std::string plain = replaced(on, "M0.7 = I0.3", "S(M0.7)");
    EXPECT_NE(withoutOptionStates(plain),
              withoutOptionStates(replaced(plain, "S(M0.7)", "R(M0.7)")));
}

} // namespace
