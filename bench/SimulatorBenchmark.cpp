// SPDX-License-Identifier: GPL-3.0-or-later
#include "NativeRuntime.h"

#include "compiler/Compiler.h"
#include "project/ProjectFile.h"
#include "sim/Simulation.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <string>

namespace rs::native {
void scanPlant(Plant& plant, std::int64_t timeMs, int cycleMs);
}

namespace {

constexpr int kCycleMs = 10;

const std::vector<rs::compiler::UnitImage>& images() {
    static const std::vector<rs::compiler::UnitImage> compiled = [] {
        auto file = rs::project::readTextFile(QStringLiteral(RUNGSMITH_BENCH_PLANT));
        auto result = rs::compiler::compileText(file.text);
        if (!file.error.isEmpty() || result.errors()) {
            std::fprintf(stderr, "cannot compile %s\n", RUNGSMITH_BENCH_PLANT);
            std::exit(2);
        }
        return result.images;
    }();
    return compiled;
}

// The same changing inputs on both sides, so that timers, edges and jumps work.
void driveInputs(rs::sim::UnitMemory& memory, std::uint64_t scan) {
    const auto terminal = static_cast<std::size_t>((scan * 7) % 18);
    memory.inputs[terminal] = !memory.inputs[terminal];
}

void BM_SimulatorScan(benchmark::State& state) {
    rs::sim::Simulation simulation(images(), kCycleMs);
    std::uint64_t scan = 0;
    for (auto _ : state) {
        for (int station : simulation.stations())
            driveInputs(simulation.unit(station)->memory(), scan);
        simulation.scan();
        ++scan;
    }
    // Virtual time simulated per second of real time.
    state.counters["real_time_factor"] = benchmark::Counter(
        static_cast<double>(state.iterations()) * kCycleMs / 1000.0, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SimulatorScan)->Unit(benchmark::kMicrosecond);

void BM_NativeScan(benchmark::State& state) {
    auto plant = std::make_unique<rs::native::Plant>();
    std::uint64_t scan = 0;
    for (auto _ : state) {
        for (const auto& image : images())
            driveInputs(plant->memory[image.station], scan);
        rs::native::scanPlant(*plant, static_cast<std::int64_t>(scan) * kCycleMs, kCycleMs);
        ++scan;
    }
    state.counters["real_time_factor"] = benchmark::Counter(
        static_cast<double>(state.iterations()) * kCycleMs / 1000.0, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_NativeScan)->Unit(benchmark::kMicrosecond);

// Beginning a simulation of the project: every unit's code decoded, translated
// and, where the machine allows, compiled to machine code (with
// RUNGSMITH_NO_JIT=1 without, so the difference is what compiling costs).
void BM_SimulationStart(benchmark::State& state) {
    images(); // the project is compiled once, before measuring
    for (auto _ : state) {
        rs::sim::Simulation simulation(images(), kCycleMs);
        benchmark::DoNotOptimize(simulation);
    }
}
BENCHMARK(BM_SimulationStart)->Unit(benchmark::kMillisecond);

// Both sides must compute the same thing, or the ratio means nothing. A third
// simulation marks conduction while scanning: the measured one replays its
// scans for conduction(), which must give the same marks.
bool sameResults(int scans) {
    rs::sim::Simulation simulation(images(), kCycleMs);
    rs::sim::Simulation marking(images(), kCycleMs);
    for (int station : marking.stations())
        marking.unit(station)->setEagerConduction(true);
    auto plant = std::make_unique<rs::native::Plant>();
    for (const auto& image : images())
        plant->memory[image.station].systemRegisters[40] = 240;
    for (int scan = 0; scan < scans; ++scan) {
        for (int station : simulation.stations()) {
            driveInputs(simulation.unit(station)->memory(), static_cast<std::uint64_t>(scan));
            driveInputs(marking.unit(station)->memory(), static_cast<std::uint64_t>(scan));
            driveInputs(plant->memory[station], static_cast<std::uint64_t>(scan));
        }
        simulation.scan();
        marking.scan();
        rs::native::scanPlant(*plant, static_cast<std::int64_t>(scan) * kCycleMs, kCycleMs);
        for (int station : simulation.stations()) {
            const auto& vm = simulation.unit(station)->memory();
            const auto& native = plant->memory[station];
            if (std::memcmp(vm.outputs.data(), native.outputs.data(), sizeof vm.outputs) ||
                std::memcmp(vm.memories.data(), native.memories.data(), sizeof vm.memories) ||
                std::memcmp(vm.globalMemories.data(), native.globalMemories.data(),
                            sizeof vm.globalMemories) ||
                std::memcmp(vm.registers.data(), native.registers.data(), sizeof vm.registers)) {
                std::fprintf(stderr, "simulator and native code differ: unit %d after scan %d\n",
                             station, scan);
                return false;
            }
            const auto* marked = marking.unit(station);
            if (std::memcmp(&vm, &marked->memory(), sizeof vm) ||
                simulation.unit(station)->conduction() != marked->conduction()) {
                std::fprintf(stderr,
                             "conduction on demand differs from marking while scanning: unit %d "
                             "after scan %d\n",
                             station, scan);
                return false;
            }
        }
    }
    return true;
}

// Prints the comparison the issue asks for after the usual table.
class RatioReporter : public benchmark::ConsoleReporter {
public:
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const auto& run : runs)
            if (run.run_type == Run::RT_Iteration || run.aggregate_name == "mean")
                m_times[run.run_name.function_name] = run.GetAdjustedRealTime();
        ConsoleReporter::ReportRuns(runs);
    }
    void Finalize() override {
        ConsoleReporter::Finalize();
        const double vm = m_times["BM_SimulatorScan"];
        const double native = m_times["BM_NativeScan"];
        if (vm > 0 && native > 0)
            std::printf("\nsimulator / native time per scan: %.2f\n"
                        "simulator real-time factor: %.0fx (%d units, %d ms cycle)\n",
                        vm / native, kCycleMs * 1000.0 / vm, static_cast<int>(images().size()),
                        kCycleMs);
    }

private:
    std::map<std::string, double> m_times; // microseconds per scan
};

} // namespace

// Only scans, for counting instructions with callgrind (docs/performance.md).
void scanOnly(bool native, int scans) {
    rs::sim::Simulation simulation(images(), kCycleMs);
    auto plant = std::make_unique<rs::native::Plant>();
    for (int scan = 0; scan < scans; ++scan) {
        for (int station : simulation.stations()) {
            if (native)
                driveInputs(plant->memory[station], static_cast<std::uint64_t>(scan));
            else
                driveInputs(simulation.unit(station)->memory(), static_cast<std::uint64_t>(scan));
        }
        if (native)
            rs::native::scanPlant(*plant, static_cast<std::int64_t>(scan) * kCycleMs, kCycleMs);
        else
            simulation.scan();
    }
}

int main(int argc, char** argv) {
    if (argc == 3 &&
        (std::strcmp(argv[1], "--scans") == 0 || std::strcmp(argv[1], "--native-scans") == 0)) {
        scanOnly(std::strcmp(argv[1], "--native-scans") == 0, std::atoi(argv[2]));
        return 0;
    }
    const bool verifyOnly = argc > 1 && std::strcmp(argv[1], "--verify") == 0;
    if (!sameResults(verifyOnly ? 2000 : 300))
        return 1;
    if (verifyOnly) {
        std::printf("simulator and native code agree on %zu units over 2000 scans, and so do "
                    "conduction on demand and marked while scanning\n",
                    images().size());
        return 0;
    }
    benchmark::Initialize(&argc, argv);
    RatioReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    benchmark::Shutdown();
    return 0;
}
