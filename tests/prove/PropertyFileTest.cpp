// SPDX-License-Identifier: GPL-3.0-or-later
#include "prove/PropertyFile.h"
#include "project/ProjectFile.h"
#include "sim/Scenario.h"

#include <gtest/gtest.h>

namespace {

using rs::prove::Condition;
using rs::prove::Property;
using rs::prove::PropertyFile;

const char* const kProject = "! id_pluto:00=000000000000\n"
                             "! type_pluto:00=A20,is3\n"
                             "! I0.12=EStop\n"
                             "! pgm_pluto:00\n"
                             "S0.0_0\n"
                             "Q0.2 = EStop * I0.0\n"
                             "Q0.3 = Q0.2\n";

PropertyFile parse(std::string_view text) {
    const auto read = rs::project::readProject(kProject);
    const rs::sim::OperandNames names(read.project);
    return rs::prove::parseProperties(text, names);
}

TEST(PropertyFileTest, ReadsEveryKindOfLine) {
    const PropertyFile file = parse("; the stop circuit\n"
                                    "cycle 5ms\n"
                                    "always Q0.2 -> EStop      ; no output without the stop\n"
                                    "never Q0.2 * /Q0.3\n"
                                    "always /EStop -> within 20ms /Q0.2 * /Q0.3\n"
                                    "assume /(I0.0 * I0.1)\n"
                                    "cover S0.0 = 0 # the PLC code's step\n"
                                    "always (R0.5>=4) + Q0.2 -> next (R0.5 = R0.6)\n"
                                    "\n"
                                    "always I0.1\r\n");
    ASSERT_TRUE(file.diagnostics.empty()) << file.diagnostics.front().message;
    EXPECT_EQ(file.cycleMs, 5);
    ASSERT_EQ(file.properties.size(), 7u);
    EXPECT_EQ(file.properties[0].kind, Property::Kind::Implies);
    EXPECT_EQ(file.properties[0].line, 3);
    EXPECT_EQ(file.properties[0].text, "always Q0.2 -> EStop");
    EXPECT_EQ(file.properties[0].second.operand.index, 12); // the name resolved
    EXPECT_EQ(file.properties[1].kind, Property::Kind::Never);
    EXPECT_EQ(file.properties[1].first.kind, Condition::Kind::And);
    EXPECT_EQ(file.properties[2].kind, Property::Kind::Within);
    EXPECT_EQ(file.properties[2].durationMs, 20);
    EXPECT_EQ(rs::prove::windowScans(file.properties[2], file.cycleMs), 4);
    EXPECT_EQ(file.properties[3].kind, Property::Kind::Assume);
    EXPECT_EQ(file.properties[3].first.kind, Condition::Kind::Not);
    EXPECT_EQ(file.properties[4].kind, Property::Kind::Cover);
    EXPECT_EQ(file.properties[4].first.operand.kind, rs::lang::AddressKind::Sequence);
    EXPECT_EQ(file.properties[5].kind, Property::Kind::Next);
    EXPECT_EQ(file.properties[5].first.kind, Condition::Kind::Or);
    EXPECT_FALSE(file.properties[5].second.rightIsConstant);
    EXPECT_EQ(file.properties[6].line, 10);
}

struct BadLine {
    const char* text;
    int line;
    int column;
    const char* message; // a part of it
};

TEST(PropertyFileTest, SaysWhereALineIsWrong) {
    const BadLine cases[] = {
        {"always Q0.2 ->\n", 1, 15, "expected an operand"},
        {"alwyas Q0.2\n", 1, 1, "expected always, never"},
        {"\nnever Q0.2 * (Q0.3\n", 2, 19, "expected ')'"},
        {"always Nope\n", 1, 8, "unknown operand 'Nope'"},
        {"always R0.5\n", 1, 8, "is a number"},
        {"always (Q0.2 >= 3)\n", 1, 9, "is a bit"},
        {"always Q5.2\n", 1, 8, "not in the project"},
        {"always Q0.2 -> within soon Q0.3\n", 1, 23, "expected a duration"},
        {"always Q0.2 Q0.3\n", 1, 13, "unexpected 'Q0.3'"},
        {"always Q0.2\ncycle 5ms\n", 2, 1, "before the first property"},
        {"assume Q0.2\n", 1, 1, "no property"},
        {"; nothing\n", 1, 1, "no property"},
        {"always (R0.5 > 99999999999)\n", 1, 16, "out of range"},
        {"always S0.0\n", 1, 8, "compare it"},
        {"always (S0.0 = 0)\nalways S0.1 = 1\n", 2, 8, "unit 0 has no sequence 1"},
    };
    for (const BadLine& bad : cases) {
        const PropertyFile file = parse(bad.text);
        ASSERT_FALSE(file.diagnostics.empty()) << bad.text;
        const auto& d = file.diagnostics.front();
        EXPECT_EQ(d.severity, rs::lang::Severity::Error) << bad.text;
        EXPECT_EQ(d.line, bad.line) << bad.text;
        EXPECT_EQ(d.column, bad.column) << bad.text << d.message;
        EXPECT_NE(d.message.find(bad.message), std::string::npos) << d.message;
    }
}

TEST(PropertyFileTest, RefusesConditionsNestedTooDeep) {
    const std::string deep = "always " + std::string(100000, '(') + "Q0.2" +
                             std::string(100000, ')') + "\nnever " + std::string(5000, '/') +
                             "Q0.2\n";
    const PropertyFile file = parse(deep);
    ASSERT_EQ(file.diagnostics.size(), 2u);
    EXPECT_EQ(file.diagnostics[0].line, 1);
    EXPECT_EQ(file.diagnostics[0].column, 8 + 64);
    EXPECT_NE(file.diagnostics[0].message.find("at most 64"), std::string::npos);
    EXPECT_EQ(file.diagnostics[1].line, 2);
    const PropertyFile fine =
        parse("always " + std::string(60, '(') + "Q0.2" + std::string(60, ')') + "\n");
    EXPECT_TRUE(fine.diagnostics.empty());
}

TEST(PropertyFileTest, WarnsWhenADurationIsNotWholeCycles) {
    const PropertyFile file = parse("always EStop -> within 25ms Q0.2\n");
    ASSERT_EQ(file.diagnostics.size(), 1u);
    EXPECT_EQ(file.diagnostics[0].severity, rs::lang::Severity::Warning);
    EXPECT_NE(file.diagnostics[0].message.find("counts as 2 scans"), std::string::npos);
}

TEST(PropertyFileTest, RefusesTextThatIsNotUtf8) {
    const PropertyFile file = parse("always Q0.2\nnever \xFF\n");
    ASSERT_FALSE(file.diagnostics.empty());
    EXPECT_EQ(file.diagnostics[0].line, 2);
}

} // namespace
