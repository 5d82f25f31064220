// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProjectGenerator.h"

#include "document/ProjectDocument.h"
#include "ladder/LadderPage.h"
#include "ladder/LadderView.h"
#include "ladder/NetworkItem.h"
#include "project/ProjectFile.h"

#include <QApplication>
#include <QImage>
#include <QScrollBar>
#include <QUndoStack>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>

// The ladder editor's page on a unit of 2,000 networks, offscreen: opening it
// up to its first painted frame, and scrolling through it frame by frame.
namespace {

constexpr int kNetworks = 2000;

// One unit whose PLC code has at least 2,000 networks: the generator's main
// code holds 85 % of a unit's statements, most of them grouped under comments
// (about eleven statements a network).
constexpr int kPlantStatements = 27000;
// A unit of ordinary size, for comparison: about 30 networks.
constexpr int kSmallUnitStatements = 400;

const rs::project::Project& plant(int statements) {
    static std::map<int, rs::project::Project> projects;
    auto found = projects.find(statements);
    if (found == projects.end()) {
        rs::bench::GeneratorOptions options;
        options.units = 1;
        options.statementsPerUnit = statements;
        found = projects
                    .emplace(statements,
                             rs::project::readProject(rs::bench::generateProject(options)).project)
                    .first;
    }
    return found->second;
}

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

struct OpenPage {
    std::unique_ptr<rs::ui::ProjectDocument> document;
    std::unique_ptr<rs::ui::LadderPage> page;
    QImage frame{1280, 800, QImage::Format_ARGB32_Premultiplied};

    explicit OpenPage(int statements = kPlantStatements)
        : document(std::make_unique<rs::ui::ProjectDocument>(plant(statements))) {
        page = std::make_unique<rs::ui::LadderPage>();
        page->resize(1280, 900);
        page->setAttribute(Qt::WA_DontShowOnScreen);
        page->show();
        page->showUnit(document.get(), 0, 0);
    }

    // Paints what the view shows now, as a screen update would.
    void paintFrame() {
        QWidget* viewport = page->view()->viewport();
        if (frame.size() != viewport->size())
            frame = QImage(viewport->size(), QImage::Format_ARGB32_Premultiplied);
        viewport->render(&frame);
    }
};

void BM_OpenToFirstPaint(benchmark::State& state) {
    int networks = 0;
    for (auto _ : state) {
        OpenPage open;
        open.paintFrame();
        networks = open.page->networkCount(0);
    }
    state.counters["networks"] = networks;
}
BENCHMARK(BM_OpenToFirstPaint)->Unit(benchmark::kMillisecond)->Iterations(5);

// Scrolls from top to bottom in steps of 120 pixels (one wheel notch), each
// step one frame; reports the mean and the worst frame.
void BM_ScrollFrames(benchmark::State& state) {
    OpenPage open;
    QScrollBar* bar = open.page->view()->verticalScrollBar();
    double worst = 0;
    double total = 0;
    int frames = 0;
    for (auto _ : state) {
        bar->setValue(0);
        while (bar->value() < bar->maximum()) {
            const auto start = Clock::now();
            bar->setValue(bar->value() + 120);
            open.paintFrame();
            const double ms = millisecondsSince(start);
            worst = std::max(worst, ms);
            total += ms;
            ++frames;
        }
    }
    state.counters["frames"] = frames;
    state.counters["mean_frame_ms"] = frames ? total / frames : 0;
    state.counters["worst_frame_ms"] = worst;
    state.counters["networks"] = open.page->networkCount(0);
}
BENCHMARK(BM_ScrollFrames)->Unit(benchmark::kMillisecond)->Iterations(1);

// The page at its smallest zoom (10 %): networks sketched without text.
void BM_ZoomedOutFrame(benchmark::State& state) {
    OpenPage open;
    open.page->view()->setZoom(rs::ui::LadderView::kMinimumZoom);
    for (auto _ : state)
        open.paintFrame();
}
BENCHMARK(BM_ZoomedOutFrame)->Unit(benchmark::kMillisecond);

// Times `edit` and the undo after it, each with the frame after it: the two
// halves of what the user waits for, as `name` and undo_ms. `prepare`, not
// timed, comes before each edit; false stops.
template <typename Prepare, typename Edit>
void measureEditAndUndo(benchmark::State& state, OpenPage& open, const char* name, Prepare prepare,
                        Edit edit) {
    double edited = 0;
    double undone = 0;
    for (auto _ : state) {
        if (!prepare())
            break;
        auto start = Clock::now();
        edit();
        open.paintFrame();
        edited += millisecondsSince(start);
        start = Clock::now();
        open.document->undoStack()->undo();
        open.paintFrame();
        undone += millisecondsSince(start);
    }
    const auto iterations = static_cast<double>(state.iterations());
    state.counters[name] = edited / iterations;
    state.counters["undo_ms"] = undone / iterations;
}

// An edit in the middle of the page and its undo: two changes of the project,
// each followed by the page (ladder model of the unit, layout of the networks
// whose statement numbers moved) and a frame.
void BM_PasteAndUndoMidway(benchmark::State& state) {
    OpenPage open(static_cast<int>(state.range(0)));
    const int middle = open.page->networkCount(0) / 2;
    open.page->setCursor({0, middle, std::nullopt, std::nullopt, -1});
    open.page->copyNetworks();
    measureEditAndUndo(
        state, open, "paste_ms", [] { return true; }, [&] { open.page->pasteNetworks(); });
    state.counters["networks"] = open.page->networkCount(0);
}
BENCHMARK(BM_PasteAndUndoMidway)
    ->Arg(kPlantStatements)
    ->Arg(kSmallUnitStatements)
    ->Unit(benchmark::kMillisecond);

// One element deleted from a network in the middle of the page (an edit of
// one network, as inserting or changing an element is), a frame, the undo
// and a frame: each half is one ladder edit as the user waits for it.
void BM_DeleteElementAndUndoMidway(benchmark::State& state) {
    OpenPage open(static_cast<int>(state.range(0)));
    const int middle = open.page->networkCount(0) / 2;
    const auto& element = open.page->networkItem(0, middle)->layout().elements.front();
    const std::uint32_t statement = element.statement;
    const std::uint16_t number = element.element;
    measureEditAndUndo(
        state, open, "edit_ms",
        [&] {
            if (open.page->selectElement(statement, number))
                return true;
            state.SkipWithError("the element is not on the page");
            return false;
        },
        [&] { open.page->deleteSelection(); });
}
BENCHMARK(BM_DeleteElementAndUndoMidway)
    ->Arg(kPlantStatements)
    ->Arg(kSmallUnitStatements)
    ->Unit(benchmark::kMillisecond);

// A new live state on every network: what the simulator's screen updates cost.
void BM_LiveRepaint(benchmark::State& state) {
    OpenPage open;
    rs::ui::LadderLiveState live;
    for (std::uint32_t statement = 0; statement < 4000; ++statement)
        live.power.statements[statement].energised = statement % 2 == 0;
    for (auto _ : state) {
        open.page->setLiveState(&live);
        open.paintFrame();
    }
}
BENCHMARK(BM_LiveRepaint)->Unit(benchmark::kMillisecond);

} // namespace

// Widgets need a QApplication; offscreen, no display is needed.
int main(int argc, char* argv[]) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    if (const int networks = OpenPage().page->networkCount(0); networks < kNetworks) {
        std::fprintf(stderr, "the generated unit has only %d networks\n", networks);
        return 1;
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
