// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProjectGenerator.h"

#include "document/ProjectDocument.h"
#include "ladder/LadderPage.h"
#include "ladder/LadderView.h"
#include "shell/MainWindow.h"
#include "sim/LiveLadder.h"
#include "sim/Simulation.h"
#include "sim/SimulationMode.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QGraphicsScene>
#include <QTemporaryDir>

#include <benchmark/benchmark.h>

#include <cstdio>
#include <memory>

// The window's cost per live update of the simulation, with the ladder page
// of a generated unit showing 2,000 networks at once (zoomed out to fit a
// tall window).
namespace {

constexpr int kNetworks = 2000;

struct Fixture {
    QTemporaryDir directory;
    rs::ui::MainWindow window;
    rs::ui::SimulationMode* mode = nullptr;
    rs::ui::LadderPage* ladder = nullptr;
    int networks = 0;
    qint64 beginMs = 0; // compiling and powering on, on the window's thread
    QString error;

    Fixture() {
        // One unit whose PLC code is long enough for 2,000 networks.
        rs::bench::GeneratorOptions options;
        options.units = 1;
        options.statementsPerUnit = 26500;
        const QString path = directory.filePath(QStringLiteral("plant.sps"));
        QFile file(path);
        if (!file.open(QIODevice::WriteOnly)) {
            error = QStringLiteral("cannot write %1").arg(path);
            return;
        }
        file.write(QByteArray::fromStdString(rs::bench::generateProject(options)));
        file.close();
        if (error = window.loadFile(path); !error.isEmpty())
            return;
        window.resize(1600, 3000);
        window.show();
        if (!window.showPage({rs::ui::PageRef::Kind::Ladder, window.currentDocument(), 0, 0})) {
            error = QStringLiteral("no ladder page");
            return;
        }
        ladder = window.ladderPage();
        for (int step = 0; step < ladder->stepCount(); ++step)
            networks += ladder->networkCount(step);
        mode = window.simulation();
        QElapsedTimer clock;
        clock.start();
        if (error = mode->begin(); !error.isEmpty())
            return;
        beginMs = clock.elapsed();
        for (int i = 0; i < 20; ++i)
            mode->session()->singleScan();
        QApplication::processEvents();
        ladder->view()->fitInView(ladder->scene()->sceneRect(), Qt::KeepAspectRatio);
        QApplication::processEvents();
    }
};

// Made in main and gone before the QApplication is.
std::unique_ptr<Fixture> theFixture;

Fixture& fixture() {
    return *theFixture;
}

void countNetworks(benchmark::State& state) {
    state.counters["networks"] = fixture().networks;
}

// The page's whole state built afresh from the engine's last scan, as when
// the simulation begins or another unit is shown.
void BM_FirstUpdate(benchmark::State& state) {
    Fixture& f = fixture();
    rs::ui::LadderLiveState live;
    for (auto _ : state) {
        rs::ui::LiveLadderBuilder builder;
        builder.update(live, *f.mode->session()->simulation(), 0);
        benchmark::DoNotOptimize(live);
    }
    countNetworks(state);
}
BENCHMARK(BM_FirstUpdate)->Unit(benchmark::kMillisecond);

// One scan of the unit alone, in a simulation of its own: what the next
// benchmark spends besides the window's work.
void BM_Scan(benchmark::State& state) {
    Fixture& f = fixture();
    rs::sim::Simulation simulation(f.mode->session()->images());
    for (auto _ : state)
        simulation.scan();
    countNetworks(state);
}
BENCHMARK(BM_Scan)->Unit(benchmark::kMillisecond);

// A scan and the engine's conduction of it, which the engine computes on
// demand by running the scan again with marking (docs/simulator.md): the
// part of an update that is the engine's, not the window's.
void BM_ScanAndConduction(benchmark::State& state) {
    Fixture& f = fixture();
    rs::sim::Simulation simulation(f.mode->session()->images());
    const rs::sim::UnitEngine* unit = simulation.unit(0);
    for (auto _ : state) {
        simulation.scan();
        benchmark::DoNotOptimize(unit->conduction().data());
    }
    countNetworks(state);
}
BENCHMARK(BM_ScanAndConduction)->Unit(benchmark::kMillisecond);

// A scan and the live update it causes, as the session's timer does it: the
// ladder page's state brought up to date and handed over (the page schedules
// a repaint), the clock, the docks. Minus BM_Scan, the window's cost.
void BM_ScanAndLiveUpdate(benchmark::State& state) {
    Fixture& f = fixture();
    for (auto _ : state)
        f.mode->session()->singleScan();
    countNetworks(state);
}
BENCHMARK(BM_ScanAndLiveUpdate)->Unit(benchmark::kMillisecond);

// Painting the view with every network in it, after an update.
void BM_PaintAllNetworks(benchmark::State& state) {
    Fixture& f = fixture();
    QWidget* viewport = f.ladder->view()->viewport();
    for (auto _ : state)
        viewport->repaint();
    countNetworks(state);
}
BENCHMARK(BM_PaintAllNetworks)->Unit(benchmark::kMillisecond);

// The same at 100 % zoom, where the view (as tall as the window) shows a few
// dozen networks: what a user sees after each update of a page of this size.
void BM_PaintAtFullSize(benchmark::State& state) {
    Fixture& f = fixture();
    rs::ui::LadderView* view = f.ladder->view();
    const QTransform fitted = view->transform();
    view->setTransform(QTransform());
    QApplication::processEvents();
    for (auto _ : state)
        view->viewport()->repaint();
    view->setTransform(fitted);
    countNetworks(state);
    state.counters["viewport_width"] = view->viewport()->width();
    state.counters["viewport_height"] = view->viewport()->height();
}
BENCHMARK(BM_PaintAtFullSize)->Unit(benchmark::kMillisecond);

// The same at the smallest zoom a user can set (LadderView::kMinimumZoom):
// the most networks the window ever shows outside this benchmark.
void BM_PaintAtMinimumZoom(benchmark::State& state) {
    Fixture& f = fixture();
    rs::ui::LadderView* view = f.ladder->view();
    const QTransform fitted = view->transform();
    view->setTransform(
        QTransform::fromScale(rs::ui::LadderView::kMinimumZoom, rs::ui::LadderView::kMinimumZoom));
    QApplication::processEvents();
    for (auto _ : state)
        view->viewport()->repaint();
    state.counters["networks_in_view"] =
        static_cast<double>(view->items(view->viewport()->rect()).size());
    view->setTransform(fitted);
    countNetworks(state);
}
BENCHMARK(BM_PaintAtMinimumZoom)->Unit(benchmark::kMillisecond);

} // namespace

// Widgets need a QApplication (offscreen: no display).
int main(int argc, char* argv[]) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    theFixture = std::make_unique<Fixture>();
    const Fixture& f = fixture();
    int status = 0;
    if (!f.error.isEmpty()) {
        std::fprintf(stderr, "%s\n", qPrintable(f.error));
        status = 1;
    } else if (f.networks < kNetworks) {
        std::fprintf(stderr, "the generated unit has only %d networks\n", f.networks);
        status = 1;
    } else {
        std::fprintf(stderr, "%d networks, view scale %.4f, simulation began in %lld ms\n",
                     f.networks, f.ladder->view()->transform().m11(),
                     static_cast<long long>(f.beginMs));
        benchmark::RunSpecifiedBenchmarks();
    }
    benchmark::Shutdown();
    theFixture.reset();
    return status;
}
