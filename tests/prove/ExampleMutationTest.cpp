// SPDX-License-Identifier: GPL-3.0-or-later
#include "compiler/Compiler.h"
#include "project/ProjectFile.h"
#include "prove/Prover.h"
#include "sim/Scenario.h"

#include <QFile>

#include <gtest/gtest.h>

#include <regex>

// A proof that a broken program also passes proves nothing: for every
// property an example proves, some copy of the program with one contact
// inverted must not be proved.

namespace {

std::string readExample(const std::string& name) {
    QFile file(QStringLiteral(RUNGSMITH_EXAMPLES "/") + QString::fromStdString(name));
    EXPECT_TRUE(file.open(QIODevice::ReadOnly)) << name;
    return file.readAll().toStdString();
}

// Each copy of the code with one operand on the right of an `=` negated,
// or its negation taken away.
std::vector<std::string> oneContactInverted(const std::string& text) {
    std::vector<std::string> mutants;
    const std::regex operand(R"((/?)([A-Za-z_][A-Za-z0-9_.]*)(\s*\()?)");
    std::size_t lineStart = 0;
    bool inCode = false;
    while (lineStart < text.size()) {
        std::size_t lineEnd = text.find('\n', lineStart);
        if (lineEnd == std::string::npos)
            lineEnd = text.size();
        const std::string line = text.substr(lineStart, lineEnd - lineStart);
        if (line.rfind("S0.0_0", 0) == 0)
            inCode = true;
        const std::size_t equals = line.find(" = ");
        const std::size_t comment = line.find(';');
        if (inCode && equals != std::string::npos && equals < comment) {
            const std::size_t from = equals + 3;
            const std::string right = line.substr(
                from, comment == std::string::npos ? std::string::npos : comment - from);
            for (auto it = std::sregex_iterator(right.begin(), right.end(), operand);
                 it != std::sregex_iterator(); ++it) {
                const std::smatch& match = *it;
                if (match[3].matched) // a function: P(...), TON(...)
                    continue;
                const std::size_t at =
                    lineStart + from + static_cast<std::size_t>(match.position());
                std::string mutant = text;
                if (match[1].length() == 1)
                    mutant.erase(at, 1);
                else
                    mutant.insert(at, "/");
                mutants.push_back(std::move(mutant));
            }
        }
        lineStart = lineEnd + 1;
    }
    return mutants;
}

std::vector<rs::prove::Verdict> prove(const std::string& project,
                                      const rs::prove::PropertyFile& file) {
    const auto compiled = rs::compiler::compileText(project);
    if (compiled.errors())
        return {};
    rs::prove::ProofOptions options;
    options.maxDepth = 40;
    return rs::prove::proveProperties(compiled.images, file, options);
}

TEST(ExampleMutationTest, AnInvertedContactBreaksEveryProof) {
    for (const std::string example : {"estop", "two-hand", "muting-wrong"}) {
        const std::string project = readExample(example + ".sps");
        const auto read = rs::project::readProject(project);
        const rs::sim::OperandNames names(read.project);
        const rs::prove::PropertyFile file =
            rs::prove::parseProperties(readExample(example + ".prop"), names);
        ASSERT_EQ(rs::lang::errorCount(file.diagnostics), 0);
        const auto verdicts = prove(project, file);
        const auto mutants = oneContactInverted(project);
        ASSERT_GE(mutants.size(), 3u) << example;
        std::vector<std::vector<rs::prove::Verdict>> mutantVerdicts;
        for (const std::string& mutant : mutants)
            mutantVerdicts.push_back(prove(mutant, file));
        for (std::size_t p = 0; p < verdicts.size(); ++p) {
            if (verdicts[p].status != rs::prove::Verdict::Status::Proved)
                continue;
            bool broken = false;
            for (const auto& mutant : mutantVerdicts)
                broken = broken || (!mutant.empty() &&
                                    mutant[p].status != rs::prove::Verdict::Status::Proved);
            EXPECT_TRUE(broken) << example << ": " << verdicts[p].property->text;
        }
    }
}

} // namespace
