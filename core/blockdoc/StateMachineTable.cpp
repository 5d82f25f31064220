// SPDX-License-Identifier: GPL-3.0-or-later
#include "StateMachineTable.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <optional>

namespace rs::blockdoc {

namespace {

constexpr std::string_view kState = "{#state}";
constexpr std::string_view kNext = "{#next}";

std::optional<int> integer(std::string_view text) {
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size())
        return std::nullopt;
    return value;
}

int codeOf(int value) {
    return value & 0xFFFF;
}

int signedOf(int code) {
    return code >= 0x8000 ? code - 0x10000 : code;
}

struct StateTest {
    std::string_view op;
    int value = 0;

    bool holds(int code) const {
        const int v = signedOf(code);
        if (op == "=")
            return v == value;
        if (op == "<")
            return v < value;
        if (op == ">")
            return v > value;
        if (op == "<=")
            return v <= value;
        return v >= value;
    }
};

// `({#state}=-32767)`, `({#state}<0)`: a comparison of the state with a number.
std::optional<StateTest> stateTest(std::string_view term) {
    if (term.size() < kState.size() + 3 || term.front() != '(' || term.back() != ')')
        return std::nullopt;
    term = term.substr(1, term.size() - 2);
    if (term.substr(0, kState.size()) != kState)
        return std::nullopt;
    term.remove_prefix(kState.size());
    std::size_t opLength = 0;
    while (opLength < term.size() &&
           (term[opLength] == '=' || term[opLength] == '<' || term[opLength] == '>'))
        ++opLength;
    const std::string_view op = term.substr(0, opLength);
    if (op != "=" && op != "<" && op != ">" && op != "<=" && op != ">=")
        return std::nullopt;
    const std::optional<int> value = integer(term.substr(opLength));
    if (!value)
        return std::nullopt;
    return StateTest{op, *value};
}

// The index of the parenthesis that closes the one at `open`, or npos.
std::size_t closing(std::string_view text, std::size_t open) {
    int depth = 0;
    for (std::size_t i = open; i < text.size(); ++i) {
        if (text[i] == '(')
            ++depth;
        else if (text[i] == ')' && --depth == 0)
            return i;
    }
    return std::string_view::npos;
}

// Splits at a separator standing outside every parenthesis.
std::vector<std::string_view> splitTopLevel(std::string_view text, std::string_view separator) {
    std::vector<std::string_view> parts;
    int depth = 0;
    std::size_t start = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '(')
            ++depth;
        else if (text[i] == ')')
            --depth;
        else if (depth == 0 && text.substr(i, separator.size()) == separator) {
            parts.push_back(text.substr(start, i - start));
            start = i + separator.size();
            i = start - 1;
        }
    }
    parts.push_back(text.substr(start));
    return parts;
}

// The states a sum of equality tests names; nothing when a term is another thing.
std::optional<std::vector<int>> namedStates(std::string_view sum) {
    std::vector<int> codes;
    for (const std::string_view term : splitTopLevel(sum, " + ")) {
        const std::optional<StateTest> test = stateTest(term);
        if (!test || test->op != "=")
            return std::nullopt;
        codes.push_back(codeOf(test->value));
    }
    return codes;
}

// A transition's condition: the states it leaves (a leading factor that
// names them), then what else must hold.
Transition transitionOf(std::string_view condition, int to) {
    Transition transition;
    transition.to = to;
    if (!condition.empty() && condition.front() == '(') {
        const std::size_t close = closing(condition, 0);
        if (close != std::string_view::npos) {
            const std::string_view first = condition.substr(0, close + 1);
            std::optional<std::vector<int>> from = namedStates(first);
            if (!from && first.size() > 2)
                from = namedStates(first.substr(1, first.size() - 2));
            const std::string_view rest = condition.substr(close + 1);
            if (from && (rest.empty() || rest.substr(0, 3) == " * ")) {
                transition.from = *from;
                transition.condition = readable(rest.empty() ? rest : rest.substr(3));
                return transition;
            }
        }
    }
    transition.condition = readable(condition);
    return transition;
}

// `{Name}` -> the pin named so, when it is a bit output.
const blocks::Pin* bitOutput(const blocks::BlockDefinition& block, std::string_view operand) {
    if (operand.size() < 3 || operand.front() != '{' || operand.back() != '}' || operand[1] == '#')
        return nullptr;
    const blocks::Pin* pin = block.findPin(operand.substr(1, operand.size() - 2));
    return pin && pin->direction == blocks::PinDirection::Out && pin->kind == blocks::PinKind::Bit
               ? pin
               : nullptr;
}

void addState(std::vector<int>& states, int code) {
    if (std::find(states.begin(), states.end(), code) == states.end())
        states.push_back(code);
}

} // namespace

std::vector<const Transition*> StateMachineTable::transitionsFrom(int state) const {
    std::vector<const Transition*> list;
    for (const Transition& t : transitions)
        if (t.from.empty() || std::find(t.from.begin(), t.from.end(), state) != t.from.end())
            list.push_back(&t);
    std::stable_partition(list.begin(), list.end(),
                          [](const Transition* t) { return t->from.empty(); });
    return list;
}

std::string stateCode(int code) {
    char text[8];
    std::snprintf(text, sizeof text, "16#%04X", static_cast<unsigned>(codeOf(code)));
    return text;
}

std::string readable(std::string_view bodyText) {
    std::string out;
    for (std::size_t i = 0; i < bodyText.size(); ++i) {
        if (bodyText[i] == '(') {
            const std::size_t close = bodyText.find(')', i);
            if (close != std::string_view::npos) {
                const std::optional<StateTest> test = stateTest(bodyText.substr(i, close - i + 1));
                if (test) {
                    out +=
                        "(state" + std::string(test->op) +
                        (test->op == "=" ? stateCode(test->value) : std::to_string(test->value)) +
                        ")";
                    i = close;
                    continue;
                }
            }
        }
        if (bodyText[i] == '{') {
            const std::size_t close = bodyText.find('}', i);
            if (close != std::string_view::npos) {
                std::string_view name = bodyText.substr(i + 1, close - i - 1);
                if (!name.empty() && name.front() == '#')
                    name.remove_prefix(1);
                out += name;
                i = close;
                continue;
            }
        }
        out += bodyText[i];
    }
    return out;
}

StateMachineTable stateMachineOf(const blocks::BlockDefinition& block) {
    StateMachineTable table;
    if (block.kind != blocks::BlockKind::Macro || !block.findPrivate("state") ||
        !block.findPrivate("next"))
        return table;
    for (const blocks::StateMeaning& state : block.states)
        addState(table.states, state.code);

    struct OutputLine {
        std::string pin;
        std::vector<StateTest> tests;
    };
    std::vector<OutputLine> outputLines;
    const std::string nextPrefix = "(" + std::string(kNext) + " = ";
    for (const std::string& line : block.body) {
        const std::string_view text = line;
        if (text.empty() || text.front() == ';')
            continue;
        if (text == "(" + std::string(kNext) + " = " + std::string(kState) + ")" ||
            text == "(" + std::string(kState) + " = " + std::string(kNext) + ")")
            continue;
        if (text == "({DiagCode} = " + std::string(kState) + ")") {
            table.diagCodeIsState = true;
            continue;
        }
        const std::vector<std::string_view> sides = splitTopLevel(text, " = ");
        if (sides.size() == 2 && sides[0].substr(0, nextPrefix.size()) == nextPrefix &&
            sides[0].back() == ')') {
            const std::string_view target =
                sides[0].substr(nextPrefix.size(), sides[0].size() - nextPrefix.size() - 1);
            if (const std::optional<int> to = integer(target)) {
                table.transitions.push_back(transitionOf(sides[1], codeOf(*to)));
                continue;
            }
        }
        if (sides.size() == 2) {
            if (const blocks::Pin* pin = bitOutput(block, sides[0])) {
                OutputLine output{pin->name, {}};
                bool fromState = true;
                for (const std::string_view term : splitTopLevel(sides[1], " + ")) {
                    const std::optional<StateTest> test = stateTest(term);
                    if (!test) {
                        fromState = false;
                        break;
                    }
                    output.tests.push_back(*test);
                }
                if (fromState) {
                    outputLines.push_back(std::move(output));
                    continue;
                }
            }
            table.definitions.push_back({readable(sides[0]), readable(sides[1])});
            continue;
        }
        table.definitions.push_back({{}, readable(text)});
    }
    // Each state's list is written last-first so that the first true line of
    // the list is the last to write `next`: read back, they are tried in turn.
    std::reverse(table.transitions.begin(), table.transitions.end());
    if (table.transitions.empty())
        return {};
    for (const Transition& t : table.transitions) {
        for (const int code : t.from)
            addState(table.states, code);
        addState(table.states, t.to);
    }
    for (const OutputLine& output : outputLines)
        table.outputs.push_back(output.pin);
    for (const int code : table.states) {
        std::vector<bool> on;
        for (const OutputLine& output : outputLines)
            on.push_back(std::any_of(output.tests.begin(), output.tests.end(),
                                     [code](const StateTest& test) { return test.holds(code); }));
        table.outputsOn.push_back(std::move(on));
    }
    return table;
}

} // namespace rs::blockdoc
