// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProjectGenerator.h"

#include "compiler/Compiler.h"
#include "compiler/ImageCodec.h"
#include "compiler/ProgramCheck.h"
#include "project/ProjectFile.h"

#include <benchmark/benchmark.h>

#include <cstdint>
#include <string>

namespace {

// The default generated project (32 units x 2,000 statements), read once.
const std::string& projectText() {
    static const std::string text = rs::bench::generateProject({});
    return text;
}

const rs::project::Project& project() {
    static const rs::project::Project parsed = rs::project::readProject(projectText()).project;
    return parsed;
}

void setBytes(benchmark::State& state) {
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(projectText().size()));
}

// The semantic checks alone, on a project already read.
void BM_Check(benchmark::State& state) {
    for (auto _ : state) {
        rs::lang::Diagnostics diagnostics;
        auto units = rs::compiler::collectUnits(project().program, diagnostics);
        benchmark::DoNotOptimize(rs::compiler::checkProgram(project().program, units, {}));
    }
    setBytes(state);
}
BENCHMARK(BM_Check)->Unit(benchmark::kMillisecond);

// Checks and code generation, on a project already read.
void BM_CheckAndGenerate(benchmark::State& state) {
    for (auto _ : state) {
        auto result = rs::compiler::compile(project());
        if (result.errors())
            state.SkipWithError("the generated project does not compile");
        benchmark::DoNotOptimize(result);
    }
    setBytes(state);
}
BENCHMARK(BM_CheckAndGenerate)->Unit(benchmark::kMillisecond);

// What `rungsmith-cli compile` does between reading and writing files:
// read the text, check, generate, encode as Intel HEX.
void BM_CompileTextToHps(benchmark::State& state) {
    for (auto _ : state) {
        auto result = rs::compiler::compileText(projectText());
        benchmark::DoNotOptimize(rs::compiler::writeHps(result.images));
    }
    setBytes(state);
}
BENCHMARK(BM_CompileTextToHps)->Unit(benchmark::kMillisecond);

// Encoding a compiled project's images as Intel HEX, piece by piece, as
// `rungsmith-cli compile` writes them (the file itself left out).
void BM_EncodeHps(benchmark::State& state) {
    static const rs::compiler::CompileResult compiled = rs::compiler::compile(project());
    std::size_t bytes = 0;
    for (auto _ : state) {
        bytes = 0;
        rs::compiler::writeHps(compiled.images, [&bytes](std::string_view piece) {
            bytes += piece.size();
            benchmark::DoNotOptimize(piece.data());
        });
    }
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(bytes));
}
BENCHMARK(BM_EncodeHps)->Unit(benchmark::kMillisecond);

} // namespace
