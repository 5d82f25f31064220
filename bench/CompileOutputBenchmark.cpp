// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProjectGenerator.h"

#include "compiler/Compiler.h"
#include "document/ProjectDocument.h"
#include "ladder/LadderPage.h"
#include "ladder/NetworkItem.h"
#include "memory/HugePageHeap.h"
#include "output/CompileOutput.h"
#include "project/ProjectFile.h"
#include "shell/MainWindow.h"
#include "text/ProgramEditor.h"
#include "text/TextPage.h"

#include <QAction>
#include <QApplication>
#include <QFile>
#include <QTemporaryDir>
#include <QUndoStack>

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <string>

// What the IDE adds to the compiler's own time on a large project (issue 23):
// Build > Compile and the Output dock showing the result of the generated
// plant (32 units x 2,000 statements), tens of thousands of warnings; and the
// check of a unit's text after a character is typed.
namespace {

struct Compiled {
    std::string text;
    rs::compiler::CompileResult result;
};

const Compiled& plant() {
    static const Compiled compiled = [] {
        Compiled c;
        c.text = rs::bench::generateProject(rs::bench::GeneratorOptions{});
        const auto read = rs::project::readProject(c.text);
        c.result = rs::compiler::compile(read.project, {}, c.text);
        return c;
    }();
    return compiled;
}

void BM_ShowCompileResult(benchmark::State& state) {
    const Compiled& c = plant();
    rs::ui::CompileOutput output;
    output.resize(1200, 300);
    output.show();
    for (auto _ : state) {
        output.showResult(QStringLiteral("plant"), c.text, c.result, QString());
        QApplication::processEvents(); // the view lays the rows out and paints
    }
    state.counters["diagnostics"] = static_cast<double>(c.result.diagnostics.size());
}
BENCHMARK(BM_ShowCompileResult)->Unit(benchmark::kMillisecond);

// The plant saved in a folder of its own and opened in a window, as a user
// opens it; false, and the benchmark skipped, when that fails.
bool openPlant(benchmark::State& state, const QTemporaryDir& directory,
               rs::ui::MainWindow& window) {
    const QString path = directory.filePath(QStringLiteral("plant.sps"));
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        state.SkipWithError("cannot write the project");
        return false;
    }
    file.write(QByteArray::fromStdString(plant().text));
    file.close();
    if (!window.loadFile(path).isEmpty()) {
        state.SkipWithError("cannot open the project");
        return false;
    }
    window.resize(1280, 900);
    window.show();
    return true;
}

// Build > Compile in the window, from the action to the result shown: the
// compile on its worker, the image written beside the project, the Output.
void BM_CompileInTheWindow(benchmark::State& state) {
    QTemporaryDir directory;
    rs::ui::MainWindow window;
    if (!openPlant(state, directory, window))
        return;
    QAction* compile = window.findChild<QAction*>(QStringLiteral("compileAction"));
    for (auto _ : state) {
        compile->trigger();
        while (window.isCompiling())
            QApplication::processEvents(QEventLoop::WaitForMoreEvents, 5);
    }
}
BENCHMARK(BM_CompileInTheWindow)->Unit(benchmark::kMillisecond)->Iterations(10);

// A character typed in the text view of unit 0, from the text being read
// into the project (what the page does 300 ms after the last key) to the
// check's marks: `gui_ms` is the part on the window's thread, the rest runs
// on the check's worker.
void BM_RecheckAfterTyping(benchmark::State& state) {
    rs::ui::ProjectDocument document(rs::project::readProject(plant().text).project);
    rs::ui::TextPage page;
    page.resize(1200, 800);
    page.show();
    page.showUnit(&document, 0);
    while (page.isChecking()) // the check of the text as opened
        QApplication::processEvents(QEventLoop::WaitForMoreEvents, 5);
    rs::ui::ProgramEditor* editor = page.editor();
    // Each key changes the project: a letter more in the last line's comment.
    const int last = editor->lines() - 1;
    editor->insertAt(QStringLiteral(" ; typed "), last, editor->text(last).length());
    page.applyNow();
    while (page.isChecking())
        QApplication::processEvents(QEventLoop::WaitForMoreEvents, 5);
    double guiMs = 0;
    for (auto _ : state) {
        editor->insertAt(QStringLiteral("x"), last, editor->text(last).length());
        const auto start = std::chrono::steady_clock::now();
        page.applyNow();
        guiMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                     .count();
        while (page.isChecking())
            QApplication::processEvents(QEventLoop::WaitForMoreEvents, 5);
    }
    state.counters["gui_ms"] = guiMs / static_cast<double>(state.iterations());
    state.counters["lines"] = editor->lines();
}
BENCHMARK(BM_RecheckAfterTyping)->Unit(benchmark::kMillisecond)->Iterations(5);

// One ladder edit in the window (an element of a network in the middle of
// unit 0 deleted, then undone), from the command to the window idle again:
// what every view of the project that follows the edit adds to the page's
// own cost (rungsmith_bench_ladder_scroll).
void BM_LadderEditInTheWindow(benchmark::State& state) {
    QTemporaryDir directory;
    rs::ui::MainWindow window;
    if (!openPlant(state, directory, window))
        return;
    QApplication::processEvents();
    rs::ui::LadderPage* page = window.ladderPage();
    const int middle = page->networkCount(0) / 2;
    const auto& element = page->networkItem(0, middle)->layout().elements.front();
    const std::uint32_t statement = element.statement;
    const std::uint16_t number = element.element;
    const auto timed = [](const auto& command) {
        const auto start = std::chrono::steady_clock::now();
        command();
        QApplication::processEvents();
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count();
    };
    double edit = 0;
    double undo = 0;
    for (auto _ : state) {
        page->selectElement(statement, number);
        edit += timed([&] { page->deleteSelection(); });
        undo += timed([&] { page->document()->undoStack()->undo(); });
    }
    const auto iterations = static_cast<double>(state.iterations());
    state.counters["edit_ms"] = edit / iterations;
    state.counters["undo_ms"] = undo / iterations;
    state.counters["networks"] = page->networkCount(0);
}
BENCHMARK(BM_LadderEditInTheWindow)->Unit(benchmark::kMillisecond)->Iterations(20);

} // namespace

int main(int argc, char* argv[]) {
    rs::memory::backTheHeapWithHugePages(); // as the IDE does
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
