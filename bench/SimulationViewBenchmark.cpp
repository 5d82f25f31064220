#include "ProjectGenerator.h"

#include "MainWindow.h"
#include "ProjectDocument.h"
#include "ladder/LadderPage.h"
#include "ladder/LadderView.h"
#include "sim/LiveLadder.h"
#include "sim/Simulation.h"
#include "sim/SimulationMode.h"

#include <QApplication>
#include <QFile>
#include <QGraphicsScene>
#include <QTemporaryDir>

#include <benchmark/benchmark.h>

#include <cstdio>

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
        if (error = mode->begin(); !error.isEmpty())
            return;
        for (int i = 0; i < 20; ++i)
            mode->session()->singleScan();
        QApplication::processEvents();
        ladder->view()->fitInView(ladder->scene()->sceneRect(), Qt::KeepAspectRatio);
        QApplication::processEvents();
    }
};

Fixture& fixture() {
    static Fixture f;
    return f;
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

} // namespace

// Widgets need a QApplication (offscreen: no display).
int main(int argc, char* argv[]) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    Fixture& f = fixture();
    if (!f.error.isEmpty()) {
        std::fprintf(stderr, "%s\n", qPrintable(f.error));
        return 1;
    }
    if (f.networks < kNetworks) {
        std::fprintf(stderr, "the generated unit has only %d networks\n", f.networks);
        return 1;
    }
    std::fprintf(stderr, "%d networks, view scale %.4f\n", f.networks,
                 f.ladder->view()->transform().m11());
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
