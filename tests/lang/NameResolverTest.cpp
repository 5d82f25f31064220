// SPDX-License-Identifier: GPL-3.0-or-later
#include "lang/NameResolver.h"
#include "lang/Parser.h"
#include "lang/Printer.h"
#include "lang/SymbolicName.h"

#include <gtest/gtest.h>

using namespace rs::lang;

namespace {

struct Resolved {
    std::string text;
    std::vector<std::string> diagnostics;
};

Resolved resolve(const std::string& source) {
    ParseResult parsed = parse(source);
    Diagnostics diagnostics = parsed.diagnostics;
    Diagnostics names = resolveNames(parsed.document);
    diagnostics.insert(diagnostics.end(), names.begin(), names.end());
    Resolved out{print(parsed.document), {}};
    for (const auto& d : diagnostics)
        out.diagnostics.push_back(std::to_string(d.line) + ":" + std::to_string(d.column) + ": " +
                                  d.message);
    return out;
}

Address addressOfCoil(const std::string& source) {
    ParseResult parsed = parse(source);
    resolveNames(parsed.document);
    const auto& statement =
        std::get<Statement>(parsed.document.units.at(0).steps.at(0).lines.at(0).body);
    return statement.condition->operand.address;
}

} // namespace

TEST(SymbolicNames, FollowTheManualsRules) {
    EXPECT_FALSE(checkSymbolicName("MuteSensor1", 3));
    EXPECT_FALSE(checkSymbolicName("Säkerhetsgrind", 3));
    EXPECT_FALSE(checkSymbolicName("Δp_2", 3));
    EXPECT_FALSE(checkSymbolicName("安全门", 3));
    EXPECT_FALSE(checkSymbolicName("Door.Left", 2));
    EXPECT_EQ(checkSymbolicName("Door.Left", 3),
              std::optional<std::string>(
                  "'Door.Left': '.' is allowed in names with instruction set 2 only"));
    EXPECT_EQ(
        checkSymbolicName("1st", 3),
        std::optional<std::string>("'1st' starts with a digit; a name must start with a letter"));
    EXPECT_EQ(checkSymbolicName("_x", 3),
              std::optional<std::string>("'_x' starts with '_'; a name must start with a letter"));
    EXPECT_EQ(checkSymbolicName("a-b", 3),
              std::optional<std::string>("'a-b': '-' is not allowed; use letters, digits and '_'"));
    EXPECT_EQ(checkSymbolicName("ton", 3),
              std::optional<std::string>("'ton' is an instruction of the language"));
    EXPECT_EQ(checkSymbolicName("Q0.1", 2),
              std::optional<std::string>("'Q0.1' looks like an address"));
    EXPECT_EQ(
        checkSymbolicName("SM_SysInit", 3),
        std::optional<std::string>("'SM_SysInit' is the name of a system memory or register"));
}

TEST(NameResolution, NamesResolveToAddressesInTheirDeclaredSpelling) {
    Resolved r = resolve("! I0.0=MuteSensor1\n"
                         "! pgm_pluto:00\n"
                         "! M0.0=MutingActive\n"
                         "S0.0_0\n"
                         "mutingactive = MUTESENSOR1 * SM_SysInit\n");
    EXPECT_TRUE(r.diagnostics.empty());
    EXPECT_NE(r.text.find("MutingActive = MuteSensor1 * SM_SysInit\n"), std::string::npos);
    EXPECT_EQ(addressOfCoil("! I0.0=Sensor\n! pgm_pluto:00\nS0.0_0\nQ0.1 = sensor\n"),
              (Address{AddressKind::Input, 0, 0}));
}

TEST(NameResolution, SystemNamesBelongToTheUnitWhoseCodeUsesThem) {
    EXPECT_EQ(addressOfCoil("! pgm_pluto:07\nS7.0_0\nQ7.1 = SM_Pluto3_Present\n"),
              (Address{AddressKind::SystemMemory, 7, 103}));
}

TEST(NameResolution, HalvesAndBitsOfNamedRegisters) {
    Resolved r = resolve("! type_pluto:00=B46,is3\n"
                         "! pgm_pluto:00\n"
                         "! DR0.4=Example\n"
                         "! R0.10=Flags\n"
                         "S0.0_0\n"
                         "(example.lo += Example.HI)\n"
                         "Q0.1 = flags.3\n");
    EXPECT_TRUE(r.diagnostics.empty()) << r.diagnostics.front();
    EXPECT_NE(r.text.find("(Example.Lo += Example.Hi)\n"), std::string::npos);
    EXPECT_NE(r.text.find("Q0.1 = Flags.3\n"), std::string::npos);
}

TEST(NameResolution, ProblemsAreReportedWhereTheyAreWritten) {
    Resolved r = resolve("! I0.0=Sensor\n"
                         "! I0.1=sensor\n"
                         "! I0.0=Other\n"
                         "! pgm_pluto:00\n"
                         "! M0.1=Sensor\n"
                         "! M0.2=2nd\n"
                         "S0.0_0\n"
                         "Q0.1 = Missing\n"
                         "Q0.2 = Sensor\n"
                         "Sensor = I0.3\n"
                         "(Sensor += 1)\n");
    EXPECT_EQ(r.diagnostics,
              (std::vector<std::string>{
                  "2:8: the name 'sensor' is already given to I0.0 at line 1",
                  "3:8: I0.0 is already named 'Sensor' at line 1",
                  "5:8: the name 'Sensor' is already given to I0.0 at line 1",
                  "6:8: '2nd' starts with a digit; a name must start with a letter",
                  "8:8: unknown name 'Missing': declare it with '! <address>=Missing'",
                  "11:2: 'Sensor' is I0.0, which cannot be used as the target of an assignment",
              }));
}

TEST(NameResolution, DotsInNamesDependOnTheUnitsInstructionSet) {
    EXPECT_TRUE(resolve("! pgm_pluto:00\n! M0.1=Door.Left\nS0.0_0\nQ0.1 = Door.Left\n")
                    .diagnostics.empty());
    EXPECT_EQ(resolve("! type_pluto:00=B46,is3\n! pgm_pluto:00\n! M0.1=Door.Left\n").diagnostics,
              std::vector<std::string>{
                  "3:8: 'Door.Left': '.' is allowed in names with instruction set 2 only"});
}

TEST(NameResolution, LocalNamesStayInTheirUnit) {
    Resolved r = resolve("! pgm_pluto:00\n! M0.1=Local\nS0.0_0\nQ0.1 = Local\n"
                         "! pgm_pluto:01\nS1.0_0\nQ1.1 = Local\n");
    EXPECT_EQ(r.diagnostics, std::vector<std::string>{
                                 "7:8: unknown name 'Local': declare it with '! <address>=Local'"});
}

// A name each unit declares for itself is each unit's own, however often
// it is written.
TEST(NameResolution, OneNameInTwoUnitsIsEachUnitsOwn) {
    Resolved r = resolve("! pgm_pluto:00\n! M0.1=Lamp\nS0.0_0\nQ0.1 = Lamp\nQ0.2 = Lamp\n"
                         "! pgm_pluto:01\n! M1.7=lamp\nS1.0_0\nQ1.1 = LAMP\nQ1.2 = Lamp\n");
    EXPECT_TRUE(r.diagnostics.empty());
    EXPECT_EQ(r.text, "! pgm_pluto:00\n! M0.1=Lamp\nS0.0_0\nQ0.1 = Lamp\nQ0.2 = Lamp\n"
                      "! pgm_pluto:01\n! M1.7=lamp\nS1.0_0\nQ1.1 = lamp\nQ1.2 = lamp\n");
}
