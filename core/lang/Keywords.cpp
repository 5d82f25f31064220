// SPDX-License-Identifier: GPL-3.0-or-later
#include "Keywords.h"

#include "TextCase.h"

#include <algorithm>
#include <array>
#include <utility>

namespace rs::lang {

namespace {

constexpr std::array kTimerWords = {
    std::pair{TimerSpelling::TON, std::string_view("TON")},
    std::pair{TimerSpelling::TPS, std::string_view("TPS")},
    std::pair{TimerSpelling::TOF, std::string_view("TOF")},
    std::pair{TimerSpelling::T, std::string_view("T")},
    std::pair{TimerSpelling::IT, std::string_view("IT")},
};

constexpr std::array kIdKeywords = {
    std::pair{UnitFamily::Pluto, std::string_view("id_pluto")},
    std::pair{UnitFamily::Double, std::string_view("id_pluto_Double")},
    std::pair{UnitFamily::ASi, std::string_view("id_pluto_ASi")},
    std::pair{UnitFamily::B42ASi, std::string_view("id_pluto_B42_ASi")},
};

constexpr std::array kCompareWords = {
    std::pair{CompareOp::Equal, std::string_view("=")},
    std::pair{CompareOp::Greater, std::string_view(">")},
    std::pair{CompareOp::Less, std::string_view("<")},
    std::pair{CompareOp::GreaterEqual, std::string_view(">=")},
    std::pair{CompareOp::LessEqual, std::string_view("<=")},
};

// Binary is written "= a op b", so "=" reads back as the plain copy.
constexpr std::array kAssignWords = {
    std::pair{AssignOp::Increment, std::string_view("++")},
    std::pair{AssignOp::Decrement, std::string_view("--")},
    std::pair{AssignOp::AddAssign, std::string_view("+=")},
    std::pair{AssignOp::SubAssign, std::string_view("-=")},
    std::pair{AssignOp::MulAssign, std::string_view("*=")},
    std::pair{AssignOp::DivAssign, std::string_view("/=")},
    std::pair{AssignOp::Copy, std::string_view("=")},
    std::pair{AssignOp::Binary, std::string_view("=")},
};

constexpr std::array kBinaryWords = {
    std::pair{BinaryOp::Add, std::string_view("+")},
    std::pair{BinaryOp::Sub, std::string_view("-")},
    std::pair{BinaryOp::Mul, std::string_view("*")},
    std::pair{BinaryOp::Div, std::string_view("/")},
};

template <typename Table, typename Value> std::string_view wordOf(const Table& table, Value value) {
    for (const auto& [v, word] : table)
        if (v == value)
            return word;
    return table.front().second;
}

template <typename Table>
auto valueOf(const Table& table, std::string_view word)
    -> std::optional<typename Table::value_type::first_type> {
    const std::string lower = toLower(word);
    for (const auto& [value, spelled] : table)
        if (toLower(spelled) == lower)
            return value;
    return std::nullopt;
}

} // namespace

std::string_view timerWord(TimerSpelling spelling) {
    return wordOf(kTimerWords, spelling);
}

std::optional<TimerSpelling> timerSpellingOf(std::string_view word) {
    return valueOf(kTimerWords, word);
}

std::string_view statementWord(StatementKind kind) {
    switch (kind) {
    case StatementKind::Set:
        return kSetWord;
    case StatementKind::Reset:
    case StatementKind::SequenceReset:
        return kResetWord;
    case StatementKind::Toggle:
        return kToggleWord;
    case StatementKind::Jump:
        return kJumpWord;
    case StatementKind::Coil:
    case StatementKind::Assign:
        break;
    }
    return {};
}

const std::vector<std::string_view>& instructionWords() {
    static const std::vector<std::string_view> words = [] {
        std::vector<std::string_view> all = {kRisingEdgeWord, kFallingEdgeWord, kSetWord,
                                             kResetWord,      kToggleWord,      kJumpWord};
        for (const auto& [spelling, word] : kTimerWords)
            if (std::find(all.begin(), all.end(), word) == all.end())
                all.push_back(word);
        return all;
    }();
    return words;
}

std::string_view idKeyword(UnitFamily family) {
    return wordOf(kIdKeywords, family);
}

std::optional<UnitFamily> familyOfIdKeyword(std::string_view word) {
    return valueOf(kIdKeywords, word);
}

const std::vector<std::string_view>& declarationWords() {
    static const std::vector<std::string_view> words = [] {
        std::vector<std::string_view> all;
        for (const auto& [family, word] : kIdKeywords)
            all.push_back(word);
        all.push_back(kTypeKeyword);
        all.push_back(kProgramKeyword);
        return all;
    }();
    return words;
}

std::string_view instructionSetWord(int instructionSet) {
    return instructionSet == 2 ? "is2" : instructionSet == 3 ? "is3" : "";
}

int instructionSetOf(std::string_view word) {
    for (int set : {2, 3})
        if (toLower(word) == instructionSetWord(set))
            return set;
    return 0;
}

std::string canonicalUnitType(std::string_view type) {
    const std::string upper = toUpper(type);
    for (auto known : kUnitTypeWords)
        if (toUpper(known) == upper)
            return std::string(known);
    return {};
}

bool isKnownIoOption(std::string_view option) {
    return std::find(kIoOptionWords.begin(), kIoOptionWords.end(), option) != kIoOptionWords.end();
}

std::string_view compareWord(CompareOp op) {
    return wordOf(kCompareWords, op);
}

std::string_view assignWord(AssignOp op) {
    return wordOf(kAssignWords, op);
}

std::string_view binaryWord(BinaryOp op) {
    return wordOf(kBinaryWords, op);
}

std::optional<CompareOp> compareOpOf(std::string_view word) {
    return valueOf(kCompareWords, word);
}

std::optional<AssignOp> assignOpOf(std::string_view word) {
    return valueOf(kAssignWords, word);
}

} // namespace rs::lang
