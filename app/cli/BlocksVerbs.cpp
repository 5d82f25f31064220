// SPDX-License-Identifier: GPL-3.0-or-later
#include "BlocksVerbs.h"

#include "ProjectLoading.h"

#include "Verbs.h"
#include "blockdoc/StateMachineTable.h"
#include "blocks/LibrarySearch.h"
#include "blocks/LibraryWords.h"
#include "lang/Diagnostic.h"

#include <QCoreApplication>

#include <algorithm>
#include <cstdio>

namespace rs::cli {

namespace {

struct Libraries {
    blocks::LibrarySet set;
    std::vector<const blocks::LoadedLibrary*> selected; // what the verb looks at
    int status = Ok;
};

Libraries loadLibraries(const Invocation& invocation) {
    Libraries result;
    QStringList files;
    QStringList names;
    for (const QString& value : invocation.options.values(QStringLiteral("lib")))
        (isLibraryFile(value) ? files : names).append(value);
    result.set = blocks::loadLibraries(
        blocks::standardLibraryFolders(QCoreApplication::applicationDirPath()), {}, files);
    for (const auto& problem : result.set.problems) {
        if (!problem.readError.isEmpty()) {
            std::fprintf(stderr, "rungsmith-cli: %s\n", qPrintable(problem.readError));
            result.status = UsageOrIo;
            continue;
        }
        for (const auto& diagnostic : problem.diagnostics)
            std::fprintf(stderr, "%s\n",
                         lang::formatDiagnostic(problem.path.toStdString(), diagnostic).c_str());
        if (lang::errorCount(problem.diagnostics) > 0 && result.status == Ok)
            result.status = Failed;
    }
    if (result.status == UsageOrIo)
        return result;
    if (files.isEmpty() && names.isEmpty()) {
        for (const auto& loaded : result.set.libraries)
            result.selected.push_back(&loaded);
        return result;
    }
    for (const auto& loaded : result.set.libraries)
        if (loaded.origin == blocks::LibraryOrigin::User && files.contains(loaded.path))
            result.selected.push_back(&loaded);
    for (const QString& name : names) {
        const blocks::LoadedLibrary* loaded = result.set.findLibrary(name.toStdString());
        if (!loaded) {
            std::fprintf(stderr,
                         "rungsmith-cli: --lib %s: no library of that name and no such file\n",
                         qPrintable(name));
            result.status = UsageOrIo;
            return result;
        }
        result.selected.push_back(loaded);
    }
    return result;
}

std::string pinList(const blocks::BlockDefinition& block, blocks::PinDirection direction) {
    std::string text;
    for (const auto& pin : block.pins) {
        if (pin.direction != direction)
            continue;
        if (!text.empty())
            text += ", ";
        text += pin.role == blocks::PinRole::Secondary ? "[" + pin.name + "]" : pin.name;
    }
    return text;
}

int list(const Invocation& invocation) {
    if (invocation.arguments.size() != 1)
        return usage(QStringLiteral("blocks list takes no other argument"));
    const Libraries libraries = loadLibraries(invocation);
    if (libraries.status == UsageOrIo)
        return UsageOrIo;
    for (const auto* loaded : libraries.selected)
        for (const auto& block : loaded->library.blocks)
            std::printf("%s %s(%s -> %s)\n", loaded->library.name.c_str(), block.name.c_str(),
                        pinList(block, blocks::PinDirection::In).c_str(),
                        pinList(block, blocks::PinDirection::Out).c_str());
    return libraries.status;
}

void printIndented(const std::string& text) {
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos)
            end = text.size();
        std::printf("  %s\n", text.substr(start, end - start).c_str());
        start = end + 1;
    }
}

std::string operandList(const blocks::Pin& pin) {
    std::string text;
    for (const auto kind : pin.operands) {
        if (!text.empty())
            text += ',';
        text += blocks::wordOf(kind);
    }
    return text;
}

// Pads UTF-8 text to `width` characters (printf's width counts bytes).
std::string padded(std::string text, std::size_t width) {
    const auto characters =
        static_cast<std::size_t>(std::count_if(text.begin(), text.end(), [](char c) {
            return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
        }));
    if (characters < width)
        text.append(width - characters, ' ');
    return text;
}

// The state machine the body describes (blockdoc::stateMachineOf), as the
// documentation page shows it: states with meaning and outputs, then each
// state's transitions in the order they are tried.
void printStateMachine(const blocks::BlockDefinition& block, const std::string& language) {
    const blockdoc::StateMachineTable table = blockdoc::stateMachineOf(block);
    if (table.empty())
        return;
    std::printf("\nStates (DiagCode, meaning, outputs on):\n");
    for (std::size_t i = 0; i < table.states.size(); ++i) {
        const int state = table.states[i];
        std::string meaning;
        for (const blocks::StateMeaning& m : block.states)
            if (m.code == state)
                meaning = m.meaning.in(language);
        std::string on;
        for (std::size_t o = 0; o < table.outputs.size(); ++o)
            if (table.outputsOn[i][o])
                on += (on.empty() ? "" : ", ") + table.outputs[o];
        std::printf("  %s  %s %s\n", blockdoc::stateCode(state).c_str(),
                    padded(meaning, 50).c_str(), on.empty() ? "-" : on.c_str());
    }
    std::printf("\nTransitions (in each state the first whose condition holds is taken):\n");
    auto print = [](const std::string& from, const blockdoc::Transition& t) {
        std::printf("  %-7s  %-50s -> %s\n", from.c_str(),
                    t.condition.empty() ? "always" : t.condition.c_str(),
                    blockdoc::stateCode(t.to).c_str());
    };
    for (const blockdoc::Transition& t : table.transitions)
        if (t.from.empty())
            print("any", t);
    for (const int state : table.states) {
        std::string from = blockdoc::stateCode(state);
        for (const blockdoc::Transition* t : table.transitionsFrom(state))
            if (!t->from.empty()) {
                print(from, *t);
                from.clear();
            }
    }
}

int show(const Invocation& invocation) {
    if (invocation.arguments.size() != 2)
        return usage(QStringLiteral("blocks show takes one block NAME"));
    const QString language = invocation.options.isSet(QStringLiteral("language"))
                                 ? invocation.options.value(QStringLiteral("language"))
                                 : QStringLiteral("en");
    if (language != QLatin1String("en") && language != QLatin1String("sv") &&
        language != QLatin1String("de"))
        return usage(QStringLiteral("--language takes en, sv or de, not '%1'").arg(language));
    const Libraries libraries = loadLibraries(invocation);
    if (libraries.status == UsageOrIo)
        return UsageOrIo;
    const std::string name = invocation.arguments[1].toStdString();
    for (const auto* loaded : libraries.selected) {
        const blocks::BlockDefinition* block = loaded->library.findBlock(name);
        if (!block)
            continue;
        std::printf("%s: %s block, version %s, library %s %s\n", block->name.c_str(),
                    std::string(blocks::wordOf(block->kind)).c_str(), block->version.c_str(),
                    loaded->library.name.c_str(), loaded->library.version.c_str());
        if (block->kind == blocks::BlockKind::System)
            std::printf("System instruction: %s\n", block->systemInstruction.c_str());
        std::printf("\n");
        printIndented(block->description.in(language.toStdString()));
        std::printf("\nPins:\n");
        for (const auto& pin : block->pins) {
            const std::string fill = pin.defaultValue ? "default " + *pin.defaultValue
                                     : pin.direction == blocks::PinDirection::In
                                         ? std::string("required")
                                         : std::string("-");
            std::printf("  %-3s %-20s %-15s %-9s %-14s %s\n",
                        std::string(blocks::wordOf(pin.direction)).c_str(), pin.name.c_str(),
                        std::string(blocks::wordOf(pin.kind)).c_str(),
                        std::string(blocks::wordOf(pin.role)).c_str(), fill.c_str(),
                        operandList(pin).c_str());
        }
        printStateMachine(*block, language.toStdString());
        if (!block->privates.empty()) {
            std::printf("\nPrivate variables:\n");
            for (const auto& variable : block->privates)
                std::printf("  %s %s\n", variable.name.c_str(),
                            std::string(blocks::wordOf(variable.kind)).c_str());
        }
        std::printf("\nTimers: %d\n", block->timers);
        if (!block->body.empty()) {
            std::printf("\nBody:\n");
            for (const auto& line : block->body)
                std::printf("  %s\n", line.c_str());
        }
        return libraries.status;
    }
    std::fprintf(stderr, "rungsmith-cli: no block named '%s' in the libraries\n",
                 lang::visibleText(name).c_str());
    return Failed;
}

} // namespace

int runBlocks(const Invocation& invocation) {
    const QStringList& arguments = invocation.arguments;
    if (arguments.isEmpty())
        return usage(QStringLiteral("blocks takes 'list' or 'show NAME'"));
    if (arguments[0] == QLatin1String("list"))
        return list(invocation);
    if (arguments[0] == QLatin1String("show"))
        return show(invocation);
    return usage(QStringLiteral("unknown blocks verb '%1': list or show").arg(arguments[0]));
}

} // namespace rs::cli
