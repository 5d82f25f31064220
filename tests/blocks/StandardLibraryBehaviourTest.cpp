// SPDX-License-Identifier: GPL-3.0-or-later
#include "blocks/BodyTemplate.h"
#include "blocks/LibraryReader.h"
#include "compiler/Compiler.h"
#include "project/ProjectFile.h"
#include "sim/ScenarioRunner.h"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

using namespace rs;

namespace {

const blocks::BlockLibrary& basics() {
    static const blocks::BlockLibrary library = [] {
        std::ifstream file(RUNGSMITH_LIBRARIES "/Rungsmith_Basics.rslib", std::ios::binary);
        std::stringstream text;
        text << file.rdbuf();
        return blocks::readLibrary(text.str()).library;
    }();
    return library;
}

// The block's body with its placeholders bound, as an expansion will be.
std::string expand(const std::string& blockName, const std::map<std::string, std::string>& bound) {
    const blocks::BlockDefinition* block = basics().findBlock(blockName);
    EXPECT_NE(block, nullptr) << blockName;
    std::string text;
    for (const std::string& line : block->body)
        text +=
            blocks::substitute(line,
                               [&](const blocks::Placeholder& placeholder) {
                                   return bound.at(placeholder.isPrivate ? "#" + placeholder.name
                                                                         : placeholder.name);
                               })
                .text +
            "\n";
    return text;
}

sim::ScenarioReport runBasics(const std::string& code, const std::string& scenarioText) {
    const std::string text = "! id_pluto:00=000000000000\n! type_pluto:00=A20,is3\n"
                             "! pgm_pluto:00\nS0.0_0\n" +
                             code;
    const compiler::CompileResult compiled = compiler::compileText(text);
    EXPECT_EQ(compiled.errors(), 0) << text;
    const project::ProjectReadResult read = project::readProject(text);
    const sim::OperandNames names(read.project);
    sim::Simulation simulation(compiled.images);
    return sim::runScenario("t.scn", sim::parseScenario(scenarioText, names), simulation);
}

} // namespace

// The definitions docs/block-libraries.md gives, checked on the simulator.
TEST(StandardLibraryBehaviour, ResetLatchNeedsANewPressOfReset) {
    const std::string code = expand("ResetLatch", {{"Enable", "I0.0"},
                                                   {"Reset", "I0.1"},
                                                   {"Out", "Q0.0"},
                                                   {"ResetLamp", "Q0.1"},
                                                   {"#on", "M0.10"}});
    const sim::ScenarioReport report = runBasics(code, "set I0.1 1\nscans 3\nset I0.0 1\nscans 3\n"
                                                       "expect Q0.0 0\nexpect Q0.1 1\n"
                                                       "set I0.1 0\nscans 2\nset I0.1 1\nscans 1\n"
                                                       "expect Q0.0 1\nexpect Q0.1 0\n"
                                                       "set I0.1 0\nscans 5\nexpect Q0.0 1\n"
                                                       "set I0.0 0\nscans 1\nexpect Q0.0 0\n"
                                                       "expect Q0.1 0\n");
    EXPECT_EQ(report.failed, 0) << (report.failures.empty() ? "" : report.failures.front());
    EXPECT_EQ(report.passed, 7);
}

TEST(StandardLibraryBehaviour, EquivalentInputsLatchesADiscrepancyUntilBothAreOff) {
    const std::string code = expand("EquivalentInputs", {{"Channel1", "I0.2"},
                                                         {"Channel2", "I0.3"},
                                                         {"DiscrepancyTime", "0s50"},
                                                         {"Out", "Q0.2"},
                                                         {"Fault", "Q0.3"},
                                                         {"#fault", "M0.20"}});
    const sim::ScenarioReport report =
        runBasics(code, "set I0.2 1\nset I0.3 1\nscans 1\nexpect Q0.2 1\n"
                        // A difference shorter than the time is no fault.
                        "set I0.3 0\nscans 40\nexpect Q0.3 0\nexpect Q0.2 0\n"
                        "set I0.3 1\nscans 1\nexpect Q0.2 1\n"
                        // One of 0.5 s is, and it holds while a channel is on.
                        "set I0.3 0\nexpect Q0.3 1 within 600ms\n"
                        "set I0.3 1\nscans 2\nexpect Q0.2 0\nexpect Q0.3 1\n"
                        "set I0.2 0\nset I0.3 0\nscans 1\nexpect Q0.3 0\n"
                        "set I0.2 1\nset I0.3 1\nscans 1\nexpect Q0.2 1\n");
    EXPECT_EQ(report.failed, 0) << (report.failures.empty() ? "" : report.failures.front());
    EXPECT_EQ(report.passed, 9);
}

namespace {

// TwoSensorMuting with the sensors on I0.0/I0.1, the beam on I0.13, short
// times so that the limits are quick to reach.
std::string twoSensorMuting() {
    return expand("TwoSensorMuting", {{"Sensor1", "I0.0"},
                                      {"Sensor2", "I0.1"},
                                      {"Beam", "I0.13"},
                                      {"SyncTime", "0s50"},
                                      {"MaxTime", "2s00"},
                                      {"Muting", "Q0.2"},
                                      {"Fault", "Q0.3"},
                                      {"#armed", "M0.10"},
                                      {"#muting", "M0.11"},
                                      {"#fault", "M0.12"}});
}

// MonitoredReset with Enable on I0.12, Reset on I0.14 and Feedback on I0.2.
std::string monitoredReset() {
    return expand("MonitoredReset", {{"Enable", "I0.12"},
                                     {"Reset", "I0.14"},
                                     {"Feedback", "I0.2"},
                                     {"Out", "Q0.2"},
                                     {"ResetLamp", "Q0.14"},
                                     {"#on", "M0.20"}});
}

void expectAllPass(const sim::ScenarioReport& report, int expectations) {
    EXPECT_EQ(report.failed, 0) << (report.failures.empty() ? "" : report.failures.front());
    EXPECT_EQ(report.passed, expectations);
}

} // namespace

TEST(StandardLibraryBehaviour, TwoSensorMutingMutesWhileBothSensorsAreOnAndEndsWithEither) {
    expectAllPass(runBasics(twoSensorMuting(),
                            "set I0.13 1\nscans 2\nexpect Q0.2 0\n"
                            // Armed: both sensors on with the beam unbroken mute it.
                            "set I0.0 1\nset I0.1 1\nscans 1\nexpect Q0.2 1\nexpect Q0.3 0\n"
                            // Breaking the beam while muted keeps muting.
                            "set I0.13 0\nscans 20\nexpect Q0.2 1\n"
                            // Sensor 1 off ends it, and sensor 1 back on does not restart it.
                            "set I0.0 0\nscans 1\nexpect Q0.2 0\n"
                            "set I0.13 1\nset I0.0 1\nscans 2\nexpect Q0.2 0\n"
                            // Both off arm it again; sensor 2 off ends muting as well.
                            "set I0.0 0\nset I0.1 0\nscans 1\nset I0.0 1\nset I0.1 1\nscans 1\n"
                            "expect Q0.2 1\nset I0.1 0\nscans 1\nexpect Q0.2 0\nexpect Q0.3 0\n"),
                  9);
}

TEST(StandardLibraryBehaviour, TwoSensorMutingIsArmedOnlyBySeeingBothSensorsOff) {
    // Sensors on from the start are not a muting sequence.
    expectAllPass(runBasics(twoSensorMuting(), "set I0.13 1\nset I0.0 1\nset I0.1 1\nscans 5\n"
                                               "expect Q0.2 0\nexpect Q0.3 0\n"
                                               "set I0.1 0\nscans 5\nset I0.1 1\nscans 1\n"
                                               "expect Q0.2 0\n"
                                               "set I0.0 0\nset I0.1 0\nscans 1\n"
                                               "set I0.0 1\nset I0.1 1\nscans 1\nexpect Q0.2 1\n"),
                  4);
}

TEST(StandardLibraryBehaviour, TwoSensorMutingRefusesSensorsReachedWithTheBeamBroken) {
    expectAllPass(runBasics(twoSensorMuting(),
                            "set I0.13 1\nscans 2\n"
                            // The beam is broken before the sensors: wrong order, no muting,
                            // and none when the beam clears while the sensors are still on.
                            "set I0.13 0\nscans 1\nset I0.0 1\nset I0.1 1\nscans 3\n"
                            "expect Q0.2 0\nset I0.13 1\nscans 3\nexpect Q0.2 0\nexpect Q0.3 0\n"
                            // The beam broken between the first and the second sensor is the same.
                            "set I0.0 0\nset I0.1 0\nscans 1\nset I0.0 1\nscans 2\nset I0.13 0\n"
                            "scans 1\nset I0.1 1\nscans 2\nset I0.13 1\nscans 2\nexpect Q0.2 0\n"
                            // Both off again, and the right order mutes.
                            "set I0.0 0\nset I0.1 0\nscans 1\nset I0.0 1\nset I0.1 1\nscans 1\n"
                            "expect Q0.2 1\n"),
                  5);
}

TEST(StandardLibraryBehaviour, TwoSensorMutingLatchesAFaultWhenTheSensorsDifferTooLong) {
    expectAllPass(runBasics(twoSensorMuting(),
                            "set I0.13 1\nscans 2\n"
                            // Sensor 2 following within SyncTime (0.5 s) mutes.
                            "set I0.0 1\nscans 40\nexpect Q0.3 0\nset I0.1 1\nscans 1\n"
                            "expect Q0.2 1\n"
                            // Leaving the sensors one after the other is no fault.
                            "set I0.0 0\nscans 80\nexpect Q0.3 0\nset I0.1 0\nscans 1\n"
                            // Sensor 2 following later is a fault, and refuses muting.
                            "set I0.1 1\nexpect Q0.3 1 within 600ms\nset I0.0 1\nscans 2\n"
                            "expect Q0.2 0\nexpect Q0.3 1\n"
                            // One sensor off releases nothing; both off release it and arm again.
                            "set I0.0 0\nscans 2\nexpect Q0.3 1\nset I0.1 0\nscans 1\n"
                            "expect Q0.3 0\nset I0.0 1\nset I0.1 1\nscans 1\nexpect Q0.2 1\n"),
                  9);
}

TEST(StandardLibraryBehaviour, TwoSensorMutingEndsMutingThatLastsLongerThanMaxTime) {
    expectAllPass(runBasics(twoSensorMuting(),
                            "set I0.13 1\nscans 2\nset I0.0 1\nset I0.1 1\nscans 1\n"
                            "set I0.13 0\nrun 1.9s\nexpect Q0.2 1\nexpect Q0.3 0\n"
                            // At 2 s of muting it ends with a fault held while the sensors stay on.
                            "expect Q0.2 0 within 200ms\nexpect Q0.3 1\nset I0.13 1\nscans 20\n"
                            "expect Q0.2 0\nexpect Q0.3 1\n"
                            "set I0.0 0\nset I0.1 0\nscans 1\nexpect Q0.3 0\n"
                            "set I0.0 1\nset I0.1 1\nscans 1\nexpect Q0.2 1\n"),
                  8);
}

TEST(StandardLibraryBehaviour, MonitoredResetStartsOnAPressWithTheContactorsSeenOff) {
    expectAllPass(runBasics(monitoredReset(),
                            "set I0.12 1\nscans 2\nexpect Q0.2 0\nexpect Q0.14 1\n"
                            // A press while the feedback says the contactors are on does nothing.
                            "set I0.14 1\nscans 1\nset I0.14 0\nscans 1\nexpect Q0.2 0\n"
                            // With the feedback on it starts, and the lamp goes out.
                            "set I0.2 1\nscans 1\nset I0.14 1\nscans 1\nexpect Q0.2 1\n"
                            "expect Q0.14 0\nset I0.14 0\n"
                            // The feedback going off afterwards (the contactors pulled in) is fine.
                            "set I0.2 0\nscans 10\nexpect Q0.2 1\n"
                            // Enable off drops it for good, and the lamp comes on.
                            "set I0.12 0\nscans 1\nexpect Q0.2 0\nexpect Q0.14 1\n"
                            "set I0.12 1\nscans 5\nexpect Q0.2 0\n"),
                  9);
}

TEST(StandardLibraryBehaviour, MonitoredResetNeedsANewPressOfReset) {
    expectAllPass(runBasics(monitoredReset(),
                            "set I0.2 1\nset I0.14 1\nscans 3\nset I0.12 1\nscans 3\n"
                            "expect Q0.2 0\nexpect Q0.14 1\n"
                            "set I0.14 0\nscans 2\nset I0.14 1\nscans 1\n"
                            "expect Q0.2 1\n"
                            // A press while Enable is off is no press for later.
                            "set I0.14 0\nset I0.12 0\nscans 1\nset I0.14 1\n"
                            "scans 1\nset I0.12 1\nscans 3\nexpect Q0.2 0\n"),
                  4);
}
