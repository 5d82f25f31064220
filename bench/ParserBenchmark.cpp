// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProjectGenerator.h"

#include "lang/Lexer.h"
#include "lang/Parser.h"
#include "project/ProjectFile.h"

#include <benchmark/benchmark.h>

#include <cstdint>
#include <string>

namespace {

using rs::lang::TokenKind;

// The default generated project (32 units x 2,000 statements, about 2 MB),
// made once and shared by all benchmarks.
const std::string& projectText() {
    static const std::string text = rs::bench::generateProject({});
    return text;
}

std::int64_t bytes(const std::string& text) {
    return static_cast<std::int64_t>(text.size());
}

void BM_Lex(benchmark::State& state) {
    const std::string& text = projectText();
    for (auto _ : state) {
        rs::lang::Lexer lexer(text);
        for (auto token = lexer.next(); token.kind != TokenKind::EndOfFile; token = lexer.next())
            benchmark::DoNotOptimize(token);
    }
    state.SetBytesProcessed(state.iterations() * bytes(text));
}
BENCHMARK(BM_Lex)->Unit(benchmark::kMillisecond);

// The syntax tree is destroyed inside the loop: every reader of a file pays for that too.
void BM_Parse(benchmark::State& state) {
    const std::string& text = projectText();
    for (auto _ : state) {
        rs::lang::ParseResult result = rs::lang::parse(text);
        benchmark::DoNotOptimize(result);
    }
    state.SetBytesProcessed(state.iterations() * bytes(text));
}
BENCHMARK(BM_Parse)->Unit(benchmark::kMillisecond);

// What opening a project costs: parse, project records, name resolution.
void BM_ReadProject(benchmark::State& state) {
    const std::string& text = projectText();
    if (!rs::project::readProject(text).ok()) {
        state.SkipWithError("the generated project has errors");
        return;
    }
    for (auto _ : state) {
        rs::project::ProjectReadResult result = rs::project::readProject(text);
        benchmark::DoNotOptimize(result);
    }
    state.SetBytesProcessed(state.iterations() * bytes(text));
}
BENCHMARK(BM_ReadProject)->Unit(benchmark::kMillisecond);

// Counted in bytes written, which equal the bytes read: the generator writes canonical text.
void BM_WriteProject(benchmark::State& state) {
    const rs::project::Project project = rs::project::readProject(projectText()).project;
    std::int64_t written = 0;
    for (auto _ : state) {
        std::string text = rs::project::writeProject(project);
        written = bytes(text);
        benchmark::DoNotOptimize(text);
    }
    state.SetBytesProcessed(state.iterations() * written);
}
BENCHMARK(BM_WriteProject)->Unit(benchmark::kMillisecond);

} // namespace
