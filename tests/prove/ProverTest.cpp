// SPDX-License-Identifier: GPL-3.0-or-later
#include "prove/Prover.h"
#include "compiler/Compiler.h"
#include "project/ProjectFile.h"
#include "prove/Counterexample.h"
#include "sim/ScenarioRunner.h"
#include "sim/Simulation.h"

#include <gtest/gtest.h>

#include <memory>

namespace {

using rs::prove::Verdict;
using Status = rs::prove::Verdict::Status;

std::string unitZero(const std::string& code, const std::string& sequences = "") {
    return "! id_pluto:00=000000000000\n! type_pluto:00=A20,is3\n! pgm_pluto:00\nS0.0_0\n" + code +
           sequences;
}

// A project and a property file, proved.
struct Proof {
    Proof(const std::string& project, const std::string& properties, int depth = 40) {
        compiled = rs::compiler::compileText(project);
        EXPECT_EQ(compiled.errors(), 0) << compiled.diagnostics.front().message;
        read = rs::project::readProject(project).project;
        names = std::make_unique<rs::sim::OperandNames>(read);
        file = rs::prove::parseProperties(properties, *names);
        EXPECT_EQ(rs::lang::errorCount(file.diagnostics), 0) << file.diagnostics.front().message;
        rs::prove::ProofOptions options;
        options.maxDepth = depth;
        verdicts = rs::prove::proveProperties(compiled.images, file, options);
    }

    // The counterexample as `rungsmith-cli test` runs it.
    rs::sim::ScenarioReport replay(std::size_t index, std::string* text = nullptr) const {
        const auto scenario = rs::prove::writeCounterexample(compiled.images, file, verdicts[index],
                                                             *names, "t.prop");
        EXPECT_TRUE(scenario.reproduced) << scenario.problem;
        if (text)
            *text = scenario.text;
        rs::sim::Simulation simulation(compiled.images);
        return rs::sim::runScenario("cex.scn", rs::sim::parseScenario(scenario.text, *names),
                                    simulation);
    }

    rs::compiler::CompileResult compiled;
    rs::project::Project read;
    std::unique_ptr<rs::sim::OperandNames> names;
    rs::prove::PropertyFile file;
    std::vector<Verdict> verdicts;
};

TEST(ProverTest, ProvesWhatHoldsInEveryScan) {
    const Proof proof(unitZero("Q0.2 = I0.12 * I0.0\nQ0.3 = Q0.2\n"),
                      "always Q0.2 -> I0.12\nnever Q0.2 * /Q0.3\nalways Q0.3 -> Q0.2 * I0.0\n");
    ASSERT_EQ(proof.verdicts.size(), 3u);
    for (const Verdict& verdict : proof.verdicts)
        EXPECT_EQ(verdict.status, Status::Proved) << verdict.property->text << verdict.reason;
}

TEST(ProverTest, FindsTheShortestCounterexampleAndItReplays) {
    const Proof proof(unitZero("M0.1 = I0.1 * P(I0.2)\nS(Q0.1) = M0.1\n"), "never Q0.1\n");
    ASSERT_EQ(proof.verdicts[0].status, Status::Failed);
    // An edge is never seen in the first scan: the set needs I0.2 low, then high.
    EXPECT_EQ(proof.verdicts[0].depth, 2);
    std::string text;
    const auto report = proof.replay(0, &text);
    EXPECT_EQ(report.failed, 1) << text;
    EXPECT_NE(text.find("expect Q0.1 0\n"), std::string::npos) << text;
}

TEST(ProverTest, ALatchDropsWithinTheWindow) {
    const Proof proof(unitZero("Q0.2 = I0.12 * (I0.1 + Q0.2)\n"),
                      "always /I0.12 -> within 20ms /Q0.2\nalways /I0.12 -> /Q0.2\n");
    EXPECT_EQ(proof.verdicts[0].status, Status::Proved);
    EXPECT_EQ(proof.verdicts[1].status, Status::Proved);
}

// A pulse ends within its preset: the proof needs the relation between the
// monitor's age and the timer's count, and comes at a depth far below the
// preset's 50 scans.
TEST(ProverTest, TimerProofsConvergeWithInvariants) {
    const Proof proof(unitZero("Q0.1 = I0.5 * TPS(0s50)\n"), "always Q0.1 -> within 500ms /Q0.1\n",
                      12);
    ASSERT_EQ(proof.verdicts[0].status, Status::Proved) << proof.verdicts[0].reason;
    EXPECT_LE(proof.verdicts[0].depth, 12);
    // One scan less and the pulse is still on at the end of the window.
    const Proof tooShort(unitZero("Q0.1 = I0.5 * TPS(0s50)\n"),
                         "always Q0.1 -> within 490ms /Q0.1\n", 60);
    ASSERT_EQ(tooShort.verdicts[0].status, Status::Failed);
    EXPECT_EQ(tooShort.verdicts[0].depth, 50);
    EXPECT_EQ(tooShort.replay(0).failed, 1);
}

TEST(ProverTest, NextSeesTheFollowingScan) {
    const Proof proof(unitZero("Q0.0 = I0.3 * TON(0s05)\n"),
                      "always /I0.3 -> next /Q0.0\nalways I0.3 -> next Q0.0\n");
    EXPECT_EQ(proof.verdicts[0].status, Status::Proved) << proof.verdicts[0].reason;
    ASSERT_EQ(proof.verdicts[1].status, Status::Failed);
    EXPECT_EQ(proof.replay(1).failed, 1);
}

TEST(ProverTest, AssumptionsNarrowTheInputs) {
    const std::string project = unitZero("Q0.2 = I0.0 * I0.1\n");
    const Proof without(project, "never Q0.2\n");
    EXPECT_EQ(without.verdicts[0].status, Status::Failed);
    const Proof with(project, "assume /(I0.0 * I0.1)\nnever Q0.2\n");
    EXPECT_EQ(with.verdicts[0].status, Status::Proved);
}

TEST(ProverTest, CoversAReachableStepAndRefusesAnUnreachableOne) {
    const std::string sequences = "S0.1_0\nJ(1) = I0.0\nS0.1_1\nJ(2) = P(I0.1)\nS0.1_2\nQ0.1\n"
                                  "J(0) = I0.2\n";
    const Proof proof(unitZero("Q0.0 = I0.0\n", sequences),
                      "cover S0.1 = 2\ncover S0.1 = 3\ncover Q0.1 * /I0.0\n");
    ASSERT_EQ(proof.verdicts[0].status, Status::Covered);
    EXPECT_EQ(proof.verdicts[0].depth, 3);
    EXPECT_EQ(proof.replay(0).failed, 0); // a witness's last line holds
    EXPECT_EQ(proof.verdicts[1].status, Status::Unreachable);
    EXPECT_EQ(proof.verdicts[2].status, Status::Covered);
}

TEST(ProverTest, SaysUnknownWhenNeitherComesWithinTheDepth) {
    const Proof proof(unitZero("(R0.1++) = P(I0.0)\n"), "never (R0.1 >= 30)\n", 20);
    ASSERT_EQ(proof.verdicts[0].status, Status::Unknown);
    EXPECT_NE(proof.verdicts[0].reason.find("within 20 scans"), std::string::npos);
}

TEST(ProverTest, SaturatingArithmeticIsExact) {
    const Proof proof(unitZero("(R0.1 += 1000)\nQ0.0 = (R0.1 = 32767)\n"),
                      "always (R0.1 >= 0)\ncover Q0.0\nnever SM0.11\n", 60);
    EXPECT_EQ(proof.verdicts[0].status, Status::Proved) << proof.verdicts[0].reason;
    ASSERT_EQ(proof.verdicts[1].status, Status::Covered);
    EXPECT_EQ(proof.verdicts[1].depth, 33); // 33 * 1000 passes 32767
    ASSERT_EQ(proof.verdicts[2].status, Status::Failed);
    EXPECT_EQ(proof.verdicts[2].depth, 33);
}

TEST(ProverTest, UnitsSeeEachOtherOverTheBusOneScanLate) {
    const std::string project = "! id_pluto:00=000000000000\n! type_pluto:00=A20,is3\n"
                                "! id_pluto:01=000000000001\n! type_pluto:01=A20,is3\n"
                                "! pgm_pluto:00\nS0.0_0\nQ0.2 = I0.0\n"
                                "! pgm_pluto:01\nS1.0_0\nQ1.0 = Q0.2\n";
    const Proof proof(project, "always Q0.2 -> next Q1.0\nalways Q0.2 -> Q1.0\n");
    EXPECT_EQ(proof.verdicts[0].status, Status::Proved) << proof.verdicts[0].reason;
    ASSERT_EQ(proof.verdicts[1].status, Status::Failed);
    EXPECT_EQ(proof.verdicts[1].depth, 1);
    EXPECT_EQ(proof.replay(1).failed, 1);
}

} // namespace
