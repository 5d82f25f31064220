// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProjectGenerator.h"
#include "compiler/Compiler.h"
#include "project/ProjectFile.h"
#include "prove/Prover.h"
#include "sim/Scenario.h"

#include <benchmark/benchmark.h>

#include <QFile>

#include <stdexcept>

// How long `prove` takes (docs/performance.md, "Prover"): the examples'
// property files, and ten invariants of a generated 32-unit plant of 500
// statements per unit. Each run reports the properties proved, the deepest
// induction, the longest counterexample or witness and the most clauses a
// property's solvers held.

namespace {

using rs::prove::Verdict;

struct Case {
    rs::compiler::CompileResult compiled;
    rs::prove::PropertyFile file;
};

std::string readFile(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        throw std::runtime_error("cannot read " + path.toStdString());
    return file.readAll().toStdString();
}

Case load(const std::string& project, const std::string& properties) {
    Case loaded{rs::compiler::compileText(project), {}};
    if (loaded.compiled.errors())
        throw std::runtime_error("the project does not compile");
    const rs::sim::OperandNames names(rs::project::readProject(project).project);
    loaded.file = rs::prove::parseProperties(properties, names);
    if (rs::lang::errorCount(loaded.file.diagnostics))
        throw std::runtime_error("the properties do not read");
    return loaded;
}

void report(benchmark::State& state, const std::vector<Verdict>& verdicts) {
    int proved = 0;
    int deepestProof = 0;
    int longestTrace = 0;
    std::int64_t clauses = 0;
    for (const Verdict& verdict : verdicts) {
        if (verdict.status == Verdict::Status::Proved) {
            ++proved;
            deepestProof = std::max(deepestProof, verdict.depth);
        } else {
            longestTrace = std::max(longestTrace, verdict.depth);
        }
        clauses = std::max(clauses, verdict.clauses);
    }
    state.counters["properties"] = static_cast<double>(verdicts.size());
    state.counters["proved"] = proved;
    state.counters["k"] = deepestProof;           // the deepest induction of a proof
    state.counters["trace_scans"] = longestTrace; // the longest counterexample or witness
    state.counters["clauses"] = static_cast<double>(clauses);
}

void BM_ProveExample(benchmark::State& state, const char* name) {
    const QString base = QStringLiteral(RUNGSMITH_EXAMPLES "/") + QString::fromUtf8(name);
    const Case example = load(readFile(base + ".sps"), readFile(base + ".prop"));
    std::vector<Verdict> verdicts;
    for (auto _ : state)
        verdicts = rs::prove::proveProperties(example.compiled.images, example.file);
    report(state, verdicts);
}
BENCHMARK_CAPTURE(BM_ProveExample, estop, "estop")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ProveExample, two_hand, "two-hand")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ProveExample, muting_wrong, "muting-wrong")->Unit(benchmark::kMillisecond);

// Ten invariants of the plant, each `always X -> C` for a coil X = C * ...
// of a unit's main code that the prover proves; chosen once, from the first
// units on, the way an engineer writes down what a network promises.
std::string plantInvariants(const std::string& plant) {
    const auto read = rs::project::readProject(plant);
    const auto compiled = rs::compiler::compileText(plant);
    const rs::sim::OperandNames names(read.project);
    std::string chosen;
    int count = 0;
    for (const auto& unit : read.project.program.units) {
        if (count == 10 || unit.steps.empty())
            break;
        for (const auto& line : unit.steps.front().lines) {
            const auto* statement = std::get_if<rs::lang::Statement>(&line.body);
            if (!statement || statement->kind != rs::lang::StatementKind::Coil ||
                !statement->condition)
                continue;
            const rs::lang::Expr& condition = *statement->condition;
            const rs::lang::Expr* first = condition.kind == rs::lang::ExprKind::And
                                              ? &condition.children.front()
                                              : &condition;
            if (first->kind != rs::lang::ExprKind::Contact || first->negated)
                continue;
            const std::string property = "always " + rs::lang::toString(statement->target.address) +
                                         " -> " + rs::lang::toString(first->operand.address) + "\n";
            const auto file = rs::prove::parseProperties(property, names);
            rs::prove::ProofOptions options;
            options.maxDepth = 5;
            const auto verdict = rs::prove::proveProperties(compiled.images, file, options);
            if (verdict.size() == 1 && verdict.front().status == Verdict::Status::Proved) {
                chosen += property;
                ++count;
                break;
            }
        }
    }
    if (count < 10)
        throw std::runtime_error("fewer than ten invariants found");
    return chosen;
}

void BM_ProvePlantInvariants(benchmark::State& state) {
    rs::bench::GeneratorOptions options;
    options.units = 32;
    options.statementsPerUnit = 500;
    const std::string plant = rs::bench::generateProject(options);
    const Case loaded = load(plant, plantInvariants(plant));
    std::vector<Verdict> verdicts;
    for (auto _ : state)
        verdicts = rs::prove::proveProperties(loaded.compiled.images, loaded.file);
    report(state, verdicts);
}
BENCHMARK(BM_ProvePlantInvariants)->Unit(benchmark::kMillisecond)->Iterations(3);

} // namespace
