// SPDX-License-Identifier: GPL-3.0-or-later
#include "project/IoOptions.h"
#include "ProjectText.h"
#include "compiler/UnitSetup.h"
#include "project/ProjectProperties.h"
#include "project/UnitSettings.h"

#include <gtest/gtest.h>

using namespace rs;
using project::SignalShape;
using project::SignalType;
using project::Terminal;
using project::TerminalKind;
using project::TerminalSetting;

namespace {

std::vector<std::string> terminalLabels(const std::vector<Terminal>& terminals) {
    std::vector<std::string> list;
    for (const auto& t : terminals)
        list.push_back(t.label());
    return list;
}

project::Project projectWith(target::UnitType type, int instructionSet = 3) {
    project::Project p = project::newProject("IO", {}, false);
    project::UnitSettings unit;
    unit.station = 2;
    unit.type = type;
    unit.instructionSet = project::supportsInstructionSet3(type) ? instructionSet : 2;
    EXPECT_FALSE(project::addUnit(p, unit));
    return p;
}

// Every setting the page can offer for a terminal: each type of signal, each
// shape offered for it, each combination of the options offered.
std::vector<TerminalSetting> offeredSettings(const target::UnitTypeInfo& type,
                                             const Terminal& terminal) {
    std::vector<TerminalSetting> settings;
    auto types = project::signalTypes(type, terminal);
    if (types.empty())
        types.push_back(SignalType::Undefined);
    for (SignalType signal : types) {
        auto shapes = project::signalShapes(terminal, signal);
        if (shapes.empty())
            shapes.push_back(SignalShape::None);
        for (SignalShape shape : shapes) {
            TerminalSetting base{signal, shape};
            const auto options = project::terminalOptions(type, terminal, base);
            for (unsigned mask = 0; mask < (1u << options.size()); ++mask) {
                TerminalSetting setting = base;
                for (std::size_t i = 0; i < options.size(); ++i) {
                    if (!(mask & (1u << i)))
                        continue;
                    switch (options[i]) {
                    case project::TerminalOption::NonInverted:
                        setting.nonInverted = true;
                        break;
                    case project::TerminalOption::NoFilter:
                        setting.noFilter = true;
                        break;
                    case project::TerminalOption::CrossTalk:
                        setting.crossTalk = true;
                        break;
                    case project::TerminalOption::NoTestPulse:
                        setting.noTestPulse = true;
                        break;
                    }
                }
                settings.push_back(setting);
            }
        }
    }
    return settings;
}

} // namespace

TEST(IoOptions, TheA20ListsItsInputsItsConfigurableTerminalsAndQ2Q3) {
    const auto& a20 = target::unitTypeInfo(target::UnitType::A20);
    const auto terminals = project::terminalsOf(a20, 0);
    EXPECT_EQ(terminalLabels(terminals),
              (std::vector<std::string>{"I0.0", "I0.1", "I0.2", "I0.3", "I0.4", "I0.5", "I0.6",
                                        "I0.7", "IQ0.10", "IQ0.11", "IQ0.12", "IQ0.13", "IQ0.14",
                                        "IQ0.15", "IQ0.16", "IQ0.17", "Q0.2", "Q0.3"}));
    const Terminal iq{TerminalKind::Configurable, 0, 14};
    EXPECT_EQ(project::signalTypes(a20, iq),
              (std::vector<SignalType>{SignalType::Undefined, SignalType::Input, SignalType::Output,
                                       SignalType::LightButton}));
    EXPECT_EQ(
        project::signalShapes(iq, SignalType::LightButton),
        (std::vector<SignalShape>{SignalShape::APulse, SignalShape::BPulse, SignalShape::CPulse}));
}

TEST(IoOptions, OtherTypesListWhatTheirTablesSay) {
    // A B22 has no safety outputs, so its list ends with its local inputs.
    const auto b22 =
        terminalLabels(project::terminalsOf(target::unitTypeInfo(target::UnitType::B22), 1));
    EXPECT_EQ(b22.back(), "I1.25");
    const auto d45 = project::terminalsOf(target::unitTypeInfo(target::UnitType::D45), 0);
    EXPECT_EQ(d45.front().label(), "IA0.0");
    EXPECT_EQ(terminalLabels(d45).at(8), "IQ0.10");
    const auto& d45Info = target::unitTypeInfo(target::UnitType::D45);
    EXPECT_EQ(project::signalTypes(d45Info, {TerminalKind::Analogue, 0, 3}).size(), 6u);
    EXPECT_EQ(project::signalTypes(d45Info, {TerminalKind::Analogue, 0, 4}).size(), 4u);
    const auto b46 =
        terminalLabels(project::terminalsOf(target::unitTypeInfo(target::UnitType::B46), 0));
    EXPECT_EQ(std::count(b46.begin(), b46.end(), "Q0.2"), 0); // no test-pulse option
}

TEST(IoOptions, ChoicesFollowTheManualsRules) {
    const auto& a20 = target::unitTypeInfo(target::UnitType::A20);
    const Terminal input{TerminalKind::Input, 0, 3};
    const Terminal iq{TerminalKind::Configurable, 0, 12};
    using O = project::TerminalOption;
    // Static: no Non_Inv; dynamic: Non_Inv; x_talk only on I10..I17.
    EXPECT_EQ(project::terminalOptions(a20, input, {SignalType::Input, SignalShape::Static}),
              (std::vector<O>{O::NoFilter}));
    EXPECT_EQ(project::terminalOptions(a20, input, {SignalType::Input, SignalShape::APulse}),
              (std::vector<O>{O::NonInverted, O::NoFilter}));
    EXPECT_EQ(project::terminalOptions(a20, iq, {SignalType::Input, SignalShape::BPulse}),
              (std::vector<O>{O::NonInverted, O::NoFilter, O::CrossTalk}));
    EXPECT_TRUE(
        project::terminalOptions(a20, iq, {SignalType::Output, SignalShape::APulse}).empty());
    // What cannot be chosen is dropped, not written.
    TerminalSetting wanted{SignalType::Input, SignalShape::Static, true, true, true, true};
    EXPECT_EQ(project::legalSetting(a20, input, wanted),
              (TerminalSetting{SignalType::Input, SignalShape::Static, false, true}));
    EXPECT_EQ(project::legalSetting(a20, input, {SignalType::LightButton}), TerminalSetting{});
    EXPECT_EQ(project::legalSetting(a20, iq, {SignalType::LightButton, SignalShape::Static}),
              (TerminalSetting{SignalType::LightButton, SignalShape::APulse}));
}

// The page cannot produce a declaration the compiler's unit setup refuses (it
// may warn, as about I10..I17 static),
// and each one reads back as the setting that wrote it.
TEST(IoOptions, EveryOfferedSettingIsADeclarationTheCompilerAccepts) {
    int checked = 0;
    for (const auto& type : target::unitTypes()) {
        project::Project base = projectWith(type.type);
        for (const Terminal& terminal : project::terminalsOf(type, 2)) {
            for (const TerminalSetting& setting : offeredSettings(type, terminal)) {
                project::Project p = base;
                const TerminalSetting written = project::setTerminalSetting(p, terminal, setting);
                ASSERT_EQ(written, setting) << type.name << " " << terminal.label();
                EXPECT_EQ(project::terminalSetting(p, terminal), setting)
                    << type.name << " " << terminal.label();
                lang::Diagnostics diagnostics;
                compiler::collectUnits(p.program, diagnostics);
                for (const auto& d : diagnostics)
                    if (d.severity == lang::Severity::Error)
                        ADD_FAILURE() << type.name << " " << terminal.label() << ": " << d.message;
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 1000);
}

TEST(IoOptions, DeclarationsAreWrittenInTerminalOrderAndReplacedInPlace) {
    project::Project p = projectFrom("$name IO\n"
                                     "! id_pluto:00=000000000000\n"
                                     "! pgm_pluto:00\n"
                                     "\n"
                                     "! Q0.10,a_pulse                ; Dynamic output A\n"
                                     "! I0.12,a_pulse                ; Emergency stop PB\n"
                                     "\n"
                                     "! M0.0=Muting\n"
                                     "S0.0_0\n");
    project::setTerminalSetting(p, {TerminalKind::Input, 0, 1},
                                {SignalType::Input, SignalShape::APulse, true});
    project::setTerminalSetting(p, {TerminalKind::Configurable, 0, 12},
                                {SignalType::Input, SignalShape::CPulse, false, true});
    project::setTerminalSetting(p, {TerminalKind::Configurable, 0, 10}, {});
    project::setTerminalSetting(
        p, {TerminalKind::SafetyOutput, 0, 3},
        {SignalType::Undefined, SignalShape::None, false, false, false, true});
    EXPECT_EQ(textOf(p), "$name IO\n"
                         "! id_pluto:00=000000000000\n"
                         "! pgm_pluto:00\n"
                         "\n"
                         "! I0.1,a_pulse,non_inv\n"
                         "! I0.12,c_pulse,no_filt        ; Emergency stop PB\n"
                         "! Q0.3,no_test_pulse\n"
                         "\n"
                         "! M0.0=Muting\n"
                         "S0.0_0\n");
    EXPECT_TRUE(isStable(p));
}

TEST(IoOptions, AUnitWithoutIoDeclarationsGetsThemBeforeItsNames) {
    project::Project p = projectWith(target::UnitType::D45);
    project::setTerminalSetting(p, {TerminalKind::Analogue, 2, 1}, {SignalType::Current});
    project::setTerminalSetting(p, {TerminalKind::Analogue, 2, 0}, {SignalType::CounterUpDown});
    const std::string text = textOf(p);
    EXPECT_NE(text.find("! pgm_pluto:02\n\n! IA2.0,counter_updown\n! IA2.1,current\nS2.0_0"),
              std::string::npos)
        << text;
    EXPECT_TRUE(isStable(p));
}
