// SPDX-License-Identifier: GPL-3.0-or-later
// What a user waits for on a large project, as whole processes (issue 23):
// `rungsmith-cli check` and `compile` of the generated plant, each against
// `wc -w` of the same file in the same iteration, with the peak memory of
// the process and its page faults as the kernel counts them.
#include "ProjectGenerator.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace {

struct Run {
    double ms = 0;
    double peakMb = 0;
    double pageFaults = 0;
};

// Runs the command with its output thrown away; its wall time and peak memory.
Run run(const std::vector<std::string>& command) {
    std::vector<char*> argv;
    for (const auto& word : command)
        argv.push_back(const_cast<char*>(word.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    const auto start = std::chrono::steady_clock::now();
    pid_t pid = 0;
    const int spawned = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0)
        throw std::runtime_error("cannot start " + command.front());
    int status = 0;
    rusage usage{};
    wait4(pid, &status, 0, &usage);
    Run result;
    result.ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    result.peakMb = static_cast<double>(usage.ru_maxrss) / 1024.0;
    result.pageFaults = static_cast<double>(usage.ru_minflt);
    if (!WIFEXITED(status) || WEXITSTATUS(status) > 1) // 1: the project has errors
        throw std::runtime_error(command.front() + " failed");
    return result;
}

// The plant of the other benchmarks (32 units x 2,000 statements), written once.
const std::string& plantFile() {
    static const std::string path = [] {
        const std::string file = "/tmp/rungsmith-bench-plant-" + std::to_string(getpid()) + ".sps";
        std::ofstream(file, std::ios::binary) << rs::bench::generateProject({});
        return file;
    }();
    return path;
}

void measure(benchmark::State& state, const std::vector<std::string>& command) {
    double total = 0;
    double words = 0;
    double peak = 0;
    double faults = 0;
    for (auto _ : state) {
        const Run counted = run({"wc", "-w", plantFile()});
        const Run measured = run(command);
        state.SetIterationTime(measured.ms / 1000.0);
        total += measured.ms;
        words += counted.ms;
        peak = std::max(peak, measured.peakMb);
        faults += measured.pageFaults;
    }
    const auto n = static_cast<double>(state.iterations());
    state.counters["ms"] = total / n;
    state.counters["wc_ms"] = words / n;
    state.counters["ratio_to_wc"] = words > 0 ? total / words : 0;
    state.counters["peak_MB"] = peak;
    state.counters["page_faults"] = faults / n;
}

void BM_CheckPlant(benchmark::State& state) {
    measure(state, {RUNGSMITH_CLI, "check", plantFile()});
}
BENCHMARK(BM_CheckPlant)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(5);

void BM_CompilePlant(benchmark::State& state) {
    measure(state, {RUNGSMITH_CLI, "compile", plantFile(), "-o", plantFile() + ".hps"});
}
BENCHMARK(BM_CompilePlant)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(5);

} // namespace

int main(int argc, char* argv[]) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    std::remove(plantFile().c_str());
    std::remove((plantFile() + ".hps").c_str());
    return 0;
}
