// SPDX-License-Identifier: GPL-3.0-or-later
#include "PropertyFile.h"

#include "project/Utf8Text.h"
#include "sim/Scenario.h"

#include <cctype>
#include <charconv>
#include <optional>

namespace rs::prove {

namespace {

bool isOperandCharacter(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' ||
           (static_cast<unsigned char>(c) & 0x80);
}

constexpr int kMaxNesting = 64;

Condition node(Condition::Kind kind, int column) {
    Condition condition;
    condition.kind = kind;
    condition.column = column;
    return condition;
}

// Reads one line's condition(s): a recursive descent over the language's
// operators, `*` before `+`, `/` on what follows it.
class ConditionReader {
public:
    ConditionReader(std::string_view line, std::size_t at, const sim::OperandNames& names)
        : m_line(line), m_at(at), m_names(names) {}

    bool failed() const { return !m_error.empty(); }
    const std::string& error() const { return m_error; }
    std::size_t errorOffset() const { return m_errorAt; }
    std::size_t offset() const { return m_at; }
    void rewind(std::size_t at) { m_at = at; }

    void skipSpace() {
        while (m_at < m_line.size() && (m_line[m_at] == ' ' || m_line[m_at] == '\t'))
            ++m_at;
    }
    bool atEnd() {
        skipSpace();
        return m_at >= m_line.size();
    }
    bool take(std::string_view token) {
        skipSpace();
        if (m_line.substr(m_at, token.size()) != token)
            return false;
        m_at += token.size();
        return true;
    }
    std::string_view word() {
        skipSpace();
        const std::size_t start = m_at;
        while (m_at < m_line.size() && isOperandCharacter(m_line[m_at]))
            ++m_at;
        return m_line.substr(start, m_at - start);
    }
    void fail(std::size_t at, std::string message) {
        if (m_error.empty()) {
            m_error = std::move(message);
            m_errorAt = at;
        }
    }

    Condition disjunction() {
        Condition first = conjunction();
        if (!take("+") || failed())
            return first;
        Condition any = node(Condition::Kind::Or, first.column);
        any.children.push_back(std::move(first));
        do
            any.children.push_back(conjunction());
        while (!failed() && take("+"));
        return any;
    }

private:
    Condition conjunction() {
        Condition first = primary();
        if (!take("*") || failed())
            return first;
        Condition all = node(Condition::Kind::And, first.column);
        all.children.push_back(std::move(first));
        do
            all.children.push_back(primary());
        while (!failed() && take("*"));
        return all;
    }

    Condition primary() {
        skipSpace();
        const std::size_t start = m_at;
        // Each level is a call: a line of ten thousand '(' must not end the stack.
        if (++m_depth > kMaxNesting) {
            fail(start, "a condition nests at most " + std::to_string(kMaxNesting) +
                            " parentheses and negations deep");
            --m_depth;
            return node(Condition::Kind::Bit, column(start));
        }
        Condition result = nested(start);
        --m_depth;
        return result;
    }

    Condition nested(std::size_t start) {
        if (take("/")) {
            Condition negation = node(Condition::Kind::Not, column(start));
            negation.children.push_back(primary());
            return negation;
        }
        if (take("(")) {
            Condition inner = disjunction();
            if (!failed() && !take(")"))
                fail(m_at, "expected ')'");
            return inner;
        }
        return atom();
    }

    Condition atom() {
        skipSpace();
        const std::size_t start = m_at;
        const std::string_view text = word();
        Condition atom = node(Condition::Kind::Bit, column(start));
        if (text.empty()) {
            fail(start, m_at < m_line.size()
                            ? "expected an operand, found '" + std::string(1, m_line[m_at]) + "'"
                            : "expected an operand at the end of the line");
            return atom;
        }
        if (!resolve(text, start, atom.operand))
            return atom;
        const auto op = comparison();
        if (!op) {
            if (atom.operand.kind == lang::AddressKind::Sequence)
                fail(start, "a sequence's active step is a number: compare it, as in " +
                                std::string(text) + " = 2");
            else if (!atom.operand.isBit())
                fail(start, "'" + std::string(text) + "' is a number: compare it, as in (" +
                                std::string(text) + ">=1)");
            return atom;
        }
        atom.kind = Condition::Kind::Compare;
        atom.op = *op;
        if (atom.operand.kind != lang::AddressKind::Sequence && !atom.operand.isWord()) {
            fail(start, "'" + std::string(text) + "' is a bit and cannot be compared");
            return atom;
        }
        skipSpace();
        const std::size_t valueAt = m_at;
        std::size_t end = m_at;
        if (end < m_line.size() && (m_line[end] == '-' || m_line[end] == '+'))
            ++end;
        while (end < m_line.size() && std::isdigit(static_cast<unsigned char>(m_line[end])))
            ++end;
        if (end > valueAt && std::isdigit(static_cast<unsigned char>(m_line[end - 1])) &&
            (end == m_line.size() || !isOperandCharacter(m_line[end]))) {
            std::string_view number = m_line.substr(valueAt, end - valueAt);
            if (number.front() == '+')
                number.remove_prefix(1);
            const auto [ptr, error] =
                std::from_chars(number.data(), number.data() + number.size(), atom.constant);
            if (error != std::errc() || atom.constant < -2147483648LL ||
                atom.constant > 2147483647LL) {
                fail(valueAt, "the number '" + std::string(number) + "' is out of range");
                return atom;
            }
            m_at = end;
            return atom;
        }
        const std::string_view right = word();
        if (right.empty()) {
            fail(valueAt, "expected a number or an operand to compare with");
            return atom;
        }
        atom.rightIsConstant = false;
        if (!resolve(right, valueAt, atom.right))
            return atom;
        if (!atom.right.isWord() || atom.operand.kind == lang::AddressKind::Sequence)
            fail(valueAt, "'" + std::string(right) + "' cannot be compared here: compare a " +
                              "number with a number");
        return atom;
    }

    std::optional<lang::CompareOp> comparison() {
        if (take(">="))
            return lang::CompareOp::GreaterEqual;
        if (take("<="))
            return lang::CompareOp::LessEqual;
        skipSpace();
        if (m_line.substr(m_at, 2) == "->")
            return std::nullopt;
        if (take("="))
            return lang::CompareOp::Equal;
        if (take(">"))
            return lang::CompareOp::Greater;
        if (take("<"))
            return lang::CompareOp::Less;
        return std::nullopt;
    }

    bool resolve(std::string_view text, std::size_t at, lang::Address& address) {
        const lang::AddressWord read = lang::readAddressWord(text);
        if (read.shape == lang::AddressWord::Shape::Variable &&
            read.address.kind == lang::AddressKind::Sequence) {
            address = read.address;
        } else {
            std::string error;
            if (!m_names.resolve(text, address, error)) {
                fail(at, error);
                return false;
            }
        }
        if (!m_names.hasStation(address.unit)) {
            fail(at, "'" + std::string(text) + "' is in unit " + std::to_string(address.unit) +
                         ", which is not in the project");
            return false;
        }
        if (address.kind == lang::AddressKind::Sequence &&
            !m_names.hasSequence(address.unit, address.index)) {
            fail(at, "unit " + std::to_string(address.unit) + " has no sequence " +
                         std::to_string(address.index));
            return false;
        }
        return true;
    }

    int column(std::size_t offset) const { return project::characterColumn(m_line, offset); }

    std::string_view m_line;
    std::size_t m_at;
    const sim::OperandNames& m_names;
    std::string m_error;
    std::size_t m_errorAt = 0;
    int m_depth = 0;
};

std::string_view withoutComment(std::string_view line) {
    const std::size_t end = line.find_first_of(";#");
    line = line.substr(0, end);
    while (!line.empty() && (line.back() == ' ' || line.back() == '\t'))
        line.remove_suffix(1);
    return line;
}

} // namespace

void collectOperands(const Condition& condition, std::vector<lang::Address>& into) {
    if (condition.kind == Condition::Kind::Bit || condition.kind == Condition::Kind::Compare)
        into.push_back(condition.operand);
    if (condition.kind == Condition::Kind::Compare && !condition.rightIsConstant)
        into.push_back(condition.right);
    for (const Condition& child : condition.children)
        collectOperands(child, into);
}

PropertyFile parseProperties(std::string_view text, const sim::OperandNames& names) {
    PropertyFile file;
    if (text.substr(0, 3) == "\xEF\xBB\xBF")
        text.remove_prefix(3);
    if (const auto fault = project::findTextFault(text)) {
        int line = 1;
        std::size_t lineStart = 0;
        for (std::size_t i = 0; i < fault->offset; ++i)
            if (text[i] == '\n') {
                ++line;
                lineStart = i + 1;
            }
        file.diagnostics.push_back(
            {lang::Severity::Error, line,
             project::characterColumn(text.substr(lineStart), fault->offset - lineStart),
             fault->message});
        return file;
    }
    bool proved = false; // a property seen: `cycle` may no longer change
    int lineNumber = 0;
    std::size_t pos = 0;
    while (pos <= text.size()) {
        std::size_t end = text.find_first_of("\r\n", pos);
        if (end == std::string_view::npos)
            end = text.size();
        const std::string_view raw = text.substr(pos, end - pos);
        pos = end + ((end + 1 < text.size() && text[end] == '\r' && text[end + 1] == '\n') ? 2 : 1);
        ++lineNumber;
        const std::string_view line = withoutComment(raw);
        ConditionReader reader(line, 0, names);
        if (reader.atEnd())
            continue;
        auto fail = [&](std::size_t at, const std::string& message) {
            file.diagnostics.push_back(
                {lang::Severity::Error, lineNumber, project::characterColumn(line, at), message});
        };
        const std::size_t verbAt = reader.offset();
        const std::string verb = [&] {
            std::string word(reader.word());
            for (char& c : word)
                c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            return word;
        }();
        Property property;
        property.line = lineNumber;
        property.text = std::string(line.substr(verbAt));
        if (verb == "cycle") {
            reader.skipSpace();
            const std::size_t at = reader.offset();
            const std::string_view duration = line.substr(at);
            std::int64_t ms = 0;
            if (!sim::parseDuration(duration, ms) || ms < sim::kMinCycleMs || ms > sim::kMaxCycleMs)
                fail(at, "expected a cycle time from 1ms to 10s, found '" + std::string(duration) +
                             "'");
            else if (proved)
                fail(verbAt, "cycle must come before the first property");
            else
                file.cycleMs = static_cast<int>(ms);
            continue;
        }
        if (verb == "always")
            property.kind = Property::Kind::Always;
        else if (verb == "never")
            property.kind = Property::Kind::Never;
        else if (verb == "assume")
            property.kind = Property::Kind::Assume;
        else if (verb == "cover")
            property.kind = Property::Kind::Cover;
        else {
            fail(verbAt, "expected always, never, assume, cover or cycle, found '" +
                             std::string(line.substr(verbAt, reader.offset() - verbAt)) + "'");
            continue;
        }
        property.first = reader.disjunction();
        if (!reader.failed() && property.kind == Property::Kind::Always && reader.take("->")) {
            property.kind = Property::Kind::Implies;
            const std::size_t save = reader.offset();
            const std::string_view keyword = reader.word();
            if (keyword == "within") {
                property.kind = Property::Kind::Within;
                reader.skipSpace();
                const std::size_t at = reader.offset();
                const std::string_view duration = reader.word();
                if (!sim::parseDuration(duration, property.durationMs) ||
                    property.durationMs > sim::kMaxVirtualMs)
                    reader.fail(at, "expected a duration such as 20ms after within, found '" +
                                        std::string(duration) + "'");
            } else if (keyword == "next") {
                property.kind = Property::Kind::Next;
            } else {
                reader.rewind(save);
            }
            if (!reader.failed())
                property.second = reader.disjunction();
        }
        if (!reader.failed() && !reader.atEnd())
            reader.fail(reader.offset(), "unexpected '" +
                                             std::string(line.substr(reader.offset())) +
                                             "' after the condition");
        if (reader.failed()) {
            fail(reader.errorOffset(), reader.error());
            continue;
        }
        if (property.kind != Property::Kind::Assume)
            proved = true;
        file.properties.push_back(std::move(property));
    }
    if (file.diagnostics.empty() && !proved)
        file.diagnostics.push_back(
            {lang::Severity::Error, 1, 1, "the file has no property to prove or cover"});
    for (const Property& property : file.properties)
        if (property.kind == Property::Kind::Within && property.durationMs % file.cycleMs != 0)
            file.diagnostics.push_back(
                {lang::Severity::Warning, property.line, 1,
                 "the duration is not a whole number of " + std::to_string(file.cycleMs) +
                     " ms cycles: it counts as " +
                     std::to_string(windowScans(property, file.cycleMs)) + " scans"});
    return file;
}

} // namespace rs::prove
