// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProgramText.h"

#include "lang/TextCase.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <map>

namespace rs::pl110 {

namespace {

using lang::SourceLocation;

constexpr std::size_t kMaxText = 1 << 20;
constexpr int kMaxDepth = 64;

constexpr std::array<std::string_view, 21> kKeywords{
    "INIT",  "MAIN", "NOT",  "P",     "N",  "SBIT", "RBIT", "TON", "TOFF", "TONR", "MUP",
    "MDOWN", "UP",   "DOWN", "RESET", "MS", "S",    "BIT",  "MOV", "FM",   "IF"};

bool isNameStart(unsigned char c) {
    return std::isalpha(c) || c >= 0x80;
}

bool isNamePart(unsigned char c) {
    return std::isalnum(c) || c == '_' || c == '.' || c >= 0x80;
}

enum class TokenKind { Word, Number, Symbol, End };

struct Token {
    TokenKind kind = TokenKind::End;
    std::string text;
    int column = 0;
};

struct DeclaredName {
    std::string name; // as declared
    Address address;
};

struct LineError {
    int column;
    std::string message;
};

// The tokens of one line without its comment.
std::vector<Token> tokenize(std::string_view code, int firstColumn) {
    std::vector<Token> tokens;
    std::size_t i = 0;
    while (i < code.size()) {
        const auto c = static_cast<unsigned char>(code[i]);
        const int column = firstColumn + static_cast<int>(i);
        if (c == ' ' || c == '\t' || c == '\r') {
            ++i;
        } else if (isNameStart(c)) {
            std::size_t end = i + 1;
            while (end < code.size() && isNamePart(static_cast<unsigned char>(code[end])))
                ++end;
            tokens.push_back({TokenKind::Word, std::string(code.substr(i, end - i)), column});
            i = end;
        } else if (std::isdigit(c)) {
            std::size_t end = i + 1; // digits and a unit: "50", "100ms", "1s"
            while (end < code.size() && std::isalnum(static_cast<unsigned char>(code[end])))
                ++end;
            tokens.push_back({TokenKind::Number, std::string(code.substr(i, end - i)), column});
            i = end;
        } else {
            static constexpr std::array<std::string_view, 5> kPairs{">=", "<=", "<>", "<<", ">>"};
            std::string_view symbol = code.substr(i, 1);
            for (std::string_view pair : kPairs)
                if (code.substr(i, 2) == pair)
                    symbol = pair;
            tokens.push_back({TokenKind::Symbol, std::string(symbol), column});
            i += symbol.size();
        }
    }
    tokens.push_back({TokenKind::End, "", firstColumn + static_cast<int>(code.size())});
    return tokens;
}

// Reads one rung or one declaration from its tokens; throws LineError.
class LineReader {
public:
    LineReader(std::vector<Token> tokens, int line,
               const std::map<std::string, DeclaredName>& names)
        : m_tokens(std::move(tokens)), m_line(line), m_names(names) {}

    // A condition alone, "I1 * /I2", as the ladder inserts it.
    Circuit condition() {
        Circuit circuit = expression(0);
        end();
        return circuit;
    }

    Rung rung() {
        Rung rung;
        rung.output = output();
        if (symbol("=")) {
            ++m_at;
            rung.condition = expression(0);
        }
        end();
        return rung;
    }

    // "I1=Start" after the "!".
    NameDeclaration declaration() {
        NameDeclaration declaration;
        const Token& place = take();
        const AddressReading reading = read(place);
        if (reading.shape != AddressReading::Shape::Address)
            fail(place, "a name declaration starts with an address: ! I1=Start");
        declaration.variable.address = reading.address;
        declaration.variable.location = at(place);
        expect("=");
        const Token& name = take();
        if (name.kind != TokenKind::Word)
            fail(name, "expected a name after '='");
        if (isKeyword(name.text))
            fail(name, "'" + name.text + "' is a keyword of the text form, not a name");
        if (read(name).shape != AddressReading::Shape::NotAnAddress)
            fail(name, "'" + name.text + "' is an address, not a name");
        declaration.name = name.text;
        declaration.nameLocation = at(name);
        end();
        return declaration;
    }

private:
    SourceLocation at(const Token& token) const { return {m_line, token.column}; }

    [[noreturn]] void fail(const Token& token, std::string message) const {
        throw LineError{token.column, std::move(message)};
    }

    const Token& peek(std::size_t ahead = 0) const {
        return m_tokens[std::min(m_at + ahead, m_tokens.size() - 1)];
    }
    const Token& take() {
        const Token& token = peek();
        if (m_at < m_tokens.size() - 1)
            ++m_at;
        return token;
    }
    bool symbol(std::string_view text, std::size_t ahead = 0) const {
        return peek(ahead).kind == TokenKind::Symbol && peek(ahead).text == text;
    }
    bool word(std::string_view keyword, std::size_t ahead = 0) const {
        return peek(ahead).kind == TokenKind::Word && lang::toUpper(peek(ahead).text) == keyword;
    }
    void expect(std::string_view text) {
        if (!symbol(text))
            fail(peek(), describe(peek()) + " where '" + std::string(text) + "' belongs");
        ++m_at;
    }
    void end() {
        if (peek().kind != TokenKind::End)
            fail(peek(), "unexpected " + describe(peek()));
    }
    static std::string describe(const Token& token) {
        return token.kind == TokenKind::End ? std::string("end of line") : "'" + token.text + "'";
    }

    static AddressReading read(const Token& token) {
        return token.kind == TokenKind::Word ? readAddress(token.text) : AddressReading{};
    }

    // An address or a declared name; `word` reads a timer or counter as its value.
    Operand operand(bool wordWanted) {
        const Token& token = take();
        if (token.kind != TokenKind::Word)
            fail(token, "expected an address or a name, found " + describe(token));
        Operand operand;
        operand.location = at(token);
        const AddressReading reading = read(token);
        if (reading.shape == AddressReading::Shape::Malformed)
            fail(token, reading.error);
        if (reading.shape == AddressReading::Shape::Address) {
            operand.address = reading.address;
        } else {
            if (isKeyword(token.text))
                fail(token, "'" + token.text + "' cannot stand here");
            // Names are case-insensitive, as the rest of the text; the tree
            // keeps the declared spelling, which the canonical text prints.
            const auto found = m_names.find(lang::toUpper(token.text));
            if (found == m_names.end())
                fail(token, "'" + token.text + "' is neither an address nor a declared name");
            operand.name = found->second.name;
            operand.address = found->second.address;
        }
        if (wordWanted)
            operand.address = asWord(operand.address);
        return operand;
    }

    Value value() {
        Value value;
        value.location = at(peek());
        const bool hash = symbol("#"); // the datasheet writes constants as #0
        if (hash)
            ++m_at;
        const bool minus = symbol("-");
        if (minus)
            ++m_at;
        if (peek().kind == TokenKind::Number) {
            const Token& token = take();
            if (!std::all_of(token.text.begin(), token.text.end(),
                             [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
                fail(token, "'" + token.text + "' is not a number");
            std::int64_t number = 0;
            for (char c : token.text) {
                number = number * 10 + (c - '0');
                if (number > 2147483648LL)
                    fail(token, "the constant is out of range: -2147483648-2147483647");
            }
            if (minus)
                number = -number;
            if (number > 2147483647LL)
                fail(token, "the constant is out of range: -2147483648-2147483647");
            value.constant = static_cast<std::int32_t>(number);
            return value;
        }
        if (hash || minus)
            fail(peek(), "expected a number, found " + describe(peek()));
        value.operand = operand(true);
        return value;
    }

    Output output() {
        Output out;
        if (symbol("(")) {
            ++m_at;
            out.target = operand(true);
            expect("=");
            out.left = value();
            static constexpr std::array<std::pair<std::string_view, FormulaOp>, 9> kOps{{
                {"+", FormulaOp::Add},
                {"-", FormulaOp::Sub},
                {"*", FormulaOp::Mul},
                {"/", FormulaOp::Div},
                {"|", FormulaOp::Or},
                {"&", FormulaOp::And},
                {"^", FormulaOp::Xor},
                {"<<", FormulaOp::ShiftLeft},
                {">>", FormulaOp::ShiftRight},
            }};
            out.kind = OutputKind::Move;
            for (const auto& [text, op] : kOps) {
                if (symbol(text)) {
                    ++m_at;
                    out.kind = OutputKind::Formula;
                    out.formula = op;
                    out.right = value();
                    break;
                }
            }
            expect(")");
            return out;
        }
        const Token& head = peek();
        const std::string keyword = lang::toUpper(head.text);
        if (head.kind == TokenKind::Word && symbol("(", 1)) {
            if (keyword == "SBIT" || keyword == "RBIT") {
                m_at += 2;
                out.kind = keyword == "SBIT" ? OutputKind::SetBit : OutputKind::ResetBit;
                out.target = operand(false);
                expect(")");
                return out;
            }
            if (keyword == "TON" || keyword == "TOFF" || keyword == "TONR") {
                m_at += 2;
                out.kind = OutputKind::Timer;
                out.timer = keyword == "TON"    ? TimerType::OnDelay
                            : keyword == "TOFF" ? TimerType::OffDelay
                                                : TimerType::Retentive;
                out.target = operand(false);
                expect(",");
                const Token& base = take();
                const std::string text = lang::toUpper(base.text);
                if (text == "10MS")
                    out.base = TimeBase::Ms10;
                else if (text == "100MS")
                    out.base = TimeBase::Ms100;
                else if (text == "1S")
                    out.base = TimeBase::S1;
                else
                    fail(base, "the time base is 10ms, 100ms or 1s, not " + describe(base));
                expect(",");
                out.preset = value();
                expect(")");
                return out;
            }
            if (keyword == "MUP" || keyword == "MDOWN") {
                m_at += 2;
                out.kind = OutputKind::Counter;
                out.counter = keyword == "MUP" ? CounterType::Up : CounterType::Down;
                out.target = operand(false);
                expect(",");
                const Token& input = take();
                const std::string text = lang::toUpper(input.text);
                if (text == "UP")
                    out.input = CounterInput::Up;
                else if (text == "DOWN")
                    out.input = CounterInput::Down;
                else if (text == "RESET")
                    out.input = CounterInput::Reset;
                else
                    fail(input, "a counter's input is UP, DOWN or RESET, not " + describe(input));
                expect(",");
                out.preset = value();
                expect(")");
                return out;
            }
        }
        out.kind = OutputKind::Coil;
        out.target = operand(false);
        return out;
    }

    Circuit element(Element element, const Token& token) {
        Circuit circuit = Circuit::of(std::move(element));
        circuit.location = at(token);
        return circuit;
    }

    Circuit expression(int depth) {
        if (depth > kMaxDepth)
            fail(peek(), "the condition nests more than 64 groups deep");
        std::vector<Circuit> terms{term(depth)};
        while (symbol("+")) {
            ++m_at;
            terms.push_back(term(depth));
        }
        return Circuit::parallel(std::move(terms));
    }

    Circuit term(int depth) {
        std::vector<Circuit> factors{factor(depth)};
        while (symbol("*")) {
            ++m_at;
            factors.push_back(factor(depth));
        }
        return Circuit::series(std::move(factors));
    }

    static std::optional<CompareOp> compareOp(const Token& token) {
        static constexpr std::array<std::pair<std::string_view, CompareOp>, 6> kOps{{
            {"=", CompareOp::Equal},
            {"<>", CompareOp::NotEqual},
            {">", CompareOp::Greater},
            {"<", CompareOp::Less},
            {">=", CompareOp::GreaterEqual},
            {"<=", CompareOp::LessEqual},
        }};
        if (token.kind == TokenKind::Symbol)
            for (const auto& [text, op] : kOps)
                if (token.text == text)
                    return op;
        return std::nullopt;
    }

    // Whether the group opening at the current "(" is an IF comparison: a value,
    // then a comparison operator.
    bool comparisonAhead() const {
        std::size_t ahead = 1;
        if (symbol("#", ahead))
            ++ahead;
        if (symbol("-", ahead))
            ++ahead;
        const Token& first = peek(ahead);
        if (first.kind != TokenKind::Word && first.kind != TokenKind::Number)
            return false;
        return compareOp(peek(ahead + 1)).has_value();
    }

    Circuit factor(int depth) {
        const Token& token = peek();
        if (symbol("/")) {
            ++m_at;
            if (peek().kind != TokenKind::Word || isKeyword(peek().text))
                fail(peek(), "negation applies to one contact: /I1");
            Element contact{ElementKind::NormallyClosed, operand(false), {}, {}, {}};
            return element(std::move(contact), token);
        }
        if (symbol("(")) {
            if (comparisonAhead()) {
                ++m_at;
                Element compare;
                compare.kind = ElementKind::Compare;
                compare.left = value();
                compare.compare = *compareOp(take());
                compare.right = value();
                expect(")");
                return element(std::move(compare), token);
            }
            ++m_at;
            Circuit group = expression(depth + 1);
            expect(")");
            return group;
        }
        if (token.kind == TokenKind::Word) {
            const std::string keyword = lang::toUpper(token.text);
            if (keyword == "NOT" || keyword == "P" || keyword == "N") {
                ++m_at;
                Element flow;
                flow.kind = keyword == "NOT" ? ElementKind::Not
                            : keyword == "P" ? ElementKind::RisingEdge
                                             : ElementKind::FallingEdge;
                return element(std::move(flow), token);
            }
            Element contact{ElementKind::NormallyOpen, operand(false), {}, {}, {}};
            return element(std::move(contact), token);
        }
        fail(token, "expected a contact, found " + describe(token));
    }

    std::vector<Token> m_tokens;
    std::size_t m_at = 0;
    int m_line;
    const std::map<std::string, DeclaredName>& m_names; // by the name in upper case
};

// The code and the comment of a line: ';' starts a comment.
struct SplitLine {
    std::string_view code;
    std::optional<std::string> comment;
};

SplitLine split(std::string_view text) {
    SplitLine line;
    const std::size_t semicolon = text.find(';');
    line.code = text.substr(0, semicolon);
    if (semicolon != std::string_view::npos) {
        std::string comment(text.substr(semicolon + 1));
        while (!comment.empty() &&
               (comment.back() == ' ' || comment.back() == '\t' || comment.back() == '\r'))
            comment.pop_back();
        line.comment = std::move(comment);
    }
    return line;
}

std::string_view trimmed(std::string_view text) {
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t'))
        text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r'))
        text.remove_suffix(1);
    return text;
}

struct Directive {
    std::string keyword; // upper case
    std::string_view argument;
};

// "$name Press line" without its comment.
Directive readDirective(std::string_view code) {
    const std::string_view directive = code.substr(1);
    const std::size_t space = directive.find_first_of(" \t");
    return {lang::toUpper(directive.substr(0, space)), space == std::string_view::npos
                                                           ? std::string_view{}
                                                           : trimmed(directive.substr(space))};
}

} // namespace

bool isKeyword(std::string_view word) {
    const std::string text = lang::toUpper(word);
    return std::find(kKeywords.begin(), kKeywords.end(), text) != kKeywords.end();
}

bool isPl110Text(std::string_view text) {
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos)
            end = text.size();
        const std::string_view line = trimmed(split(text.substr(start, end - start)).code);
        if (!line.empty()) {
            if (line.front() != '$')
                return false;
            const Directive directive = readDirective(line);
            return directive.keyword == "TARGET" && lang::toUpper(directive.argument) == "PL110";
        }
        start = end + 1;
    }
    return false;
}

ProgramReading readProgram(std::string_view text) {
    ProgramReading reading;
    Program& program = reading.program;
    auto error = [&](int line, int column, std::string message) {
        reading.diagnostics.push_back({lang::Severity::Error, line, column, std::move(message)});
    };
    if (text.size() > kMaxText) {
        error(1, 1, "the file is larger than 1 MB, the limit of a PL110 program");
        return reading;
    }
    std::map<std::string, DeclaredName> names;
    std::map<Address, std::string> namedAddresses;
    enum class Part { Declarations, Init, Main } part = Part::Declarations;
    bool targetSeen = false;
    int number = 0;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos)
            end = text.size();
        const std::string_view raw = text.substr(start, end - start);
        const bool last = end == text.size();
        start = end + 1;
        ++number;
        if (last && raw.empty())
            break;
        const SplitLine split = ::rs::pl110::split(raw);
        const std::string_view code = trimmed(split.code);
        const int column = static_cast<int>(code.data() - raw.data()) + 1;
        std::vector<Line>& lines = part == Part::Declarations ? program.declarations
                                   : part == Part::Init       ? program.init
                                                              : program.main;
        Line line;
        line.location = {number, column};
        line.comment = split.comment;
        if (code.empty()) {
            if (split.comment)
                line.body = CommentLine{*split.comment};
            line.comment.reset();
            lines.push_back(std::move(line));
            continue;
        }
        if (code.front() == '$') {
            const Directive directive = readDirective(code);
            if (part != Part::Declarations) {
                error(number, column, "directives come before INIT");
            } else if (directive.keyword == "TARGET") {
                if (lang::toUpper(directive.argument) != "PL110")
                    error(number, column,
                          "this file's target is PL110, not '" + std::string(directive.argument) +
                              "'");
                targetSeen = true;
            } else if (directive.keyword == "NAME") {
                // The name is text to the end of the line, ';' included.
                program.name = std::string(readDirective(trimmed(raw)).argument);
            } else {
                error(number, column,
                      "unknown directive '$" + directive.keyword + "': $target or $name");
            }
            continue;
        }
        const std::string word = lang::toUpper(code);
        if (word == "INIT" || word == "MAIN") {
            const Part next = word == "INIT" ? Part::Init : Part::Main;
            if (next == Part::Init && part != Part::Declarations)
                error(number, column, "INIT comes once, before MAIN");
            else if (next == Part::Main && part == Part::Main)
                error(number, column, "MAIN comes once");
            else
                part = next;
            continue;
        }
        try {
            if (code.front() == '!') {
                if (part != Part::Declarations)
                    throw LineError{column, "declarations come before INIT"};
                LineReader reader(tokenize(code.substr(1), column + 1), number, names);
                NameDeclaration declaration = reader.declaration();
                const std::string key = lang::toUpper(declaration.name);
                if (names.contains(key))
                    throw LineError{declaration.nameLocation.column,
                                    "'" + declaration.name + "' is declared twice"};
                if (namedAddresses.contains(declaration.variable.address))
                    throw LineError{column + 1, toString(declaration.variable.address) +
                                                    " already has the name '" +
                                                    namedAddresses[declaration.variable.address] +
                                                    "'"};
                names[key] = {declaration.name, declaration.variable.address};
                namedAddresses[declaration.variable.address] = declaration.name;
                line.body = std::move(declaration);
            } else {
                if (part == Part::Declarations)
                    throw LineError{column, "a rung stands after INIT or MAIN"};
                LineReader reader(tokenize(code, column), number, names);
                line.body = reader.rung();
            }
            lines.push_back(std::move(line));
        } catch (const LineError& bad) {
            error(number, bad.column, bad.message);
        }
    }
    if (!targetSeen)
        error(1, 1, "a PL110 program starts with \"$target PL110\"");
    return reading;
}

namespace {

std::map<std::string, DeclaredName> declaredNames(const Program& program) {
    std::map<std::string, DeclaredName> names;
    for (const Line& line : program.declarations)
        if (const auto* declaration = std::get_if<NameDeclaration>(&line.body))
            names[lang::toUpper(declaration->name)] = {declaration->name,
                                                       declaration->variable.address};
    return names;
}

} // namespace

RungReading readRung(const Program& program, std::string_view text) {
    RungReading reading;
    const std::map<std::string, DeclaredName> names = declaredNames(program);
    const SplitLine split = ::rs::pl110::split(text);
    const std::string_view code = trimmed(split.code);
    const int column = static_cast<int>(code.data() - text.data()) + 1;
    try {
        if (code.empty())
            throw LineError{1, "a rung is an output, '=' and its condition: Q1 = I1 * /I2"};
        if (text.find('\n') != std::string_view::npos)
            throw LineError{column, "a rung is one line"};
        LineReader reader(tokenize(code, column), 1, names);
        Line line;
        line.body = reader.rung();
        line.comment = split.comment;
        line.location = {1, column};
        reading.line = std::move(line);
    } catch (const LineError& bad) {
        reading.diagnostics.push_back({lang::Severity::Error, 1, bad.column, bad.message});
    }
    return reading;
}

ConditionReading readCondition(const Program& program, std::string_view text) {
    ConditionReading reading;
    try {
        if (text.find_first_of("\n;") != std::string_view::npos)
            throw LineError{static_cast<int>(text.find_first_of("\n;")) + 1,
                            "a condition is one line without a comment"};
        const std::string_view code = trimmed(text);
        const int column = static_cast<int>(code.data() - text.data()) + 1;
        if (code.empty())
            throw LineError{1, "write a contact such as I3 or /I3, a comparison such as "
                               "(VW1 >= 10), NOT, P or N"};
        const std::map<std::string, DeclaredName> names = declaredNames(program);
        LineReader reader(tokenize(code, column), 1, names); // keeps a reference to the names
        reading.circuit = reader.condition();
    } catch (const LineError& bad) {
        reading.diagnostics.push_back({lang::Severity::Error, 1, bad.column, bad.message});
    }
    return reading;
}

} // namespace rs::pl110
