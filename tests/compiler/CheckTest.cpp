// SPDX-License-Identifier: GPL-3.0-or-later
// The compiler's semantic checks (core/compiler/UnitSetup.cpp and ProgramCheck.cpp):
// every diagnostic they can give, with its exact line, column, severity and message.
// Each test compiles a small complete program with compileText and compares the
// diagnostics, written "LINE:COL: error|warning: message", with a table.

#include "compiler/Compiler.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

using namespace rs::compiler;

namespace {

using Lines = std::vector<std::string>;

const CheckOptions kQuiet{.warnUnconfiguredIo = false,
                          .onlyUnit = {}}; // no unconfigured-I/O warnings

std::string join(const Lines& lines) {
    std::string text;
    for (const auto& line : lines)
        text += line + "\n";
    return text;
}

Lines diagnosticsOf(const CompileResult& result) {
    Lines out;
    for (const auto& d : result.diagnostics)
        out.push_back(std::to_string(d.line) + ":" + std::to_string(d.column) + ": " +
                      (d.severity == rs::lang::Severity::Error ? "error" : "warning") + ": " +
                      d.message);
    return out;
}

Lines checkText(std::string_view text, const CheckOptions& options = {}) {
    return diagnosticsOf(compileText(text, options));
}

// A whole program, one string per line (line 1 first).
Lines check(const Lines& lines, const CheckOptions& options = {}) {
    return checkText(join(lines), options);
}

std::string familyKeyword(std::string_view type) {
    type = type.substr(0, type.find(','));
    if (type == "B46" || type == "S46" || type == "D45")
        return "id_pluto_Double";
    if (type == "ASi")
        return "id_pluto_ASi";
    if (type == "B42_ASi")
        return "id_pluto_B42_ASi";
    return "id_pluto";
}

// Station 0 of the given type ("A20,is3"; "A20" alone is instruction set 2):
//   line 1  ! id_pluto...:00=000000000000   (the family of the type)
//   line 2  ! type_pluto:00=<type>
//   line 3  ! pgm_pluto:00
//   line 4  the first line of body (I/O declarations, names, steps)
Lines program(std::string_view type, const Lines& body) {
    Lines lines{"! " + familyKeyword(type) + ":00=000000000000",
                "! type_pluto:00=" + std::string(type), "! pgm_pluto:00"};
    lines.insert(lines.end(), body.begin(), body.end());
    return lines;
}

Lines checkUnit(std::string_view type, const Lines& body, const CheckOptions& options = {}) {
    return check(program(type, body), options);
}

// One I/O declaration at line 4 of a unit with empty PLC code; its
// diagnostics point at the terminal, column 3.
struct IoCase {
    std::string type;
    std::string declaration;
    std::string expected; // empty: accepted
};

void expectIo(const std::vector<IoCase>& cases) {
    for (const auto& c : cases) {
        SCOPED_TRACE(c.type + ": " + c.declaration);
        Lines expected;
        if (!c.expected.empty())
            expected.push_back(c.expected);
        EXPECT_EQ(checkUnit(c.type, {c.declaration, "S0.0_0"}), expected);
    }
}

std::string set3(std::string_view feature, std::string_view type = "A20") {
    return std::string(feature) +
           ": only with instruction set 3; unit 0 uses instruction set 2 (declare '! "
           "type_pluto:00=" +
           std::string(type) + ",is3')";
}

const std::string kReadOnly =
    " is read-only; the program may write only SM_TimerFreeze and SR_PlutoDisplay";

} // namespace

// ===== Units: id_pluto, type_pluto, pgm_pluto (UnitSetup.cpp)

TEST(UnitSetupCheck, ValidProgramHasNoDiagnostics) {
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "M0.0 = M0.1"}), Lines{});
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0"}), Lines{});
    EXPECT_EQ(check({"! id_pluto:31=000000000000", "! pgm_pluto:31", "S31.0_0", "M31.0 = M31.1"}),
              Lines{});
}

TEST(UnitSetupCheck, StationOutside0To31) {
    EXPECT_EQ(check({"! id_pluto:32=000000000000", "! pgm_pluto:32", "S32.0_0", "M32.0 = M32.1"}),
              (Lines{"1:1: error: station number 32 is outside 0-31",
                     "2:1: error: station number 32 is outside 0-31"}));
    EXPECT_EQ(
        check({"! id_pluto:00=000000000000", "! type_pluto:40=A20", "! pgm_pluto:00", "S0.0_0"}),
        (Lines{"2:1: error: station number 40 is outside 0-31"}));
    EXPECT_EQ(check({"! id_pluto:00=000000000000", "! pgm_pluto:00", "S0.0_0", "! pgm_pluto:99",
                     "S99.0_0"}),
              (Lines{"4:1: error: station number 99 is outside 0-31"}));
}

TEST(UnitSetupCheck, UnitDeclaredTwice) {
    EXPECT_EQ(check({"! id_pluto:00=000000000000", "! id_pluto_Double:00=000000000001",
                     "! pgm_pluto:00", "S0.0_0"}),
              (Lines{"2:1: error: unit 0 is already declared at line 1"}));
}

TEST(UnitSetupCheck, TypeDeclaredTwice) {
    EXPECT_EQ(check({"! id_pluto:00=000000000000", "! type_pluto:00=A20", "! type_pluto:00=A20,is3",
                     "! pgm_pluto:00", "S0.0_0"}),
              (Lines{"3:1: error: the type of unit 0 is already declared at line 2"}));
}

TEST(UnitSetupCheck, TypeWithoutIdPluto) {
    EXPECT_EQ(
        check({"! id_pluto:00=000000000000", "! type_pluto:01=A20", "! pgm_pluto:00", "S0.0_0"}),
        (Lines{"2:1: error: type_pluto:01 names a unit that has no id_pluto declaration"}));
}

TEST(UnitSetupCheck, TypeOfAnotherFamily) {
    EXPECT_EQ(
        check({"! id_pluto:00=000000000000", "! type_pluto:00=B46", "! pgm_pluto:00", "S0.0_0"}),
        (Lines{"2:1: error: a B46 is declared with '! id_pluto_Double:00=...', not with "
               "'! id_pluto'"}));
    EXPECT_EQ(check({"! id_pluto_Double:05=000000000000", "! type_pluto:05=ASi", "! pgm_pluto:05",
                     "S5.0_0"}),
              (Lines{"2:1: error: an AS-i is declared with '! id_pluto_ASi:05=...', not with "
                     "'! id_pluto_Double'"}));
    EXPECT_EQ(check({"! id_pluto_ASi:12=000000000000", "! type_pluto:12=B42_ASi", "! pgm_pluto:12",
                     "S12.0_0"}),
              (Lines{"2:1: error: a B42 AS-i is declared with '! id_pluto_B42_ASi:12=...', not "
                     "with '! id_pluto_ASi'"}));
    EXPECT_EQ(check({"! id_pluto_B42_ASi:00=000000000000", "! type_pluto:00=A20", "! pgm_pluto:00",
                     "S0.0_0"}),
              (Lines{"2:1: error: an A20 is declared with '! id_pluto:00=...', not with "
                     "'! id_pluto_B42_ASi'"}));
    // Every type of the right family is accepted.
    for (const char* type : {"A16", "A20", "B16", "B20", "S20", "B22", "D20", "O2", "B46", "S46",
                             "D45", "ASi", "B42_ASi"}) {
        SCOPED_TRACE(type);
        EXPECT_EQ(checkUnit(std::string(type) + ",is3", {"S0.0_0", "M0.0 = M0.1"}), Lines{});
    }
}

TEST(UnitSetupCheck, CodeForUnitWithoutIdPluto) {
    EXPECT_EQ(check({"! id_pluto:00=000000000000", "! pgm_pluto:00", "S0.0_0", "M0.0 = M0.1",
                     "! pgm_pluto:03", "S3.0_0", "M3.0 = M3.1"}),
              (Lines{"5:1: error: code for unit 3, which has no '! id_pluto:03=...' declaration"}));
    EXPECT_EQ(check({"! id_pluto:00=000000000000", "! pgm_pluto:00", "S0.0_0", "! pgm_pluto:12",
                     "S12.0_0"}),
              (Lines{"4:1: error: code for unit 12, which has no '! id_pluto:12=...' "
                     "declaration"}));
}

TEST(UnitSetupCheck, CodeForUnitTwice) {
    EXPECT_EQ(check({"! id_pluto:00=000000000000", "! pgm_pluto:00", "S0.0_0", "M0.0 = M0.1",
                     "! pgm_pluto:00", "S0.0_0", "M0.0 = M0.1"}),
              (Lines{"5:1: error: the code of unit 0 already starts at line 2"}));
}

TEST(UnitSetupCheck, WithoutTypeUnitIsBaseTypeOfFamilyWithInstructionSet2) {
    // id_pluto_Double without type_pluto is a B46: Q0.4 and I0.20 exist.
    EXPECT_EQ(
        check({"! id_pluto_Double:00=000000000000", "! pgm_pluto:00", "S0.0_0", "Q0.4 = I0.20"},
              kQuiet),
        Lines{});
    // id_pluto_ASi without type_pluto is an AS-i with instruction set 2: 150 memories.
    EXPECT_EQ(
        check({"! id_pluto_ASi:00=000000000000", "! pgm_pluto:00", "S0.0_0", "M0.149 = M0.150"}),
        (Lines{"4:10: error: M0.150 does not exist on unit 0, an AS-i with instruction set 2"}));
    // A type_pluto line without ,is3 keeps instruction set 2.
    EXPECT_EQ(checkUnit("A20", {"S0.0_0", "M0.0 = TOF(1s00)"}),
              (Lines{"5:8: error: " + set3("the off-delay timer TOF")}));
    EXPECT_EQ(checkUnit("A20,is2", {"S0.0_0", "M0.0 = TOF(1s00)"}),
              (Lines{"5:8: error: " + set3("the off-delay timer TOF")}));
}

TEST(UnitSetupCheck, ColumnsFollowIndentation) {
    // Declarations at their terminal, statements at their first token; a tab is one column.
    EXPECT_EQ(checkUnit("A20,is3", {"  ! I0.0,static,static", "S0.0_0", "   J(1)",
                                    "    M0.0 = M0.600 ; comment", "S0.1_0", "\tJ(5)"}),
              (Lines{"4:5: error: I0.0: option 'static' is given twice",
                     "6:4: error: J(1) in the PLC code: jumps belong in sequences 1-9",
                     "7:12: error: M0.600 does not exist on unit 0, an A20",
                     "9:2: error: J(5) jumps to step 5, which sequence 1 does not have"}));
}

// ===== I/O declarations (UnitSetup.cpp, checkOptions)

TEST(IoOptionCheck, OptionGivenTwice) {
    expectIo({
        {"A20,is3", "! I0.0,static,static", "4:3: error: I0.0: option 'static' is given twice"},
        {"A20,is3", "! I0.5,c_pulse,non_inv,no_filt,non_inv",
         "4:3: error: I0.5: option 'non_inv' is given twice"},
        {"A20,is3", "! Q0.2,no_test_pulse,no_test_pulse",
         "4:3: error: Q0.2: option 'no_test_pulse' is given twice"},
    });
}

TEST(IoOptionCheck, InputsNeedExactlyOneSignal) {
    const std::string one = " needs exactly one signal: a_pulse, b_pulse, c_pulse or static";
    expectIo({
        {"A20,is3", "! I0.0,non_inv", "4:3: error: I0.0" + one},
        {"A20,is3", "! I0.0,no_filt", "4:3: error: I0.0" + one},
        {"A20,is3", "! I0.0,a_pulse,b_pulse", "4:3: error: I0.0" + one},
        {"A20,is3", "! I0.0,static,c_pulse", "4:3: error: I0.0" + one},
        {"A20,is3", "! I0.0,voltage", "4:3: error: I0.0" + one},
        // The manuals' own declarations.
        {"A20,is3", "! I0.5,c_pulse,non_inv,no_filt", ""},
        {"A20,is3", "! i0.1,a_pulse", ""},
        {"A20,is3", "! i0.2,a_pulse,non_inv", ""},
        {"A20,is3", "! i0.3,static", ""},
        {"A20,is3", "! I0.4,b_pulse,no_filt", ""},
        {"A20,is3", "! I0.17,static,no_filt",
         "4:3: warning: I0.17,static does not fulfil category 4 (EN 954-1) as a stand-alone "
         "input"},
    });
}

TEST(IoOptionCheck, NonInvOnlyWithDynamicSignals) {
    expectIo({
        {"A20,is3", "! I0.0,static,non_inv",
         "4:3: error: I0.0: non_inv applies to dynamic signals (a_pulse, b_pulse, c_pulse), not "
         "to static"},
        {"A20,is3", "! I0.0,non_inv,static",
         "4:3: error: I0.0: non_inv applies to dynamic signals (a_pulse, b_pulse, c_pulse), not "
         "to static"},
    });
}

TEST(IoOptionCheck, CrossTalkOnlyOnDynamicInputsOfTerminals10To17) {
    expectIo({
        {"A20,is3", "! I0.12,a_pulse,x_talk", ""},
        {"A20,is3", "! I0.10,c_pulse,x_talk,non_inv,no_filt", ""},
        {"A20,is3", "! I0.0,a_pulse,x_talk", "4:3: error: I0.0 cannot take the option 'x_talk'"},
        {"A20,is3", "! I0.7,b_pulse,x_talk", "4:3: error: I0.7 cannot take the option 'x_talk'"},
        {"A20,is3", "! I0.10,static,x_talk", "4:3: error: I0.10 cannot take the option 'x_talk'"},
        {"B46,is3", "! I0.20,b_pulse,x_talk", ""},
        {"B46,is3", "! I0.30,b_pulse,x_talk", "4:3: error: I0.30 cannot take the option 'x_talk'"},
    });
}

TEST(IoOptionCheck, OptionsOfAnotherKindOfTerminal) {
    expectIo({
        {"A20,is3", "! I0.0,a_pulse,no_test_pulse",
         "4:3: error: I0.0 cannot take the option 'no_test_pulse'"},
        {"A20,is3", "! I0.0,static,current", "4:3: error: I0.0 cannot take the option 'current'"},
        {"A20,is3", "! Q0.10,a_pulse,non_inv",
         "4:3: error: Q0.10 cannot take the option 'non_inv'"},
        {"A20,is3", "! Q0.10,static,no_filt", "4:3: error: Q0.10 cannot take the option 'no_filt'"},
        {"A20,is3", "! Q0.10,a_pulse,x_talk", "4:3: error: Q0.10 cannot take the option 'x_talk'"},
    });
}

TEST(IoOptionCheck, NonFailsafeOutputsTakeASignal) {
    const std::string one = " needs exactly one signal: a_pulse, b_pulse, c_pulse or static";
    expectIo({
        {"A20,is3", "! Q0.10,a_pulse", ""},
        {"A20,is3", "! Q0.11,b_pulse", ""},
        {"A20,is3", "! Q0.12,c_pulse", ""},
        {"A20,is3", "! Q0.17,static", ""},
        {"B46,is3", "! Q0.27,static", ""},
        {"B42_ASi,is3", "! Q0.27,a_pulse", ""},
        {"ASi,is3", "! Q0.13,static", ""},
        {"A20,is3", "! Q0.10,non_inv", "4:3: error: Q0.10" + one},
        {"A20,is3", "! Q0.10,a_pulse,static", "4:3: error: Q0.10" + one},
        {"A20,is3", "! Q0.12,no_test_pulse", "4:3: error: Q0.12" + one},
    });
    // A declaration without any option is a syntax error (core/lang), not an
    // output "declared without options".
    EXPECT_EQ(checkUnit("A20,is3", {"! Q0.10", "S0.0_0"}),
              (Lines{"4:8: error: expected '=' and a symbolic name, or ',' and I/O options after "
                     "'Q0.10'"}));
}

TEST(IoOptionCheck, NoTestPulseOnlyOnQ2AndQ3OfTypesThatAllowIt) {
    const std::string noOptions =
        " takes no I/O options: only the non-failsafe outputs Q0.10.. and Q2/Q3 (no_test_pulse) "
        "are declared";
    expectIo({
        {"A20,is3", "! Q0.2,no_test_pulse", ""},
        {"A20,is3", "! Q0.3,no_test_pulse", ""},
        {"B20,is3", "! Q0.2,no_test_pulse", ""},
        {"S20,is3", "! Q0.3,no_test_pulse", ""},
        {"D20,is3", "! Q0.2,no_test_pulse", ""},
        {"B46,is3", "! Q0.2,no_test_pulse",
         "4:3: error: the test pulses of Q0.2 cannot be disabled on a B46"},
        {"D45,is3", "! Q0.3,no_test_pulse",
         "4:3: error: the test pulses of Q0.3 cannot be disabled on a D45"},
        {"A16,is3", "! Q0.2,no_test_pulse",
         "4:3: error: the test pulses of Q0.2 cannot be disabled on an A16"},
        {"ASi,is3", "! Q0.2,no_test_pulse",
         "4:3: error: the test pulses of Q0.2 cannot be disabled on an AS-i"},
        {"A20,is3", "! Q0.1,no_test_pulse", "4:3: error: Q0.1" + noOptions},
        {"A20,is3", "! Q0.2,no_test_pulse,static",
         "4:3: error: Q0.2 takes only the option no_test_pulse"},
    });
}

TEST(IoOptionCheck, SafetyOutputsTakeNoOptions) {
    const std::string noOptions =
        " takes no I/O options: only the non-failsafe outputs Q0.10.. and Q2/Q3 (no_test_pulse) "
        "are declared";
    expectIo({
        {"A20,is3", "! Q0.0,static", "4:3: error: Q0.0" + noOptions},
        {"A20,is3", "! Q0.2,a_pulse", "4:3: error: Q0.2" + noOptions},
        {"A20,is3", "! Q0.3,static", "4:3: error: Q0.3" + noOptions},
        {"B46,is3", "! Q0.4,static", "4:3: error: Q0.4" + noOptions},
        {"B42_ASi,is3", "! Q0.5,c_pulse", "4:3: error: Q0.5" + noOptions},
    });
}

TEST(IoOptionCheck, IlluminatedPushButtonTakesOnePulse) {
    const std::string iq = ", an illuminated push button, takes one of a_pulse, b_pulse, c_pulse";
    expectIo({
        {"A20,is3", "! IQ0.14,a_pulse", ""},
        {"A20,is3", "! IQ0.10,b_pulse", ""},
        {"A20,is3", "! IQ0.17,c_pulse", ""},
        {"B46,is3", "! IQ0.27,a_pulse", ""},
        {"A20,is3", "! IQ0.14,static", "4:3: error: IQ0.14" + iq},
        {"A20,is3", "! IQ0.14,non_inv", "4:3: error: IQ0.14" + iq},
        {"A20,is3", "! IQ0.14,a_pulse,non_inv", "4:3: error: IQ0.14" + iq},
        {"A20,is3", "! IQ0.14,a_pulse,b_pulse", "4:3: error: IQ0.14" + iq},
        {"A20,is3", "! IQ0.14,a_pulse,x_talk", "4:3: error: IQ0.14" + iq},
        {"A20,is3", "! IQ0.4,a_pulse", "4:3: error: an A20 has no terminal IQ0.4"},
        {"A20,is3", "! IQ0.20,a_pulse", "4:3: error: an A20 has no terminal IQ0.20"},
    });
}

TEST(IoOptionCheck, AnalogueInputsOfD20) {
    const std::string one = "4:3: error: IA0.0 takes one of voltage, current, counter_up, "
                            "counter_updown, or the options of an ordinary input";
    expectIo({
        {"D20,is3", "! IA0.0,voltage", ""},
        {"D20,is3", "! IA0.3,current", ""},
        {"D20,is3", "! IA0.1,a_pulse,non_inv,no_filt", ""},
        {"D20,is3", "! IA0.2,static", ""},
        {"D20,is3", "! IA0.4,voltage", "4:3: error: a D20 has no analogue input IA0.4"},
        {"D20,is3", "! IA0.0,counter_up", "4:3: error: IA0.0 cannot count pulses on a D20"},
        {"D20,is3", "! IA0.3,counter_updown", "4:3: error: IA0.3 cannot count pulses on a D20"},
        {"D20,is3", "! IA0.0,counter_up,non_inv", "4:3: error: IA0.0 cannot count pulses on a D20"},
        {"D20,is3", "! IA0.0,voltage,current", one},
        {"D20,is3", "! IA0.0,voltage,static", one},
        {"D20,is3", "! IA0.0,current,no_filt", one},
        {"D20,is3", "! IA0.0,non_inv",
         "4:3: error: IA0.0 needs exactly one signal: a_pulse, b_pulse, c_pulse or static"},
        {"D20,is3", "! IA0.0,a_pulse,x_talk", "4:3: error: IA0.0 cannot take the option 'x_talk'"},
        {"D20,is3", "! IA0.0,static,non_inv",
         "4:3: error: IA0.0: non_inv applies to dynamic signals (a_pulse, b_pulse, c_pulse), not "
         "to static"},
        // IA0..IA3 replace I0..I3 on a D20.
        {"D20,is3", "! I0.0,static", "4:3: error: a D20 has no input I0.0"},
        {"D20,is3", "! I0.4,static", ""},
        {"A20,is3", "! IA0.0,voltage", "4:3: error: an A20 has no analogue input IA0.0"},
        {"B46,is3", "! IA0.0,current", "4:3: error: a B46 has no analogue input IA0.0"},
    });
}

TEST(IoOptionCheck, AnalogueAndCounterInputsOfD45) {
    expectIo({
        {"D45,is3", "! IA0.0,voltage", ""},
        {"D45,is3", "! IA0.7,current", ""},
        {"D45,is3", "! IA0.0,counter_up", ""},
        {"D45,is3", "! IA0.3,counter_updown", ""},
        {"D45,is3", "! IA0.5,b_pulse,non_inv", ""},
        {"D45,is3", "! IA0.4,counter_up",
         "4:3: error: IA0.4 cannot count pulses on a D45 (only IA0..IA3)"},
        {"D45,is3", "! IA0.7,counter_updown",
         "4:3: error: IA0.7 cannot count pulses on a D45 (only IA0..IA3)"},
        {"D45,is3", "! IA0.8,current", "4:3: error: a D45 has no analogue input IA0.8"},
        {"D45,is3", "! IA0.0,counter_up,no_filt",
         "4:3: error: IA0.0 takes one of voltage, current, counter_up, counter_updown, or the "
         "options of an ordinary input"},
        {"D45,is3", "! IA0.1,counter_up,counter_updown",
         "4:3: error: IA0.1 takes one of voltage, current, counter_up, counter_updown, or the "
         "options of an ordinary input"},
        {"D45,is3", "! I0.4,static", "4:3: error: a D45 has no input I0.4"},
        {"D45,is3", "! I0.26,static", ""},
        {"D45,is3", "! I0.27,static", "4:3: error: a D45 has no input I0.27"},
    });
}

TEST(IoOptionCheck, TerminalsTheTypeDoesNotHave) {
    expectIo({
        {"A20,is3", "! I0.20,a_pulse", "4:3: error: an A20 has no input I0.20"},
        {"A20,is3", "! I0.8,a_pulse", "4:3: error: an A20 has no input I0.8"},
        {"B46,is3", "! I0.20,a_pulse", ""},
        {"B46,is3", "! I0.47,static", ""},
        {"B46,is3", "! I0.50,static", "4:3: error: a B46 has no input I0.50"},
        {"B22,is3", "! I0.25,static", ""},
        {"B22,is3", "! I0.26,static", "4:3: error: a B22 has no input I0.26"},
        {"ASi,is3", "! I0.13,a_pulse", ""},
        {"ASi,is3", "! I0.14,a_pulse", "4:3: error: an AS-i has no input I0.14"},
    });
}

TEST(IoOptionCheck, OnlyTerminalsAreDeclared) {
    const std::string none = " takes no I/O options; only I, Q, IQ and IA terminals are declared";
    expectIo({
        {"A20,is3", "! M0.0,static", "4:3: error: M0.0" + none},
        {"A20,is3", "! GM0.1,a_pulse", "4:3: error: GM0.1" + none},
        {"A20,is3", "! R0.0,static", "4:3: error: R0.0" + none},
        {"ASi,is3", "! ASi0.1,static", "4:3: error: ASi0.1" + none},
    });
}

TEST(IoOptionCheck, TerminalDeclaredTwice) {
    // I12, Q12 and IQ12 are one terminal.
    EXPECT_EQ(checkUnit("A20,is3", {"! Q0.10,a_pulse", "! I0.10,a_pulse", "S0.0_0"}),
              (Lines{"5:3: error: terminal 10 is already declared at line 4"}));
    EXPECT_EQ(checkUnit("A20,is3", {"! I0.12,a_pulse", "! IQ0.12,a_pulse", "S0.0_0"}),
              (Lines{"5:3: error: terminal 12 is already declared at line 4"}));
    EXPECT_EQ(checkUnit("A20,is3", {"! I0.3,static", "! I0.3,static", "S0.0_0"}),
              (Lines{"5:3: error: terminal 3 is already declared at line 4"}));
    EXPECT_EQ(checkUnit("A20,is3",
                        {"! Q0.2,no_test_pulse", "; Q2 again", "! Q0.2,no_test_pulse", "S0.0_0"}),
              (Lines{"6:3: error: terminal 2 is already declared at line 4"}));
    EXPECT_EQ(checkUnit("D20,is3", {"! IA0.1,voltage", "! IA0.1,current", "S0.0_0"}),
              (Lines{"5:3: error: terminal 1 is already declared at line 4"}));
    // The input I2 and the safety output Q2 are different terminals; so are IA1 and I11.
    EXPECT_EQ(checkUnit("A20,is3", {"! I0.2,static", "! Q0.2,no_test_pulse", "S0.0_0"}), Lines{});
    EXPECT_EQ(checkUnit("D20,is3", {"! IA0.1,voltage", "! I0.11,a_pulse", "S0.0_0"}), Lines{});
    // A rejected declaration does not occupy the terminal.
    EXPECT_EQ(checkUnit("A20,is3", {"! I0.10,static,non_inv", "! I0.10,a_pulse", "S0.0_0"}),
              (Lines{"4:3: error: I0.10: non_inv applies to dynamic signals (a_pulse, b_pulse, "
                     "c_pulse), not to static"}));
}

TEST(IoOptionCheck, IoOfAnotherUnit) {
    EXPECT_EQ(check({"! id_pluto:00=000000000000", "! id_pluto:01=000000000001", "! pgm_pluto:00",
                     "! I1.0,static", "! q1.10,a_pulse", "S0.0_0", "! pgm_pluto:01", "S1.0_0"}),
              (Lines{"4:3: error: I1.0 belongs to unit 1; declare its I/O in that unit's code",
                     "5:3: error: Q1.10 belongs to unit 1; declare its I/O in that unit's code"}));
}

// ===== Steps and sequences (ProgramCheck.cpp)

TEST(StepCheck, SequenceAbove9) {
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "M0.0 = M0.1", "S0.10_0", "M0.2 = M0.1"}),
              (Lines{"6:1: error: sequences are numbered 1-9 (0 is the PLC code), not 10"}));
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "S0.9_0", "M0.2 = M0.1"}), Lines{});
}

TEST(StepCheck, PlcCodeHasOnlyStep0) {
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "M0.0 = M0.1", "S0.0_1", "M0.2 = M0.1"}),
              (Lines{"6:1: error: the PLC code S0.0_0 has only step 0; steps belong in sequences "
                     "1-9"}));
}

TEST(StepCheck, StepsAre0To254) {
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "S0.1_0", "J(254)", "S0.1_254", "J(0)"}), Lines{});
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "S0.1_0", "J(255)", "S0.1_255", "J(0)"}),
              (Lines{"6:1: error: J(255) jumps to step 255, which sequence 1 does not have",
                     "7:1: error: steps are numbered 0-254, not 255"}));
}

TEST(StepCheck, StepDeclaredTwice) {
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "M0.0 = M0.1", "S0.1_0", "J(+1)", "S0.1_1", "J(0)",
                                    "S0.1_1", "M0.2 = M0.1"}),
              (Lines{"10:1: error: S0.1_1 is already declared at line 8"}));
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "M0.0 = M0.1", "S0.0_0"}),
              (Lines{"6:1: error: S0.0_0 is already declared at line 4"}));
}

TEST(StepCheck, PlcCodeMissing) {
    EXPECT_EQ(checkUnit("A20,is3", {"S0.1_0", "J(+1)", "S0.1_1", "J(0)"}),
              (Lines{"3:1: error: the code of unit 0 has no PLC code step S0.0_0"}));
    EXPECT_EQ(check({"! id_pluto:07=000000000000", "! pgm_pluto:07"}),
              (Lines{"2:1: error: the code of unit 7 has no PLC code step S7.0_0"}));
}

TEST(StepCheck, SequenceWithoutStep0) {
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "M0.0 = M0.1", "S0.1_1", "J(1)"}),
              (Lines{"6:1: error: sequence 1 has no step 0 (S0.1_0), where it starts"}));
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "S0.3_4", "J(5)", "S0.3_5", "J(4)"}),
              (Lines{"5:1: error: sequence 3 has no step 0 (S0.3_0), where it starts"}));
}

TEST(JumpCheck, NoJumpsInPlcCode) {
    EXPECT_EQ(checkUnit("A20,is3",
                        {"S0.0_0", "M0.0 = M0.1", "J(1)", "J(+1) = M0.0 * /M0.1", "J(-2) = M0.2"}),
              (Lines{"6:1: error: J(1) in the PLC code: jumps belong in sequences 1-9",
                     "7:1: error: J(+1) in the PLC code: jumps belong in sequences 1-9",
                     "8:1: error: J(-2) in the PLC code: jumps belong in sequences 1-9"}));
}

TEST(JumpCheck, JumpToMissingStep) {
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "S0.1_0", "J(2) = M0.0", "J(+3)", "J(-1)",
                                    "J(+1) = M0.1", "S0.1_1", "J(0)", "J(-1)", "J(+253)"}),
              (Lines{"6:1: error: J(2) jumps to step 2, which sequence 1 does not have",
                     "7:1: error: J(+3) jumps to step 3, which sequence 1 does not have",
                     "8:1: error: J(-1) jumps to step -1, which sequence 1 does not have",
                     "13:1: error: J(+253) jumps to step 254, which sequence 1 does not have"}));
}

TEST(JumpCheck, JumpsStayInTheirSequence) {
    // Sequence 2 has a step 1, sequence 1 does not.
    EXPECT_EQ(
        checkUnit("A20,is3", {"S0.0_0", "S0.1_0", "J(1)", "S0.2_0", "J(1)", "S0.2_1", "J(0)"}),
        (Lines{"6:1: error: J(1) jumps to step 1, which sequence 1 does not have"}));
}

TEST(SequenceResetCheck, ResetsOnlyAnotherSequenceOfItsOwnUnit) {
    EXPECT_EQ(check({"! id_pluto:00=000000000000", "! id_pluto:01=000000000001", "! pgm_pluto:00",
                     "S0.0_0", "R(S1.1) = M0.0", "R(S0.0) = M0.0", "R(S0.2) = M0.0",
                     "R(S0.1) = M0.0", "S0.1_0", "R(S0.1) = M0.0", "R(S0.3) = M0.0", "S0.3_0",
                     "R(s0.10) = M0.0", "R(S0.1)", "! pgm_pluto:01", "S1.0_0", "S1.1_0"}),
              (Lines{"5:3: error: R(S1.1) resets a sequence of unit 1; a unit resets only its own",
                     "6:3: error: only sequences 1-9 can be reset, not S0.0",
                     "7:3: error: R(S0.2) resets sequence 2, which unit 0 does not have",
                     "10:3: error: sequence 1 cannot reset itself; a reset must come from "
                     "another sequence or the PLC code",
                     "13:3: error: only sequences 1-9 can be reset, not S0.10"}));
}

// ===== Instruction set 3 features in an instruction set 2 unit

TEST(InstructionSetCheck, Set3FeaturesInSet2Unit) {
    const Lines body{"S0.0_0",
                     "M0.0 = TOF(1s00)",       // 5
                     "M0.1 = /P(M0.2)",        // 6
                     "M0.3 = M0.2 * /N(M0.2)", // 7
                     "(R0.1 *= 2)",            // 8
                     "(R0.1 /= R0.3)",         // 9
                     "(R0.1 = R0.2 + R0.3)",   // 10
                     "(R0.1 = R0.2 - 5)",      // 11
                     "M0.4 = R0.2.3",          // 12
                     "R0.15.1 = M0.0",         // 13
                     "(DR0.4 = 5)",            // 14
                     "(DR0.6.Lo = 1)",         // 15
                     "M0.5 = (DR0.8 > 3)",     // 16
                     "M0.6 = TON(DR0.10.Hi)"}; // 17
    EXPECT_EQ(checkUnit("A20", body),
              (Lines{"5:8: error: " + set3("the off-delay timer TOF"),
                     "6:8: error: " + set3("'Not positive edge' /P(...)"),
                     "7:15: error: " + set3("'Not negative edge' /N(...)"),
                     "8:1: error: " + set3("multiplication and division"),
                     "9:1: error: " + set3("multiplication and division"),
                     "10:1: error: " + set3("arithmetic with three operands (R = a op b)"),
                     "11:1: error: " + set3("arithmetic with three operands (R = a op b)"),
                     "12:8: error: " + set3("register bits (R0.2.3)"),
                     "13:1: error: " + set3("register bits (R0.15.1)"),
                     "14:2: error: " + set3("double registers (DR0.4)"),
                     "15:2: error: " + set3("double registers (DR0.6.Lo)"),
                     "16:9: error: " + set3("double registers (DR0.8)"),
                     "17:12: error: " + set3("double registers (DR0.10.Hi)")}));
    EXPECT_EQ(checkUnit("A20,is3", body), Lines{});
}

TEST(InstructionSetCheck, Set2Instructions) {
    EXPECT_EQ(checkUnit("A20", {"S0.0_0", "M0.0 = TON(1s00) * T(2s00) * TPS(1s00) * IT(1s00)",
                                "M0.1 = P(M0.0) * N(/M0.0)", "(R0.1++)", "(R0.1--)", "(R0.1 += 77)",
                                "(R0.1 -= R0.2)", "(R0.1 = R0.2)", "(R0.1 = -7) = (R0.2 >= 4)",
                                "M0.2 = TON(R0.3)"}),
              Lines{});
}

TEST(InstructionSetCheck, MessageNamesTheUnitsType) {
    EXPECT_EQ(checkUnit("B46", {"S0.0_0", "(R0.1 *= 2)"}),
              (Lines{"5:1: error: " + set3("multiplication and division", "B46")}));
    EXPECT_EQ(checkUnit("B42_ASi,is2", {"S0.0_0", "M0.0 = TOF(1s00)"}),
              (Lines{"5:8: error: " + set3("the off-delay timer TOF", "B42_ASi")}));
    EXPECT_EQ(
        check(
            {"! id_pluto:12=000000000000", "! pgm_pluto:12", "S12.0_0", "(R12.1 = R12.2 * R12.3)"}),
        (Lines{"4:1: error: arithmetic with three operands (R = a op b): only with instruction "
               "set 3; unit 12 uses instruction set 2 (declare '! type_pluto:12=A20,is3')"}));
}

// ===== Registers and double registers

TEST(RegisterCheck, DoubleRegisterHasEvenNumber) {
    EXPECT_EQ(
        checkUnit("A20,is3", {"S0.0_0", "(DR0.3 = 5)", "M0.0 = (DR0.5.Lo > 1)", "(DR0.7.Hi = 2)",
                              "(DR0.148 = 1)", "(DR0.149 = 1)"}),
        (Lines{"5:2: error: DR0.3: a double register has an even number (DR0.2 is R0.2 and R0.3)",
               "6:9: error: DR0.5.Lo: a double register has an even number (DR0.4 is R0.4 and "
               "R0.5)",
               "7:2: error: DR0.7.Hi: a double register has an even number (DR0.6 is R0.6 and "
               "R0.7)",
               "9:2: error: DR0.149: a double register has an even number (DR0.148 is R0.148 and "
               "R0.149)"}));
}

TEST(RegisterCheck, HalvesOfAUsedDoubleRegisterAreWrittenLoAndHi) {
    EXPECT_EQ(
        checkUnit("A20,is3", {"S0.0_0", "(DR0.4 = 70000)", "(R0.4 = 1)", "(R0.5 += 2)",
                              "M0.0 = R0.5.3", "M0.1 = (R0.4 > 2)", "M0.2 = TON(R0.5)",
                              "(R0.6 = R0.3)", "(DR0.4.Lo = 1)", "(DR0.4.Hi = R0.7)"}),
        (Lines{"6:2: error: R0.4 is half of DR0.4 (used at line 5); write DR0.4.Lo",
               "7:2: error: R0.5 is half of DR0.4 (used at line 5); write DR0.4.Hi",
               "8:8: error: R0.5.3 is a bit of R0.5, which is half of DR0.4 (used at line 5); bits "
               "of a double register cannot be addressed",
               "9:9: error: R0.4 is half of DR0.4 (used at line 5); write DR0.4.Lo",
               "10:12: error: R0.5 is half of DR0.4 (used at line 5); write DR0.4.Hi"}));
    // Whether the register comes before or after the double register; the
    // line is the first use of the double register.
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "(R0.4 = 1)", "(DR0.4.Hi = 70)", "(DR0.4 += 1)"}),
              (Lines{"5:2: error: R0.4 is half of DR0.4 (used at line 6); write DR0.4.Lo"}));
    // Through a name, and in a sequence.
    EXPECT_EQ(
        checkUnit("A20,is3", {"! R0.11=Count", "S0.0_0", "(DR0.10 = 0)", "S0.1_0", "(Count++)"}),
        (Lines{"8:2: error: R0.11 is half of DR0.10 (used at line 6); write DR0.10.Hi"}));
}

TEST(RegisterCheck, DoubleRegisterCannotBeDivided) {
    const std::string divided = ": a double register cannot be divided; divide into a register, "
                                "as in (R0.1 = DR0.2 / R0.4)";
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "(DR0.4 /= 2)", "(DR0.4 = DR0.6 / R0.1)",
                                    "(R0.1 = DR0.6 / R0.2)", "(DR0.4.Lo /= 2)",
                                    "(DR0.8 = R0.1 * R0.2)", "(DR0.8 *= R0.2)"}),
              (Lines{"5:2: error: DR0.4" + divided, "6:2: error: DR0.4" + divided}));
    EXPECT_EQ(checkUnit("A20,is3", {"! DR0.4=Total", "S0.0_0", "(Total /= R0.1)"}),
              (Lines{"6:2: error: 'Total' (DR0.4)" + divided}));
}

TEST(RegisterCheck, DoubleRegisterCannotBeADivisor) {
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "(R0.1 /= DR0.6)", "(R0.1 = R0.2 / DR0.6)",
                                    "(R0.1 = DR0.6 / DR0.8.Lo)"}),
              (Lines{"5:10: error: a double register cannot be a divisor",
                     "6:16: error: a double register cannot be a divisor"}));
}

TEST(RegisterCheck, DivisionByConstantZero) {
    EXPECT_EQ(
        checkUnit("A20,is3", {"S0.0_0", "(R0.1 /= 0)", "(R0.1 = R0.2 / 0)", "(R0.1 = 0 / R0.2)",
                              "(R0.1 = R0.2 / -0)", "(R0.1 *= 0)", "(R0.1 /= 1)"}),
        (Lines{"5:10: warning: division by zero: the result is 0 and SM_DivByZero is set",
               "6:16: warning: division by zero: the result is 0 and SM_DivByZero is set",
               "8:16: warning: division by zero: the result is 0 and SM_DivByZero is set"}));
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "(DR0.4 /= 0)"}),
              (Lines{"5:2: error: DR0.4: a double register cannot be divided; divide into a "
                     "register, as in (R0.1 = DR0.2 / R0.4)",
                     "5:11: warning: division by zero: the result is 0 and SM_DivByZero is set"}));
}

TEST(ConstantCheck, RegisterConstantsAre16Bit) {
    const std::string r = " does not fit a register (-32768..32767)";
    EXPECT_EQ(
        checkUnit("A20,is3", {"S0.0_0", "(R0.1 = 32767)", "(R0.1 = -32768)", "(R0.1 = 32768)",
                              "(R0.1 = -32769)", "(R0.1 += 40000)", "(R0.1 -= 99999)",
                              "(R0.1 = R0.2 + 40000)", "(R0.1 = 40000 * R0.2)",
                              "(DR0.20.Lo = 40000)", "(SR0.10 = 40000)", "(R0.1 *= -40000)"}),
        (Lines{"7:9: error: 32768" + r, "8:9: error: -32769" + r, "9:10: error: 40000" + r,
               "10:10: error: 99999" + r, "11:16: error: 40000" + r, "12:9: error: 40000" + r,
               "13:14: error: 40000" + r, "14:11: error: 40000" + r, "15:10: error: -40000" + r}));
}

TEST(ConstantCheck, DoubleRegisterConstantsAre32Bit) {
    const std::string dr = " does not fit a double register (32 bits)";
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "(DR0.2 = 2147483647)", "(DR0.2 = -2147483648)",
                                    "(DR0.2 = 2147483648)", "(DR0.2 = -2147483649)",
                                    "(DR0.2 += 70000)", "(DR0.2 = DR0.4 + 9999999999)"}),
              (Lines{"7:10: error: 2147483648" + dr, "8:10: error: -2147483649" + dr,
                     "10:18: error: 9999999999" + dr}));
}

TEST(ConstantCheck, ComparedConstantsAre32Bit) {
    const std::string dr = " does not fit a double register (32 bits)";
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "M0.0 = (DR0.2 > -2147483649)",
                                    "M0.1 = (R0.1 > 9999999999)", "M0.2 = (DR0.2 < 2147483647)"}),
              (Lines{"5:17: error: -2147483649" + dr,
                     "6:16: error: 9999999999 does not fit a register (-32768..32767)"}));
}

// ===== Timers

TEST(TimerCheck, AtMost50TimersPerUnit) {
    Lines body{"S0.0_0"};
    for (int i = 0; i < 50; ++i)
        body.push_back("M0." + std::to_string(i) + " = TON(1s00)");
    EXPECT_EQ(checkUnit("A20,is3", body), Lines{});

    body.push_back("M0.50 = I0.0 * TPS(1s00)"); // line 55, the 51st timer
    body.push_back("M0.51 = TON(1s00)");        // the 52nd is not reported again
    EXPECT_EQ(checkUnit("A20,is3", body, kQuiet),
              (Lines{"55:16: error: more than 50 timers in unit 0"}));

    // Timers in sequences count; two on one line are two timers.
    Lines mixed{"S0.0_0"};
    for (int i = 0; i < 25; ++i)
        mixed.push_back("M0." + std::to_string(i) + " = TON(1s00) * T(2s00)");
    mixed.push_back("S0.1_0");                    // line 30
    mixed.push_back("M0.100 = M0.1 * /IT(1s00)"); // line 31
    EXPECT_EQ(checkUnit("A20,is3", mixed), (Lines{"31:17: error: more than 50 timers in unit 0"}));
}

TEST(TimerCheck, TimersAreCountedPerUnit) {
    Lines lines{"! id_pluto:00=000000000000", "! id_pluto:01=000000000000", "! pgm_pluto:00",
                "S0.0_0"};
    for (int i = 0; i < 30; ++i)
        lines.push_back("M0." + std::to_string(i) + " = TON(1s00)");
    lines.push_back("! pgm_pluto:01");
    lines.push_back("S1.0_0");
    for (int i = 0; i < 30; ++i)
        lines.push_back("M1." + std::to_string(i) + " = TON(1s00)");
    EXPECT_EQ(check(lines), Lines{});
}

TEST(TimerCheck, TimeBetween0s01And655s35) {
    // The parser stores hundredths: 655s36 is 65536.
    const std::string range = "a time must be between 0s01 and 655s35, not ";
    EXPECT_EQ(checkUnit("A20,is3",
                        {"S0.0_0", "M0.0 = TON(0s00)", "M0.1 = TON(655s35)", "M0.2 = TON(655s36)",
                         "M0.3 = TPS(0s01)", "M0.4 = M0.9 * TOF(999999s99)", "M0.5 = /TON(0s0)",
                         "M0.6 = T(0s1)", "M0.7 = IT(1000s00)"}),
              (Lines{"5:8: error: " + range + "0s00", "7:8: error: " + range + "655s36",
                     "9:15: error: " + range + "999999s99", "10:8: error: " + range + "0s00",
                     "12:8: error: " + range + "1000s00"}));
}

// ===== Addresses: what each unit type has

TEST(AddressCheck, VariablesOutsideTheA20) {
    const std::string a20 = " does not exist on unit 0, an A20";
    EXPECT_EQ(
        checkUnit("A20,is3",
                  {"S0.0_0",
                   "M0.0 = M0.600",        // 5
                   "M0.1 = GM0.12",        // 6
                   "M0.2 = I0.20",         // 7
                   "Q0.4 = M0.0",          // 8
                   "M0.3 = SM0.200",       // 9
                   "(R0.150 = 1)",         // 10
                   "(SR0.100 = 1)",        // 11
                   "M0.4 = (DR0.150 > 1)", // 12
                   "M0.5 = R0.1.16",       // 13
                   "M0.6 = IQ0.4",         // 14
                   "M0.7 = IA0.0",         // 15
                   "M0.8 = ASi0.1",        // 16
                   "ASq0.1.1 = M0.0",      // 17
                   "M0.9 = I0.8 * Q0.18"}, // 18
                  kQuiet),
        (Lines{"5:8: error: M0.600" + a20, "6:8: error: GM0.12" + a20, "7:8: error: I0.20" + a20,
               "8:1: error: Q0.4" + a20, "9:8: error: SM0.200" + a20, "10:2: error: R0.150" + a20,
               "11:2: error: SR0.100" + a20, "12:9: error: DR0.150" + a20,
               "13:8: error: R0.1.16" + a20, "14:8: error: IQ0.4" + a20, "15:8: error: IA0.0" + a20,
               "16:8: error: ASi0.1" + a20, "17:1: error: ASq0.1.1" + a20,
               "18:8: error: I0.8" + a20, "18:15: error: Q0.18" + a20}));
    // The last of each kind exists.
    EXPECT_EQ(checkUnit("A20,is3",
                        {"S0.0_0", "M0.599 = GM0.11 * SM0.199 * (SR0.99 > 0) * (R0.149 > 0)",
                         "M0.0 = (DR0.146 > 0) * R0.145.15 * R0.0.0 * I0.17 * Q0.3 * Q0.17",
                         "GM0.11 = I0.0"},
                        kQuiet),
              Lines{});
}

TEST(AddressCheck, GlobalMemoriesOfB42AsI) {
    EXPECT_EQ(checkUnit("B42_ASi,is3", {"S0.0_0", "GM0.27 = GM0.28"}),
              (Lines{"5:10: error: GM0.28 does not exist on unit 0, a B42 AS-i"}));
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "GM0.11 = GM0.27"}),
              (Lines{"5:10: error: GM0.27 does not exist on unit 0, an A20"}));
}

TEST(AddressCheck, MemoriesOfAsIDependOnInstructionSet) {
    EXPECT_EQ(
        checkUnit("ASi", {"S0.0_0", "M0.149 = M0.150"}),
        (Lines{"5:10: error: M0.150 does not exist on unit 0, an AS-i with instruction set 2"}));
    EXPECT_EQ(checkUnit("ASi,is3", {"S0.0_0", "M0.149 = M0.150"}), Lines{});
    EXPECT_EQ(checkUnit("ASi,is3", {"S0.0_0", "M0.149 = M0.600"}),
              (Lines{"5:10: error: M0.600 does not exist on unit 0, an AS-i"}));
    // Only memories depend on it.
    EXPECT_EQ(checkUnit("ASi", {"S0.0_0", "M0.1 = GM0.12"}),
              (Lines{"5:8: error: GM0.12 does not exist on unit 0, an AS-i"}));
}

TEST(AddressCheck, AsISlaves) {
    EXPECT_EQ(checkUnit("ASi,is3", {"S0.0_0", "M0.1 = ASi0.1 * ASi0.31 * ASi0.1.4 * ASi0.31B.1",
                                    "ASq0.1.1 = M0.0", "ASq0.1B.4 = M0.0",
                                    "M0.2 = ASi0.32 * ASi0.1.5 * ASi0.0.1"}),
              // No slave is defined on the AS-i Options page: each is a warning, once.
              (Lines{"5:8: warning: ASi0.1: AS-i slave ASi0.1 is not defined on the AS-i "
                     "Options page",
                     "5:17: warning: ASi0.31: AS-i slave ASi0.31 is not defined on the AS-i "
                     "Options page",
                     "5:38: warning: ASi0.31B.1: AS-i slave ASi0.31B is not defined on the AS-i "
                     "Options page",
                     "7:1: warning: ASq0.1B.4: AS-i slave ASi0.1B is not defined on the AS-i "
                     "Options page",
                     "8:8: error: ASi0.32 does not exist on unit 0, an AS-i",
                     "8:18: error: ASi0.1.5 does not exist on unit 0, an AS-i",
                     "8:29: error: ASi0.0.1 does not exist on unit 0, an AS-i"}));
}

TEST(AddressCheck, B46HasMoreTerminals) {
    EXPECT_EQ(checkUnit("B46,is3",
                        {"S0.0_0", "Q0.4 = I0.20", "Q0.5 = I0.47 * I0.50", "Q0.27 = M0.0",
                         "Q0.6 = M0.0", "Q0.28 = M0.0"},
                        kQuiet),
              (Lines{"6:16: error: I0.50 does not exist on unit 0, a B46",
                     "8:1: error: Q0.6 does not exist on unit 0, a B46",
                     "9:1: error: Q0.28 does not exist on unit 0, a B46"}));
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "Q0.4 = I0.20"}),
              (Lines{"5:1: error: Q0.4 does not exist on unit 0, an A20",
                     "5:8: error: I0.20 does not exist on unit 0, an A20"}));
}

// ===== Access: other units, inputs, system variables

TEST(AccessCheck, UnitNotInTheProject) {
    // Its globals may come from another project on the bus (language.md); its locals may not.
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "M0.0 = I5.0", "GM0.1 = GM7.1", "(R0.1 = R3.1)"}),
              (Lines{"5:8: warning: unit 5 is not in this project; its globals come from another "
                     "project on the bus",
                     "6:9: warning: unit 7 is not in this project; its globals come from another "
                     "project on the bus",
                     "7:9: error: R3.1 belongs to unit 3, which the project does not have (no "
                     "'! id_pluto:03=...'); only its globals can be read"}));
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "Q12.2 = M0.0"}),
              (Lines{"5:1: error: Q12.2 belongs to unit 12, which the project does not have (no "
                     "'! id_pluto:12=...')"}));
}

namespace {
// Units 0 and 1; the code of unit 0 starts at line 4.
Lines twoUnitsLines(const Lines& code0) {
    Lines lines{"! id_pluto:00=000000000000", "! id_pluto:01=000000000001", "! pgm_pluto:00"};
    lines.insert(lines.end(), code0.begin(), code0.end());
    lines.push_back("! pgm_pluto:01");
    lines.push_back("S1.0_0");
    return lines;
}
} // namespace

TEST(AccessCheck, WritingAnotherUnitsVariable) {
    const std::string own = "; a unit writes only its own variables";
    EXPECT_EQ(
        check(twoUnitsLines({"S0.0_0", "Q1.2 = M0.0", "M1.0 = M0.0", "GM1.0 = M0.0", "(R1.0 = 1)",
                             "S(M1.0) = M0.0", "R(Q1.2) = M0.0", "T(GM1.1) = M0.0"})),
        (Lines{
            "5:1: error: Q1.2 belongs to unit 1" + own, "6:1: error: M1.0 belongs to unit 1" + own,
            "7:1: error: GM1.0 belongs to unit 1" + own, "8:2: error: R1.0 belongs to unit 1" + own,
            "9:3: error: M1.0 belongs to unit 1" + own, "10:3: error: Q1.2 belongs to unit 1" + own,
            "11:3: error: GM1.1 belongs to unit 1" + own}));
}

TEST(AccessCheck, ReadingAnotherUnitsVariables) {
    // Global: inputs, safety outputs Q0..Q3, global memories.
    EXPECT_EQ(check(twoUnitsLines({"S0.0_0", "M0.0 = I1.0 * Q1.2 * GM1.3 * I1.17 * IQ1.10 * Q1.0"}),
                    kQuiet),
              Lines{});
    const std::string local = " and not exported; other units cannot read it";
    EXPECT_EQ(check(twoUnitsLines({"S0.0_0", "M0.1 = M1.0", "M0.2 = Q1.10", "M0.3 = (R1.0 > 1)",
                                   "M0.4 = SM1.9", "M0.5 = (SR1.10 > 0)"}),
                    kQuiet),
              (Lines{"5:8: error: M1.0 is local to unit 1" + local,
                     "6:8: error: Q1.10 is local to unit 1" + local,
                     "7:9: error: R1.0 is local to unit 1" + local,
                     "8:8: error: SM1.9 is local to unit 1" + local,
                     "9:9: error: SR1.10 is local to unit 1" + local}));
    // A name declared for all units does not make a local variable global.
    EXPECT_EQ(check({"! id_pluto:00=000000000000", "! id_pluto:01=000000000001", "! M1.5=Remote",
                     "! pgm_pluto:00", "S0.0_0", "M0.0 = Remote", "! pgm_pluto:01", "S1.0_0",
                     "M1.5 = M1.0"}),
              (Lines{"6:8: error: 'Remote' (M1.5) is local to unit 1" + local}));
}

TEST(AccessCheck, ReadingExportedVariablesOfAnotherUnit) {
    // Unit 1 (instruction set 3) exports a memory, a register and a double
    // register; unit 0 reads them, a register's bit and a half included.
    const Lines program{"! id_pluto:00=000000000000",
                        ";@var M1.3 export=\"yes\"",
                        ";@var R1.7 export=\"yes\"",
                        ";@var DR1.4 export=\"yes\"",
                        "! id_pluto:01=000000000001",
                        "! type_pluto:00=A20,is3",
                        "! type_pluto:01=A20,is3",
                        "! pgm_pluto:00",
                        "S0.0_0",
                        "M0.0 = M1.3 * R1.7.2",
                        "M0.1 = (R1.7 > 5) * (DR1.4 > 70000) * (DR1.4.Lo > 1)",
                        "M0.2 = M1.4",
                        "! pgm_pluto:01",
                        "S1.0_0",
                        "M1.3 = I1.0"};
    EXPECT_EQ(check(program, kQuiet),
              (Lines{"12:8: error: M1.4 is local to unit 1 and not exported; other units cannot "
                     "read it"}));
}

TEST(AccessCheck, ExportsTheOriginalToolWouldRefuse) {
    // A file edited by hand: a unit with instruction set 2 cannot export, a
    // global variable needs no export, and a unit adds at most 4 telegram pairs
    // (here 5 double registers, one pair each).
    EXPECT_EQ(check({"! id_pluto:00=000000000000", ";@var M0.3 export=\"yes\"",
                     "! id_pluto:01=000000000001", ";@var Q1.2 export=\"yes\"",
                     ";@var DR1.0 export=\"yes\"", ";@var DR1.2 export=\"yes\"",
                     ";@var DR1.4 export=\"yes\"", ";@var DR1.6 export=\"yes\"",
                     ";@var DR1.8 export=\"yes\"", "! type_pluto:01=A20,is3", "! pgm_pluto:00",
                     "S0.0_0", "! pgm_pluto:01", "S1.0_0"},
                    kQuiet),
              (Lines{"1:1: error: M0.3 cannot be exported: export variables need instruction set 3",
                     "3:1: error: Q1.2 is global: the other units see it already",
                     "3:1: error: unit 1 exports variables for 5 extra telegram pairs; a unit "
                     "may add 4"}));
}

TEST(AccessCheck, ReadingTheLocalInputsOfAnotherFamily) {
    // A B46's I20.. and Q4/Q5 are local; an A20 reads its I0..I17 and Q0..Q3.
    EXPECT_EQ(
        check({"! id_pluto:00=000000000000", "! id_pluto_Double:01=000000000001", "! pgm_pluto:00",
               "S0.0_0", "M0.0 = I1.17 * Q1.3 * I1.20 * Q1.4", "! pgm_pluto:01", "S1.0_0"},
              kQuiet),
        (Lines{
            "5:23: error: I1.20 is local to unit 1 and not exported; other units cannot read it",
            "5:31: error: Q1.4 is local to unit 1 and not exported; other units cannot read it"}));
}

TEST(AccessCheck, WritingAnInput) {
    const std::string input = " is an input; the program cannot write it";
    EXPECT_EQ(checkUnit("D20,is3", {"! IA0.0,voltage", "! I0.4,static", "! I0.5=Start", "S0.0_0",
                                    "I0.4 = M0.0", "S(IA0.0) = M0.0", "(IA0.0 = 5)",
                                    "R(Start) = M0.0", "T(I0.6) = M0.0"}),
              (Lines{"8:1: error: I0.4" + input, "9:3: error: IA0.0" + input,
                     "10:2: error: IA0.0" + input, "11:3: error: 'Start' (I0.5)" + input,
                     "12:3: error: I0.6" + input}));
    EXPECT_EQ(
        checkUnit("ASi,is3", {"S0.0_0", "ASi0.1 = M0.0", "ASq0.1.1 = M0.0", "ASi0.1.1 = M0.0"}),
        (Lines{"5:1: warning: ASi0.1: AS-i slave ASi0.1 is not defined on the AS-i Options page",
               "5:1: error: ASi0.1" + input, "7:1: error: ASi0.1.1" + input}));
}

TEST(AccessCheck, ReadOnlySystemMemoriesAndRegisters) {
    EXPECT_EQ(
        checkUnit("A20,is3", {"! SR0.2=Rem", "S0.0_0", "SM0.9 = M0.0", "SM0.8 = M0.0",
                              "S(SM0.150) = M0.0", "(SR0.2 = 1)", "(SR0.60 += 1)", "(Rem = 1)"}),
        (Lines{"6:1: error: SM0.9 (SM_SysInit)" + kReadOnly, "7:1: error: SM0.8" + kReadOnly,
               "8:3: error: SM0.150" + kReadOnly, "9:2: error: SR0.2 (SR_Remain)" + kReadOnly,
               "10:2: error: SR0.60" + kReadOnly,
               "11:2: error: 'Rem' (SR0.2) (SR_Remain)" + kReadOnly}));
}

TEST(AccessCheck, TimerFreezeAndPlutoDisplayAreWritable) {
    EXPECT_EQ(
        checkUnit("A20,is3", {"S0.0_0", "SM_TimerFreeze = M0.0", "S(SM0.10) = M0.2",
                              "(SR0.10 = 201)", "(SR_PlutoDisplay = 202) = M0.3", "(SR0.10 += 1)",
                              "M0.4 = SM0.9 * (SR0.2 > 0) * SM_TimerFreeze"}),
        // Writable, so no errors; a coil that is also latched is worth a warning.
        (Lines{"6:3: warning: SM0.10 is both a coil and latched with S(...)/R(...) (see line 5); "
               "the coil sets it every scan the line runs"}));
}

// ===== I/O declarations and the code

TEST(TerminalCheck, UnconfiguredIoWarnsOncePerAddress) {
    const Lines body{"S0.0_0",
                     "Q0.10 = I0.0",        // 5
                     "Q0.11 = I0.0 * I0.1", // 6
                     "M0.0 = Q0.10 * IQ0.12 * Q0.2",
                     "IQ0.12 = M0.0",        // 8
                     "Q0.2 = I0.1 * IQ0.13", // 9
                     "M0.1 = I0.10 * I0.13"};
    EXPECT_EQ(
        checkUnit("A20,is3", body),
        (Lines{"5:1: warning: unconfigured I/O: Q0.10 has no I/O declaration in the code of unit 0",
               "5:9: warning: unconfigured I/O: I0.0 has no I/O declaration in the code of unit 0",
               "6:1: warning: unconfigured I/O: Q0.11 has no I/O declaration in the code of unit 0",
               "6:16: warning: unconfigured I/O: I0.1 has no I/O declaration in the code of unit 0",
               "7:16: warning: unconfigured I/O: IQ0.12 has no I/O declaration in the code of "
               "unit 0",
               "9:15: warning: unconfigured I/O: IQ0.13 has no I/O declaration in the code of "
               "unit 0",
               "10:8: warning: unconfigured I/O: I0.10 has no I/O declaration in the code of unit "
               "0",
               "10:16: warning: unconfigured I/O: I0.13 has no I/O declaration in the code of "
               "unit 0"}));
    EXPECT_EQ(checkUnit("A20,is3", body, kQuiet), Lines{});
}

TEST(TerminalCheck, UnconfiguredAnalogueInputs) {
    EXPECT_EQ(
        checkUnit("D20,is3", {"! IA0.2,current", "S0.0_0",
                              "M0.0 = IA0.0 * (IA0.1 > 2) * (IA0.0 > 3) * (IA0.2 > 4)"}),
        (Lines{"6:8: warning: unconfigured I/O: IA0.0 has no I/O declaration in the code of unit 0",
               "6:17: warning: unconfigured I/O: IA0.1 has no I/O declaration in the code of unit "
               "0"}));
}

TEST(TerminalCheck, UnconfiguredInputOfAnotherUnit) {
    EXPECT_EQ(check({"! id_pluto:00=000000000000", "! id_pluto:01=000000000001", "! pgm_pluto:00",
                     "S0.0_0", "M0.0 = I1.0 * I1.1", "M0.1 = I1.0", "! pgm_pluto:01",
                     "! I1.1,static", "S1.0_0"}),
              (Lines{"5:8: warning: unconfigured I/O: I1.0 has no I/O declaration in the code of "
                     "unit 1"}));
}

TEST(TerminalCheck, DeclaredUseMustMatch) {
    const Lines body{"! I0.10,a_pulse",  // 4
                     "! Q0.11,static",   // 5
                     "! IQ0.12,a_pulse", // 6
                     "! I0.13,a_pulse",  // 7
                     "S0.0_0",
                     "Q0.10 = M0.0", // 9: output on an input terminal
                     "M0.1 = I0.11", // 10: input on an output terminal
                     "M0.2 = Q0.10", // 11: reading it says which input to read
                     "M0.3 = I0.12 * Q0.12 * IQ0.13 * IQ0.11 * IQ0.10",
                     "S(Q0.13) = M0.0", // 13
                     "IQ0.12 = M0.1",
                     "Q0.11 = M0.1",
                     "M0.5 = Q0.11 * I0.10 * Q0.12"};
    EXPECT_EQ(checkUnit("A20,is3", body),
              (Lines{"9:1: error: Q0.10: terminal 10 is declared as an input at line 4",
                     "10:8: error: I0.11: terminal 11 is declared as an output at line 5",
                     "11:8: error: Q0.10: terminal 10 is declared as an input at line 4; read the "
                     "input I0.10 instead",
                     "12:24: error: IQ0.13: terminal 13 is declared as an input at line 7, not as "
                     "an illuminated push button (IQ)",
                     "12:33: error: IQ0.11: terminal 11 is declared as an output at line 5, not as "
                     "an illuminated push button (IQ)",
                     "12:42: error: IQ0.10: terminal 10 is declared as an input at line 4, not as "
                     "an illuminated push button (IQ)",
                     "13:3: error: Q0.13: terminal 13 is declared as an input at line 7"}));
}

TEST(TerminalCheck, DeclaredUseOfAnotherUnitsTerminal) {
    EXPECT_EQ(check({"! id_pluto:00=000000000000", "! id_pluto:01=000000000001", "! pgm_pluto:00",
                     "S0.0_0", "M0.0 = I1.10 * IQ1.11", "! pgm_pluto:01", "! Q1.10,static",
                     "! I1.11,a_pulse", "S1.0_0"}),
              (Lines{"5:8: error: I1.10: terminal 10 is declared as an output at line 7",
                     "5:16: error: IQ1.11: terminal 11 is declared as an input at line 8, not as "
                     "an illuminated push button (IQ)"}));
}

// ===== Warnings a careful reviewer would give

TEST(CoilCheck, CoilWrittenInTwoPlaces) {
    EXPECT_EQ(
        checkUnit("A20,is3", {"S0.0_0", "M0.0 = M0.1", "M0.0 = M0.1", "M0.0 = M0.2"}),
        (Lines{"6:1: warning: M0.0 is also written at line 5; the write that runs last in each "
               "scan wins",
               "7:1: warning: M0.0 is also written at line 5; the write that runs last in each "
               "scan wins"}));
    EXPECT_EQ(
        checkUnit("A20,is3", {"! M0.0=Motor", "S0.0_0", "Motor = M0.1", "M0.0"}),
        (Lines{"7:1: warning: M0.0 is also written at line 6; the write that runs last in each "
               "scan wins"}));
}

TEST(CoilCheck, StepsOfOneSequenceDoNotConflict) {
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "S0.1_0", "M0.2 = M0.1", "J(1) = M0.1", "S0.1_1",
                                    "M0.2 = M0.3", "J(0) = M0.1"}),
              Lines{});
}

TEST(CoilCheck, PlcCodeAndSequencesConflict) {
    EXPECT_EQ(
        checkUnit("A20,is3", {"S0.0_0", "M0.0 = M0.1", "S0.1_0", "M0.2 = M0.1", "J(1) = M0.1",
                              "S0.1_1", "M0.2 = M0.3", "M0.0 = M0.3", "J(0) = M0.1", "S0.2_0",
                              "M0.2 = M0.4", "M0.2 = M0.5"}),
        (Lines{"11:1: warning: M0.0 is also written at line 5; the write that runs last in each "
               "scan wins",
               "14:1: warning: M0.2 is also written at line 7; the write that runs last in each "
               "scan wins",
               "15:1: warning: M0.2 is also written at line 7; the write that runs last in each "
               "scan wins"}));
}

TEST(CoilCheck, OneStepWritingTwiceConflicts) {
    EXPECT_EQ(
        checkUnit("A20,is3", {"S0.0_0", "S0.1_0", "Q0.2 = M0.1", "Q0.2"}),
        (Lines{"7:1: warning: Q0.2 is also written at line 6; the write that runs last in each "
               "scan wins"}));
}

// Latches and toggles are not coils: no "also written". A coil that is also
// latched is a mistake of its own.
TEST(CoilCheck, LatchesAndTogglesAreNotCoils) {
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "M0.6", "S(M0.6) = M0.1", "R(M0.6) = M0.2",
                                    "T(M0.6) = M0.3", "S(M0.7) = M0.1", "S(M0.7) = M0.2"}),
              (Lines{"6:3: warning: M0.6 is both a coil and latched with S(...)/R(...) (see line "
                     "5); the coil sets it every scan the line runs"}));
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "S(M0.6) = M0.1", "M0.6 = M0.2"}),
              (Lines{"6:1: warning: M0.6 is both a coil and latched with S(...)/R(...) (see line "
                     "5); the coil sets it every scan the line runs"}));
}

TEST(StepReachCheck, StepNoJumpLeadsTo) {
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "S0.1_0", "J(+1) = M0.1", "S0.1_1", "J(0) = M0.2",
                                    "S0.1_2", "J(0) = M0.3", "S0.1_3", "J(-1) = M0.3", "S0.2_0",
                                    "M0.5 = M0.1", "S0.2_5", "J(0) = M0.3"}),
              (Lines{"11:1: warning: no jump leads to step S0.1_3",
                     "15:1: warning: no jump leads to step S0.2_5"}));
}

TEST(NameCheck, NamedButNeverUsed) {
    EXPECT_EQ(checkUnit("A20,is3", {"! M0.0=Unused", "! M0.9=Used", "S0.0_0", "M0.1 = Used"}),
              (Lines{"4:8: warning: 'Unused' (M0.0) is named but never used"}));
    EXPECT_EQ(check({"! id_pluto:00=000000000000", "! I0.0=Global", "! pgm_pluto:00",
                     "! R0.4=Local", "S0.0_0"}),
              (Lines{"2:8: warning: 'Global' (I0.0) is named but never used",
                     "4:8: warning: 'Local' (R0.4) is named but never used"}));
}

TEST(NameCheck, UsesThroughHalvesBitsAddressesAndOtherUnits) {
    EXPECT_EQ(checkUnit("A20,is3", {"! R0.4=Reg", "! DR0.6=Big", "! R0.10=Bits", "! DR0.12=Other",
                                    "! M0.9=Plain", "S0.0_0", "M0.1 = Reg.3", "(Big.Lo = 1)",
                                    "(DR0.12.Hi = 2)", "M0.2 = R0.10.1", "M0.3 = M0.9"}),
              Lines{});
    // A name given for all units and used by another unit.
    EXPECT_EQ(check({"! id_pluto:00=000000000000", "! id_pluto:01=000000000001", "! GM1.0=Shared",
                     "! pgm_pluto:00", "S0.0_0", "M0.0 = Shared", "! pgm_pluto:01", "S1.0_0"}),
              Lines{});
}

// ===== The manual's example

TEST(ManualMutingCheck, MutingGivesOnlyTheUnconfiguredQ17Warning) {
    std::ifstream file(RUNGSMITH_TEST_DATA "/manual/manual_muting.sps");
    ASSERT_TRUE(file) << RUNGSMITH_TEST_DATA "/manual/manual_muting.sps";
    std::stringstream text;
    text << file.rdbuf();
    const CompileResult result = compileText(text.str());
    EXPECT_EQ(diagnosticsOf(result),
              (Lines{"37:1: warning: unconfigured I/O: Q0.17 has no I/O declaration in the code of "
                     "unit 0"}));
    EXPECT_EQ(result.errors(), 0);
    ASSERT_EQ(result.images.size(), 1u);
    EXPECT_EQ(diagnosticsOf(compileText(text.str(), kQuiet)), Lines{});
}

TEST(ManualMutingCheck, ErrorsMeanNoImages) {
    const CompileResult result = compileText(join(program("A20,is3", {"S0.0_0", "M0.0 = M0.600"})));
    EXPECT_EQ(result.errors(), 1);
    EXPECT_TRUE(result.images.empty());
    // Warnings alone do not stop the images.
    const CompileResult warned =
        compileText(join(program("A20,is3", {"! M0.3=Spare", "S0.0_0", "M0.0 = M0.1"})));
    EXPECT_EQ(warned.errors(), 0);
    EXPECT_EQ(warned.images.size(), 1u);
}

// ===== Behaviour that was wrong when these tests were written, now fixed.

TEST(WriteCheck, SystemNameIsShownOnce) {
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "SM_SysInit = M0.0", "(SR_Remain = 1)"}),
              (Lines{"5:1: error: 'SM_SysInit' (SM0.9)" + kReadOnly,
                     "6:2: error: 'SR_Remain' (SR0.2)" + kReadOnly}));
}

// Only an AS-i has more memories with instruction set 3, so only there does the hint help.
TEST(AddressCheck, InstructionSet2IsNamedOnlyWhereSet3HasMoreMemories) {
    EXPECT_EQ(checkUnit("A20", {"S0.0_0", "M0.0 = M0.600"}),
              (Lines{"5:8: error: M0.600 does not exist on unit 0, an A20"}));
    EXPECT_EQ(checkUnit("B46,is2", {"S0.0_0", "M0.0 = M0.600"}),
              (Lines{"5:8: error: M0.600 does not exist on unit 0, a B46"}));
}

TEST(AddressCheck, StationNumberOutside0To31InAnOperand) {
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "M0.0 = M40.0"}),
              (Lines{"5:8: error: M40.0 belongs to unit 40, but stations are numbered 0-31"}));
}

TEST(IoOptionCheck, OutputsTheTypeDoesNotHave) {
    expectIo({
        {"A20,is3", "! Q0.20,static", "4:3: error: an A20 has no output Q0.20"},
        {"B22,is3", "! Q0.2,no_test_pulse", "4:3: error: a B22 has no output Q0.2"},
    });
}

TEST(CoilCheck, CoilOnQAndIqOfOneTerminal) {
    EXPECT_EQ(checkUnit("A20,is3", {"! IQ0.12,a_pulse", "S0.0_0", "IQ0.12 = M0.0", "Q0.12 = M0.1"}),
              (Lines{"7:1: warning: Q0.12 is also written at line 6; the write that runs last in "
                     "each scan wins"}));
}

TEST(CoilCheck, TheWriteThatRunsLastWins) {
    EXPECT_EQ(checkUnit("A20,is3", {"S0.1_0", "M0.0 = M0.1", "S0.0_0", "M0.0 = M0.2"}),
              (Lines{"5:1: warning: M0.0 is also written at line 7; the write that runs last in "
                     "each scan wins"}));
}

TEST(UnusedNameCheck, NameOfABitOrHalfUsedThroughAnother) {
    EXPECT_EQ(checkUnit("A20,is3", {"! R0.4.3=Bit", "! DR0.6.Lo=Low", "S0.0_0", "M0.0 = R0.4.5",
                                    "(DR0.6.Hi = 1)"}),
              (Lines{"4:10: warning: 'Bit' (R0.4.3) is named but never used",
                     "5:12: warning: 'Low' (DR0.6.Lo) is named but never used"}));
}

// ===== Checks added after review

TEST(ConstantCheck, ComparedConstantOutsideA16BitRegister) {
    EXPECT_EQ(checkUnit("A20,is3", {"S0.0_0", "M0.0 = (R0.1 > 70000)"}),
              (Lines{"5:16: error: 70000 does not fit a register (-32768..32767)"}));
}
