// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProjectGenerator.h"

#include "NetworkPainter.h"
#include "NetworkPicture.h"
#include "ladder/Layout.h"
#include "ladder/UnitLadder.h"
#include "project/ProjectFile.h"

#include <QGuiApplication>
#include <QImage>
#include <QPainter>

#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

namespace {

constexpr std::size_t kNetworks = 2000;

// One network of the generated plant, ready to lay out.
struct NetworkToDraw {
    rs::ladder::Network network;
    rs::ladder::LayoutContext context;
};

// The first 2,000 networks of the default generated plant (the one the other
// benchmarks use: single statements as written by hand, and networks the IDE
// grouped under comments), as the ladder pages show them.
const std::vector<NetworkToDraw>& networks() {
    static const auto project = rs::project::readProject(rs::bench::generateProject({})).project;
    static std::vector<rs::ladder::SymbolTable> symbols;
    static const std::vector<NetworkToDraw> all = [] {
        std::vector<NetworkToDraw> list;
        symbols.reserve(project.program.units.size());
        for (const auto& unit : project.program.units) {
            symbols.push_back(rs::ladder::SymbolTable::of(project.program, unit.station()));
            for (const auto& page : rs::ladder::unitLadder(unit))
                for (std::size_t i = 0; i < page.ladder.networks.size(); ++i) {
                    if (list.size() == kNetworks)
                        return list;
                    rs::ladder::LayoutContext context;
                    context.number = static_cast<int>(i) + 1;
                    context.firstStatement = page.firstStatements[i];
                    context.symbols = &symbols.back();
                    list.push_back({page.ladder.networks[i], context});
                }
        }
        return list;
    }();
    return all;
}

void countNetworks(benchmark::State& state) {
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(networks().size()));
    state.counters["networks"] = static_cast<double>(networks().size());
}

// Geometry alone: what every view needs before it draws.
void BM_Layout(benchmark::State& state) {
    for (auto _ : state)
        for (const auto& n : networks())
            benchmark::DoNotOptimize(rs::ladder::layoutNetwork(n.network, n.context));
    countNetworks(state);
}
BENCHMARK(BM_Layout)->Unit(benchmark::kMillisecond);

// Layout and drawing on one raster canvas, as a view repaints networks.
void BM_LayoutAndPaint(benchmark::State& state) {
    QImage canvas(2400, 1600, QImage::Format_ARGB32_Premultiplied);
    const rs::render::LadderStyle style;
    for (auto _ : state)
        for (const auto& n : networks()) {
            const auto layout = rs::ladder::layoutNetwork(n.network, n.context);
            QPainter painter(&canvas);
            rs::render::paintNetwork(painter, layout, style);
        }
    countNetworks(state);
}
BENCHMARK(BM_LayoutAndPaint)->Unit(benchmark::kMillisecond);

// The same with every element and wire conducting: the heavier pens and fills.
void BM_LayoutAndPaintPowered(benchmark::State& state) {
    QImage canvas(2400, 1600, QImage::Format_ARGB32_Premultiplied);
    const rs::render::LadderStyle style;
    rs::render::PowerSnapshot power;
    for (std::uint32_t statement = 0; statement < 8000; ++statement) {
        auto& p = power.statements[statement];
        p.energised = true;
        for (std::uint16_t element = 1; element < 64; ++element)
            p.conducting.insert(element);
    }
    for (auto _ : state)
        for (const auto& n : networks()) {
            const auto layout = rs::ladder::layoutNetwork(n.network, n.context);
            QPainter painter(&canvas);
            rs::render::paintNetwork(painter, layout, style, &power);
        }
    countNetworks(state);
}
BENCHMARK(BM_LayoutAndPaintPowered)->Unit(benchmark::kMillisecond);

// What `rungsmith-cli ladder` does between reading and writing: a picture per network.
void BM_LayoutAndPng(benchmark::State& state) {
    const rs::render::LadderStyle style;
    for (auto _ : state)
        for (const auto& n : networks())
            benchmark::DoNotOptimize(
                rs::render::networkImage(rs::ladder::layoutNetwork(n.network, n.context), style));
    countNetworks(state);
}
BENCHMARK(BM_LayoutAndPng)->Unit(benchmark::kMillisecond);

void BM_LayoutAndSvg(benchmark::State& state) {
    const rs::render::LadderStyle style;
    for (auto _ : state)
        for (const auto& n : networks())
            benchmark::DoNotOptimize(
                rs::render::networkSvg(rs::ladder::layoutNetwork(n.network, n.context), style));
    countNetworks(state);
}
BENCHMARK(BM_LayoutAndSvg)->Unit(benchmark::kMillisecond);

} // namespace

// Text needs fonts, and fonts need a QGuiApplication (offscreen: no display).
int main(int argc, char* argv[]) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QGuiApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    if (networks().size() != kNetworks) {
        std::fprintf(stderr, "the generated plant has only %zu networks\n", networks().size());
        return 1;
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
