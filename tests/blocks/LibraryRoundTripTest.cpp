// SPDX-License-Identifier: GPL-3.0-or-later
#include "blocks/LibraryReader.h"
#include "blocks/LibraryWords.h"
#include "blocks/LibraryWriter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace rs::blocks;

namespace {

// Random libraries that the reader must accept: names, pins of every kind,
// private variables, descriptions and state meanings with Swedish and German
// letters, and bodies of statements over the pins.
class RandomLibrary {
public:
    explicit RandomLibrary(unsigned seed) : m_random(seed) {}

    BlockLibrary make() {
        BlockLibrary library;
        library.name = name(40);
        library.version = version();
        if (chance(2))
            library.description = description();
        const int blocks = below(6);
        for (int i = 0; i < blocks; ++i) {
            BlockDefinition block = makeBlock();
            block.name += "_" + std::to_string(i); // unique in any case
            library.blocks.push_back(std::move(block));
        }
        return library;
    }

private:
    int below(int n) { return std::uniform_int_distribution<int>(0, n - 1)(m_random); }
    bool chance(int n) { return below(n) == 0; }
    template <typename T> const T& pick(const std::vector<T>& items) {
        return items[static_cast<std::size_t>(below(static_cast<int>(items.size())))];
    }

    std::string name(int maxLength) {
        static const std::string first = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz";
        static const std::string rest = first + "0123456789_";
        std::string text(1, first[static_cast<std::size_t>(below(52))]);
        const int length = below(std::min(maxLength, 12));
        for (int i = 0; i < length; ++i)
            text += rest[static_cast<std::size_t>(below(static_cast<int>(rest.size())))];
        return text;
    }

    std::string version() {
        std::string text = std::to_string(below(20));
        for (int parts = below(3); parts > 0; --parts)
            text += "." + std::to_string(below(100));
        return text;
    }

    // In a body, braces always make a placeholder, even in a comment.
    std::string textLine(bool braces = true) {
        static const std::vector<std::string> words{
            "Två",   "kanaler", "är",     "från",  "Größe", "Übung", "schließt", "Ärger",
            "reset", "the",     "output", "{Pin}", "#1",    "100%",  "ÅÄÖ",      "–"};
        std::string text = chance(5) ? " " : "";
        const int count = 1 + below(8);
        for (int i = 0; i < count; ++i) {
            const std::string& word = pick(words);
            text += (i > 0 ? " " : "") + (braces || word != "{Pin}" ? word : "Pin");
        }
        return text;
    }

    std::string paragraph(bool mayBeEmpty) {
        if (mayBeEmpty && chance(3))
            return {};
        std::string text = textLine();
        for (int lines = below(3); lines > 0; --lines)
            text += "\n" + (chance(4) ? std::string() : textLine());
        return text;
    }

    Description description() { return {paragraph(false), paragraph(true), paragraph(true)}; }

    std::string defaultFor(PinKind kind) {
        switch (kind) {
        case PinKind::Bit:
            return std::to_string(below(2));
        case PinKind::Register:
            return std::to_string(below(65536) - 32768);
        case PinKind::DoubleRegister:
        case PinKind::Constant:
            return std::to_string(static_cast<long>(m_random()) - 2147483648L);
        case PinKind::Time: {
            const int hundredths = below(65536);
            const int fraction = hundredths % 100;
            return std::to_string(hundredths / 100) + "s" + (fraction < 10 ? "0" : "") +
                   std::to_string(fraction);
        }
        }
        return {};
    }

    Pin makePin(const std::string& pinName) {
        Pin pin;
        pin.name = pinName;
        pin.kind = static_cast<PinKind>(below(5));
        pin.direction =
            pin.kind == PinKind::Constant || chance(2) ? PinDirection::In : PinDirection::Out;
        pin.role = chance(3) ? PinRole::Secondary : PinRole::Primary;
        if (pin.direction == PinDirection::In && chance(2))
            pin.defaultValue = defaultFor(pin.kind);
        for (const OperandKind kind : possibleOperands(pin.kind, pin.direction))
            if (chance(2))
                pin.operands.push_back(kind);
        if (pin.operands.empty())
            pin.operands = possibleOperands(pin.kind, pin.direction);
        return pin;
    }

    std::string bitSource(const BlockDefinition& block) {
        std::vector<std::string> sources{"I0.3", "M0.7", "SM_1Hz"};
        for (const Pin& pin : block.pins)
            if (pin.kind == PinKind::Bit)
                sources.push_back("{" + pin.name + "}");
        for (const PrivateVariable& variable : block.privates)
            if (variable.kind == PrivateKind::Memory)
                sources.push_back("{#" + variable.name + "}");
        const std::string source = pick(sources);
        return below(4) == 0 ? "P(" + source + ")" : (chance(3) ? "/" : "") + source;
    }

    std::string statement(BlockDefinition& block) {
        std::vector<std::string> targets{"Q0.2"};
        for (const Pin& pin : block.pins)
            if (pin.kind == PinKind::Bit && pin.direction == PinDirection::Out)
                targets.push_back("{" + pin.name + "}");
        for (const PrivateVariable& variable : block.privates)
            if (variable.kind == PrivateKind::Memory)
                targets.push_back("{#" + variable.name + "}");
        std::string text = pick(targets) + " = " + bitSource(block);
        for (int terms = below(4); terms > 0; --terms)
            text += (chance(2) ? " * " : " + ") + bitSource(block);
        if (chance(3)) {
            std::string time = "1s50";
            for (const Pin& pin : block.pins)
                if (pin.kind == PinKind::Time && pin.direction == PinDirection::In)
                    time = "{" + pin.name + "}";
            text += " * TON(" + time + ")";
            ++block.timers;
        }
        if (chance(4))
            text += " ; " + textLine(false);
        return text;
    }

    BlockDefinition makeBlock() {
        BlockDefinition block;
        block.name = name(30);
        block.kind = chance(4) ? BlockKind::System : BlockKind::Macro;
        block.version = version();
        block.description = description();
        for (int states = below(5); states > 0; --states) {
            const int code = below(65536);
            if (std::none_of(block.states.begin(), block.states.end(),
                             [&](const StateMeaning& state) { return state.code == code; }))
                block.states.push_back({code,
                                        {textLine(), chance(2) ? textLine() : std::string(),
                                         chance(2) ? textLine() : std::string()}});
        }
        if (block.kind == BlockKind::System)
            block.systemInstruction = name(40);
        const int pins = below(8);
        for (int i = 0; i < pins; ++i)
            block.pins.push_back(makePin(name(20) + "_" + std::to_string(i)));
        const int privates = below(4);
        for (int i = 0; i < privates; ++i)
            block.privates.push_back({"v" + std::to_string(i), static_cast<PrivateKind>(below(3))});
        const int lines = block.kind == BlockKind::Macro ? 1 + below(6) : below(3);
        for (int i = 0; i < lines; ++i) {
            if (chance(6))
                block.body.emplace_back(chance(2) ? "" : "  ; " + textLine(false));
            else
                block.body.push_back(statement(block));
        }
        return block;
    }

    std::mt19937 m_random;
};

} // namespace

TEST(LibraryRoundTrip, ReadWriteReadKeepsEveryRandomLibrary) {
    for (unsigned seed = 1; seed <= 2000; ++seed) {
        const BlockLibrary library = RandomLibrary(seed).make();
        const std::string text = writeLibrary(library);
        const LibraryReadResult read = readLibrary(text);
        ASSERT_TRUE(read.ok()) << "seed " << seed << ": " << read.diagnostics.front().line << ":"
                               << read.diagnostics.front().column << ": "
                               << read.diagnostics.front().message << "\n"
                               << text;
        ASSERT_EQ(read.library, library) << "seed " << seed << "\n" << text;
        ASSERT_EQ(writeLibrary(read.library), text) << "seed " << seed;
    }
}
