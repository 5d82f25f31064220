// SPDX-License-Identifier: GPL-3.0-or-later
#include "Parser.h"

#include "Keywords.h"
#include "Lexer.h"
#include "TextCase.h"

#include <algorithm>
#include <array>
#include <iterator>
#include <utility>

namespace rs::lang {

namespace {

// "A16 A20 ... B42_ASi": the unit types as a message lists them.
std::string unitTypeList() {
    std::string list;
    for (auto word : kUnitTypeWords)
        list += (list.empty() ? "" : " ") + std::string(word);
    return list;
}

// "a_pulse, b_pulse, ... counter_up or counter_updown".
std::string ioOptionList() {
    std::string list;
    for (std::size_t i = 0; i < kIoOptionWords.size(); ++i)
        list += (i == 0                           ? ""
                 : i + 1 == kIoOptionWords.size() ? " or "
                                                  : ", ") +
                std::string(kIoOptionWords[i]);
    return list;
}

bool isWord(std::string_view lower, std::string_view keyword) {
    return lower == toLower(keyword);
}

// Thrown inside one line; the line is reported and skipped.
struct LineError {
    Token at;
    std::string message;
};

std::string describe(const Token& token) {
    switch (token.kind) {
    case TokenKind::EndOfLine:
    case TokenKind::EndOfFile:
        return "the end of the line";
    case TokenKind::Comment:
        return "a comment";
    default:
        return "'" + std::string(token.text) + "'";
    }
}

int toInt(std::string_view digits) {
    long long value = 0;
    for (char c : digits) {
        value = value * 10 + (c - '0');
        if (value > 1000000000)
            return 1000000000;
    }
    return static_cast<int>(value);
}

class Parser {
public:
    explicit Parser(std::string_view source) : m_source(source), m_lexer(source) {}

    ParseResult run() {
        fill();
        while (current().kind != TokenKind::EndOfFile) {
            try {
                parseLine();
            } catch (const LineError& error) {
                report(error.at, error.message);
                skipToLineEnd();
            }
        }
        settlePending();
        trimTrailingBlank();
        return {std::move(m_document), std::move(m_diagnostics)};
    }

private:
    // ----- tokens
    void fill() {
        for (auto& token : m_buffer)
            token = m_lexer.next();
    }
    const Token& current() const { return m_buffer[m_head % 3]; }
    const Token& peek(int ahead) const { return m_buffer[(m_head + ahead) % 3]; }
    Token take() {
        Token token = current();
        m_buffer[m_head % 3] = m_lexer.next();
        ++m_head;
        return token;
    }
    bool at(TokenKind kind) const { return current().kind == kind; }
    bool atLineEnd() const {
        return at(TokenKind::EndOfLine) || at(TokenKind::EndOfFile) || at(TokenKind::Comment);
    }
    Token expect(TokenKind kind, const char* what) {
        if (!at(kind))
            fail(std::string("expected ") + what + ", found " + describe(current()));
        return take();
    }
    [[noreturn]] void fail(std::string message) const {
        throw LineError{current(), std::move(message)};
    }
    [[noreturn]] static void failAt(const Token& token, std::string message) {
        throw LineError{token, std::move(message)};
    }
    static SourceLocation loc(const Token& token) { return {token.line, token.column}; }

    void report(const Token& token, const std::string& message,
                Severity severity = Severity::Error) {
        m_diagnostics.push_back({severity, token.line, token.column, visibleText(message)});
    }

    void skipToLineEnd() {
        while (!at(TokenKind::EndOfLine) && !at(TokenKind::EndOfFile))
            take();
        if (at(TokenKind::EndOfLine))
            take();
        m_lastWasBlank = false;
    }

    // Ends a line: an optional trailing comment, then the line break.
    std::optional<std::string> finishLine(const char* after) {
        std::optional<std::string> comment;
        if (at(TokenKind::Comment))
            comment = trimmedComment(take().text);
        if (!at(TokenKind::EndOfLine) && !at(TokenKind::EndOfFile))
            fail(std::string("unexpected ") + describe(current()) + " after " + after);
        if (at(TokenKind::EndOfLine))
            take();
        return comment;
    }

    static std::string trimmedComment(std::string_view text) {
        while (!text.empty() && (text.back() == ' ' || text.back() == '\t'))
            text.remove_suffix(1);
        return std::string(text);
    }

    // ----- where lines go
    enum class Section { Preamble, UnitDeclarations, Steps };

    std::vector<Line>& container() {
        switch (m_section) {
        case Section::Preamble:
            return m_document.preamble;
        case Section::UnitDeclarations:
            return m_document.units.back().declarations;
        case Section::Steps:
            return m_document.units.back().steps.back().lines;
        }
        return m_document.preamble;
    }

    // Lines are gathered in one vector that keeps its capacity and moved to
    // their container when it is complete, in a block of their exact size:
    // most steps have a few lines, and a vector grown line by line left a
    // third of a large project's tree as unused capacity.
    void add(Line line) {
        m_lastWasBlank = std::holds_alternative<BlankLine>(line.body);
        m_seenContent = true;
        m_pending.push_back(std::move(line));
    }

    // Call before the container changes.
    void settlePending() {
        std::vector<Line>& lines = container();
        lines.reserve(lines.size() + m_pending.size());
        std::move(m_pending.begin(), m_pending.end(), std::back_inserter(lines));
        m_pending.clear();
    }

    void trimTrailingBlank() {
        if (m_document.units.empty()) {
            auto& lines = m_document.preamble;
            if (!lines.empty() && std::holds_alternative<BlankLine>(lines.back().body))
                lines.pop_back();
            return;
        }
        auto& unit = m_document.units.back();
        auto& lines = unit.steps.empty() ? unit.declarations : unit.steps.back().lines;
        if (!lines.empty() && std::holds_alternative<BlankLine>(lines.back().body))
            lines.pop_back();
    }

    // ----- lines
    void parseLine() {
        const Token first = current();
        switch (first.kind) {
        case TokenKind::EndOfLine:
            take();
            if (m_seenContent && !m_lastWasBlank)
                add({BlankLine{}, std::nullopt, loc(first)});
            return;
        case TokenKind::Comment: {
            CommentLine comment{trimmedComment(take().text), first.column > 1};
            finishLine("a comment");
            add({std::move(comment), std::nullopt, loc(first)});
            return;
        }
        case TokenKind::Bang:
            take();
            parseDeclaration(first);
            return;
        case TokenKind::Dollar:
            take();
            parseDirective(first);
            return;
        case TokenKind::Word: {
            AddressWord word = readAddressWord(first.text);
            if (word.shape == AddressWord::Shape::Step) {
                take();
                parseStepHeader(first, word.step);
                return;
            }
            break;
        }
        default:
            break;
        }
        parseStatementLine(first);
    }

    void parseDirective(const Token& dollar) {
        if (m_section != Section::Preamble)
            failAt(dollar, "a '$' directive belongs at the top of the file, before '! " +
                               std::string(kProgramKeyword) + "'");
        Token keyword = expect(TokenKind::Word, "a directive name such as 'name' after '$'");
        Directive directive{toLower(keyword.text), std::string(takeFreeText())};
        if (directive.keyword != "name")
            report(keyword,
                   "unknown directive '$" + std::string(keyword.text) + "'; kept as written",
                   Severity::Warning);
        auto comment = finishLine("the directive");
        add({std::move(directive), std::move(comment), loc(dollar)});
    }

    // A directive's argument is free text up to the comment or line end.
    std::string_view takeFreeText() {
        if (atLineEnd())
            return {};
        const char* begin = current().text.data();
        const char* sourceEnd = m_source.data() + m_source.size();
        const char* end = begin;
        while (end < sourceEnd && *end != '\n' && *end != '\r' && *end != ';')
            ++end;
        while (!atLineEnd() && current().text.data() < end)
            take();
        std::string_view text(begin, static_cast<std::size_t>(end - begin));
        while (!text.empty() && (text.back() == ' ' || text.back() == '\t'))
            text.remove_suffix(1);
        return text;
    }

    void parseStepHeader(const Token& token, StepAddress step) {
        if (m_document.units.empty())
            failAt(token, "step " + toString(step) + " before '! " + std::string(kProgramKeyword) +
                              "': declare which unit the code is for first");
        auto& unit = m_document.units.back();
        if (step.unit != unit.station())
            failAt(token, "step " + toString(step) + " is in the code of unit " +
                              std::to_string(unit.station()) + "; write S" +
                              std::to_string(unit.station()) + "." + std::to_string(step.sequence) +
                              "_" + std::to_string(step.step));
        auto comment = finishLine("the step header");
        settlePending();
        unit.steps.push_back({step, std::move(comment), loc(token), {}});
        m_section = Section::Steps;
        m_lastWasBlank = false;
        m_seenContent = true;
    }

    // ----- declarations
    void parseDeclaration(const Token& bang) {
        Token word = expect(TokenKind::Word, "a declaration after '!'");
        std::string lower = toLower(word.text);
        Declaration declaration;
        declaration.location = loc(bang);
        if (const auto family = familyOfIdKeyword(lower)) {
            IdDeclaration id;
            id.family = *family;
            id.station = parseStation();
            expect(TokenKind::Equal, "'=' and the 12-digit IDFIX number");
            if (!at(TokenKind::Word) && !at(TokenKind::Number))
                fail("expected the 12-digit hexadecimal IDFIX number, found " +
                     describe(current()));
            Token idfix = take();
            if (idfix.text.size() != 12 ||
                idfix.text.find_first_not_of("0123456789abcdefABCDEF") != std::string_view::npos)
                failAt(idfix,
                       "the IDFIX number must be 12 hexadecimal digits (000000000000 when no "
                       "identifier is connected), found '" +
                           std::string(idfix.text) + "'");
            id.idfix = toUpper(idfix.text);
            declaration.body = std::move(id);
            requireDeclarationSection(bang);
        } else if (isWord(lower, kTypeKeyword)) {
            TypeDeclaration type;
            type.station = parseStation();
            expect(TokenKind::Equal, "'=' and a unit type such as B46");
            Token typeWord = current();
            if (!at(TokenKind::Word))
                fail("expected a unit type such as B46, found " + describe(current()));
            take();
            type.type = canonicalUnitType(typeWord.text);
            if (type.type.empty())
                failAt(typeWord, "unknown unit type '" + std::string(typeWord.text) +
                                     "'; expected one of " + unitTypeList());
            if (at(TokenKind::Comma)) {
                take();
                Token set = current();
                const int instructionSet = at(TokenKind::Word) ? instructionSetOf(set.text) : 0;
                if (instructionSet == 0)
                    fail("expected the instruction set '" + std::string(instructionSetWord(2)) +
                         "' or '" + std::string(instructionSetWord(3)) + "' after ','");
                take();
                type.instructionSet = instructionSet;
            }
            declaration.body = std::move(type);
            requireDeclarationSection(bang);
        } else if (isWord(lower, kProgramKeyword)) {
            ProgramDeclaration program{parseStation()};
            declaration.body = program;
            auto comment = finishLine("the declaration");
            UnitProgram unit;
            unit.header = {std::move(declaration), std::move(comment), loc(bang)};
            settlePending();
            m_document.units.push_back(std::move(unit));
            m_section = Section::UnitDeclarations;
            m_lastWasBlank = false;
            m_seenContent = true;
            return;
        } else {
            AddressWord address = readAddressWord(word.text);
            if (address.shape == AddressWord::Shape::Malformed)
                failAt(word, address.error);
            if (address.shape != AddressWord::Shape::Variable)
                failAt(word, "expected an address (such as I0.5) or " +
                                 std::string(idKeyword(UnitFamily::Pluto)) + ", " +
                                 std::string(kTypeKeyword) + ", " + std::string(kProgramKeyword) +
                                 " after '!', found '" + std::string(word.text) + "'");
            Operand operand{{}, address.address, loc(word)};
            if (at(TokenKind::Equal)) {
                take();
                Token name = current();
                if (!at(TokenKind::Word) && !at(TokenKind::Number) && !at(TokenKind::Time))
                    fail("expected a symbolic name after '=', found " + describe(current()));
                take();
                declaration.body = NameDeclaration{operand, std::string(name.text), loc(name)};
                requireDeclarationSection(bang);
            } else if (at(TokenKind::Comma)) {
                IoDeclaration io{operand, {}};
                while (at(TokenKind::Comma)) {
                    take();
                    Token option = current();
                    if (!at(TokenKind::Word))
                        fail("expected an I/O option such as a_pulse after ','");
                    take();
                    std::string text = toLower(option.text);
                    if (!isKnownIoOption(text))
                        failAt(option, "unknown I/O option '" + std::string(option.text) +
                                           "'; expected " + ioOptionList());
                    io.options.push_back(std::move(text));
                }
                declaration.body = std::move(io);
                if (m_section == Section::Preamble)
                    failAt(bang, "I/O declarations belong to a unit's code: put them after '! " +
                                     std::string(kProgramKeyword) + ":NN'");
                requireDeclarationSection(bang);
            } else {
                fail("expected '=' and a symbolic name, or ',' and I/O options after '" +
                     std::string(word.text) + "'");
            }
        }
        auto comment = finishLine("the declaration");
        add({std::move(declaration), std::move(comment), loc(bang)});
    }

    void requireDeclarationSection(const Token& bang) const {
        if (m_section == Section::Steps)
            failAt(bang, "declarations come before the first step of a unit's code");
    }

    int parseStation() {
        expect(TokenKind::Colon, "':' and a station number");
        Token number = expect(TokenKind::Number, "a station number 0-31");
        return toInt(number.text);
    }

    // ----- statements
    void parseStatementLine(const Token& first) {
        if (m_section != Section::Steps)
            failAt(first, m_document.units.empty()
                              ? "a statement before '! " + std::string(kProgramKeyword) +
                                    "' and a step header such as S0.0_0"
                              : "a statement outside a step: add a step header such as S" +
                                    std::to_string(m_document.units.back().station()) + ".0_0");
        m_depth = 0; // a line that failed may have left it raised
        Statement statement = parseStatement();
        auto comment = finishLine("the statement");
        add({std::move(statement), std::move(comment), loc(first)});
    }

    Statement parseStatement() {
        Statement statement;
        const Token first = current();
        statement.location = loc(first);
        if (at(TokenKind::LParen)) {
            take();
            statement.kind = StatementKind::Assign;
            statement.assignment = parseAssignment();
            expect(TokenKind::RParen, "')' to close the assignment");
        } else if (at(TokenKind::Word) && peek(1).kind == TokenKind::LParen) {
            std::string keyword = toUpper(first.text);
            take();
            take();
            if (keyword == kSetWord || keyword == kResetWord || keyword == kToggleWord) {
                statement.target = parseOperand("an output or memory");
                if (keyword == kSetWord)
                    statement.kind = StatementKind::Set;
                else if (keyword == kToggleWord)
                    statement.kind = StatementKind::Toggle;
                else if (statement.target.address.kind == AddressKind::Sequence)
                    statement.kind = StatementKind::SequenceReset;
                else
                    statement.kind = StatementKind::Reset;
                if (statement.kind != StatementKind::SequenceReset)
                    requireBitTarget(statement.target, first);
                if (statement.target.address.kind == AddressKind::Sequence &&
                    statement.kind != StatementKind::SequenceReset)
                    failAt(first, "only R(...) applies to a sequence");
            } else if (keyword == kJumpWord) {
                statement.kind = StatementKind::Jump;
                int sign = 0;
                if (at(TokenKind::Plus) || at(TokenKind::Minus))
                    sign = take().kind == TokenKind::Plus ? 1 : -1;
                Token step = expect(TokenKind::Number, "a step number in J(...)");
                statement.relativeJump = sign != 0;
                statement.jumpStep = (sign < 0 ? -1 : 1) * toInt(step.text);
            } else if (keyword == kRisingEdgeWord || keyword == kFallingEdgeWord ||
                       timerSpellingOf(keyword)) {
                failAt(first, "a statement cannot start with " + keyword +
                                  "(...); write the output first, as in Q0.1 = " + keyword +
                                  "(...)");
            } else {
                failAt(first, "unknown instruction '" + std::string(first.text) +
                                  "('; a statement starts with an output, S(, R(, T(, J( or a "
                                  "register assignment in parentheses");
            }
            expect(TokenKind::RParen, "')'");
        } else if (at(TokenKind::Word)) {
            statement.kind = StatementKind::Coil;
            statement.target = parseOperand("an output or memory");
            requireBitTarget(statement.target, first);
            if (statement.target.address.kind == AddressKind::Sequence)
                failAt(first, "a sequence cannot be a coil; reset it with R(" +
                                  std::string(first.text) + ")");
        } else {
            fail("expected a statement (an output, S(...), R(...), T(...), J(...) or a register "
                 "assignment), found " +
                 describe(current()));
        }
        if (at(TokenKind::Equal)) {
            Token equal = take();
            if (atLineEnd())
                failAt(current(), "expected a condition after '='");
            (void)equal;
            statement.condition = parseExpression();
        }
        return statement;
    }

    static void requireBitTarget(const Operand& operand, const Token& at) {
        if (operand.isName() || operand.address.kind == AddressKind::Sequence)
            return;
        if (!operand.address.isBit())
            failAt(at, toString(operand.address) +
                           " holds a number, not a bit; only Q, M, GM, IQ, SM or a register bit "
                           "can be switched");
    }

    Assignment parseAssignment() {
        Assignment assignment;
        assignment.target = parseOperand("a register");
        switch (current().kind) {
        case TokenKind::Plus:
        case TokenKind::Minus:
        case TokenKind::Star:
        case TokenKind::Slash: {
            Token op = take();
            if (op.kind == TokenKind::Plus && at(TokenKind::Plus)) {
                take();
                assignment.op = AssignOp::Increment;
                return assignment;
            }
            if (op.kind == TokenKind::Minus && at(TokenKind::Minus)) {
                take();
                assignment.op = AssignOp::Decrement;
                return assignment;
            }
            expect(TokenKind::Equal,
                   (std::string("'=' after '") + std::string(op.text) + "'").c_str());
            assignment.op = op.kind == TokenKind::Plus    ? AssignOp::AddAssign
                            : op.kind == TokenKind::Minus ? AssignOp::SubAssign
                            : op.kind == TokenKind::Star  ? AssignOp::MulAssign
                                                          : AssignOp::DivAssign;
            assignment.left = parseValue("a register or a number");
            return assignment;
        }
        case TokenKind::Equal:
            take();
            assignment.op = AssignOp::Copy;
            assignment.left = parseValue("a register or a number");
            if (at(TokenKind::Plus) || at(TokenKind::Minus) || at(TokenKind::Star) ||
                at(TokenKind::Slash)) {
                Token op = take();
                assignment.op = AssignOp::Binary;
                assignment.binary = op.kind == TokenKind::Plus    ? BinaryOp::Add
                                    : op.kind == TokenKind::Minus ? BinaryOp::Sub
                                    : op.kind == TokenKind::Star  ? BinaryOp::Mul
                                                                  : BinaryOp::Div;
                assignment.right = parseValue(
                    (std::string("a register or a number after '") + std::string(op.text) + "'")
                        .c_str());
            }
            return assignment;
        default:
            fail("expected ++, --, +=, -=, *=, /= or = after the register, found " +
                 describe(current()));
        }
    }

    Value parseValue(const char* what) {
        Value value;
        value.location = loc(current());
        if (at(TokenKind::Plus) || at(TokenKind::Minus) || at(TokenKind::Number)) {
            int sign = 1;
            if (at(TokenKind::Plus) || at(TokenKind::Minus))
                sign = take().kind == TokenKind::Minus ? -1 : 1;
            Token number = expect(TokenKind::Number, what);
            if (number.text.size() > 10)
                failAt(number, "number too large: " + std::string(number.text));
            std::int64_t v = 0;
            for (char c : number.text)
                v = v * 10 + (c - '0');
            value.constant = sign * v;
            return value;
        }
        if (!at(TokenKind::Word) || peek(1).kind == TokenKind::LParen)
            fail(std::string("expected ") + what + ", found " + describe(current()));
        value.operand = parseOperand(what);
        if (!value.operand->isName() && !value.operand->address.isWord())
            failAt(Token{TokenKind::Word, {}, value.location.line, value.location.column},
                   toString(value.operand->address) + " is not a register; expected " + what);
        return value;
    }

    Operand parseOperand(const char* what) {
        if (!at(TokenKind::Word))
            fail(std::string("expected ") + what + ", found " + describe(current()));
        Token word = take();
        AddressWord address = readAddressWord(word.text);
        switch (address.shape) {
        case AddressWord::Shape::Malformed:
            failAt(word, address.error);
        case AddressWord::Shape::Step:
            failAt(word, "a step header such as " + toString(address.step) +
                             " must stand alone on its line");
        case AddressWord::Shape::Variable:
            return {{}, address.address, loc(word)};
        case AddressWord::Shape::NotAnAddress:
            break;
        }
        return {std::string(word.text), {}, loc(word)};
    }

    // ----- expressions
    // An Or's or And's children are gathered in a vector kept for reuse, one
    // for each Or or And being read, and moved to their node in a block of
    // their exact size (grown child by child, a quarter of the nodes' memory
    // was unused capacity).
    class Gathering {
    public:
        explicit Gathering(Parser& parser) : m_parser(parser), m_level(parser.m_gatheringLevels++) {
            if (parser.m_gathered.size() <= m_level)
                parser.m_gathered.emplace_back();
            children().clear();
        }
        ~Gathering() { --m_parser.m_gatheringLevels; }
        Gathering(const Gathering&) = delete;
        Gathering& operator=(const Gathering&) = delete;

        // a * (b * c) is one series circuit a * b * c: same power flow, one canonical tree.
        void add(ExprKind kind, Expr&& child) {
            if (child.kind == kind)
                std::move(child.children.begin(), child.children.end(),
                          std::back_inserter(children()));
            else
                children().push_back(std::move(child));
        }
        std::vector<Expr> take() {
            std::vector<Expr>& gathered = children();
            return {std::make_move_iterator(gathered.begin()),
                    std::make_move_iterator(gathered.end())};
        }

    private:
        // By index: reading a child may add a level and move the vectors.
        std::vector<Expr>& children() { return m_parser.m_gathered[m_level]; }

        Parser& m_parser;
        std::size_t m_level;
    };

    Expr parseExpression() {
        Expr first = parseTerm();
        if (!at(TokenKind::Plus))
            return first;
        Expr result;
        result.kind = ExprKind::Or;
        result.location = first.location;
        Gathering children(*this);
        children.add(result.kind, std::move(first));
        while (at(TokenKind::Plus)) {
            take();
            if (atLineEnd() || at(TokenKind::RParen))
                failAt(current(), "expected an operand after '+'");
            children.add(result.kind, parseTerm());
        }
        result.children = children.take();
        return result;
    }

    Expr parseTerm() {
        Expr first = parseFactor();
        if (!at(TokenKind::Star))
            return first;
        Expr result;
        result.kind = ExprKind::And;
        result.location = first.location;
        Gathering children(*this);
        children.add(result.kind, std::move(first));
        while (at(TokenKind::Star)) {
            take();
            if (atLineEnd() || at(TokenKind::RParen))
                failAt(current(), "expected an operand after '*'");
            children.add(result.kind, parseFactor());
        }
        result.children = children.take();
        return result;
    }

    Expr parseFactor() {
        if (at(TokenKind::Slash)) {
            Token slash = take();
            if (at(TokenKind::Slash))
                fail("double negation '//' : remove both slashes");
            if (at(TokenKind::LParen) && !isComparisonAhead())
                failAt(slash, "negation applies to one operand, not to a group in parentheses");
            Expr operand = parsePrimary();
            if (operand.kind == ExprKind::Or || operand.kind == ExprKind::And)
                failAt(slash, "negation applies to one operand, not to a group in parentheses");
            operand.negated = true;
            operand.location = loc(slash);
            return operand;
        }
        return parsePrimary();
    }

    bool isComparisonAhead() const {
        if (peek(1).kind != TokenKind::Word)
            return false;
        auto op = peek(2).kind;
        return op == TokenKind::Equal || op == TokenKind::Less || op == TokenKind::Greater;
    }

    Expr parsePrimary() {
        const Token first = current();
        if (at(TokenKind::LParen)) {
            if (isComparisonAhead())
                return parseComparison();
            if (m_depth == kMaxExpressionDepth)
                fail("expression nested deeper than " + std::to_string(kMaxExpressionDepth) +
                     " levels");
            take();
            if (at(TokenKind::RParen))
                fail("empty parentheses: expected an operand");
            ++m_depth;
            Expr inner = parseExpression();
            --m_depth;
            expect(TokenKind::RParen, "')'");
            return inner;
        }
        if (at(TokenKind::Word) && peek(1).kind == TokenKind::LParen)
            return parseFunction();
        if (at(TokenKind::Word)) {
            Expr contact;
            contact.kind = ExprKind::Contact;
            contact.location = loc(first);
            contact.operand = parseOperand("an operand");
            requireBitOperand(contact.operand, first);
            return contact;
        }
        if (at(TokenKind::Number) || at(TokenKind::Time))
            fail("a number cannot be a condition; compare a register with it, as in (R0.1>" +
                 std::string(first.text) + ")");
        fail("expected an operand, found " + describe(current()));
    }

    static void requireBitOperand(const Operand& operand, const Token& at) {
        if (operand.isName())
            return;
        if (operand.address.kind == AddressKind::Sequence)
            failAt(at, "a sequence is not a condition; use it in R(...) or compare S" +
                           std::to_string(operand.address.unit) + "." +
                           std::to_string(operand.address.index) + " in a scenario");
        if (!operand.address.isBit())
            failAt(at, toString(operand.address) + " holds a number; compare it, as in (" +
                           toString(operand.address) + ">0)");
    }

    Expr parseComparison() {
        Token open = take();
        Expr compare;
        compare.kind = ExprKind::Compare;
        compare.location = loc(open);
        Token leftToken = current();
        compare.operand = parseOperand("a register");
        if (!compare.operand.isName() && !compare.operand.address.isWord())
            failAt(leftToken, toString(compare.operand.address) +
                                  " is not a register; only registers can be compared");
        Token op = take();
        if (op.kind == TokenKind::Equal) {
            compare.compare = CompareOp::Equal;
        } else if (at(TokenKind::Equal)) {
            take();
            compare.compare =
                op.kind == TokenKind::Greater ? CompareOp::GreaterEqual : CompareOp::LessEqual;
        } else {
            compare.compare = op.kind == TokenKind::Greater ? CompareOp::Greater : CompareOp::Less;
        }
        compare.right = parseValue("a register or a number to compare with");
        expect(TokenKind::RParen, "')' to close the comparison");
        return compare;
    }

    Expr parseFunction() {
        const Token name = take();
        take(); // (
        std::string keyword = toUpper(name.text);
        Expr expr;
        expr.location = loc(name);
        if (keyword == kRisingEdgeWord || keyword == kFallingEdgeWord) {
            expr.kind = ExprKind::Edge;
            expr.risingEdge = keyword == kRisingEdgeWord;
            if (at(TokenKind::Slash)) {
                take();
                expr.operandNegated = true;
            }
            Token operandToken = current();
            expr.operand = parseOperand("an operand");
            requireBitOperand(expr.operand, operandToken);
        } else if (const auto spelling = timerSpellingOf(keyword)) {
            expr.kind = ExprKind::Timer;
            expr.timer = *spelling;
            expr.preset = parseTimerPreset(keyword);
        } else if (keyword == kSetWord || keyword == kResetWord || keyword == kJumpWord) {
            failAt(name, keyword + "(...) is an instruction, not a condition: it can only start a "
                                   "statement");
        } else {
            failAt(name, "unknown function '" + std::string(name.text) +
                             "('; conditions may use P(, N(, TON(, TPS(, TOF(, T( and IT(");
        }
        expect(TokenKind::RParen, "')'");
        return expr;
    }

    // "0.5": a time written the way most languages write a number.
    static bool isDecimalFraction(std::string_view text) {
        const std::size_t dot = text.find('.');
        auto digits = [](std::string_view part) {
            return !part.empty() && std::all_of(part.begin(), part.end(),
                                                [](char c) { return c >= '0' && c <= '9'; });
        };
        return dot != std::string_view::npos && digits(text.substr(0, dot)) &&
               digits(text.substr(dot + 1));
    }

    // "0.5" as the language writes it, "0s50"; hundredths beyond two decimals dropped.
    static std::string asTime(std::string_view decimal) {
        const std::size_t dot = decimal.find('.');
        std::string fraction(decimal.substr(dot + 1, 2));
        fraction.resize(2, '0');
        return std::string(decimal.substr(0, dot)) + "s" + fraction;
    }

    TimerPreset parseTimerPreset(const std::string& keyword) {
        TimerPreset preset;
        Token token = current();
        if (at(TokenKind::Time)) {
            take();
            std::size_t s = token.text.find_first_of("sS");
            std::string_view whole = token.text.substr(0, s);
            std::string_view fraction = token.text.substr(s + 1);
            if (fraction.size() > 2)
                failAt(token, "a time has at most two decimals (hundredths of a second): '" +
                                  std::string(token.text) + "'");
            if (whole.size() > 6)
                failAt(token, "time too long: '" + std::string(token.text) + "'");
            int hundredths = toInt(fraction);
            if (fraction.size() == 1)
                hundredths *= 10;
            preset.hundredths = toInt(whole) * 100 + hundredths;
            return preset;
        }
        if (at(TokenKind::Word) && isDecimalFraction(token.text))
            fail("a time is written with the decimal sign 's': " + asTime(token.text) + ", not " +
                 std::string(token.text));
        if (at(TokenKind::Word)) {
            Operand operand = parseOperand("a time or a register");
            if (!operand.isName() && operand.address.isBit() && !operand.address.isWord())
                failAt(token, keyword == timerWord(TimerSpelling::T)
                                  ? "T(" + std::string(token.text) +
                                        ") toggles an output; it can only start a statement: "
                                        "T(" +
                                        std::string(token.text) + ") = condition"
                                  : "a timer needs a time such as 5s10 or a register, not " +
                                        toString(operand.address));
            if (!operand.isName() && !operand.address.isWord())
                failAt(token, "a timer needs a time such as 5s10 or a register, not " +
                                  std::string(token.text));
            preset.registerOperand = std::move(operand);
            return preset;
        }
        if (at(TokenKind::Number))
            fail("a time needs the decimal sign 's', as in " + std::string(token.text) + "s00");
        fail("expected a time such as 5s10 or a register in " + keyword + "(...), found " +
             describe(current()));
    }

    std::string_view m_source;
    Lexer m_lexer;
    std::array<Token, 3> m_buffer;
    unsigned m_head = 0;
    Document m_document;
    Diagnostics m_diagnostics;
    Section m_section = Section::Preamble;
    std::vector<Line> m_pending;               // the lines of the current container, not yet in it
    std::vector<std::vector<Expr>> m_gathered; // by level: see Gathering
    std::size_t m_gatheringLevels = 0;
    bool m_lastWasBlank = false;
    bool m_seenContent = false;
    int m_depth = 0; // parentheses open around the expression being read
};

} // namespace

int UnitProgram::station() const {
    const auto* declaration = std::get_if<Declaration>(&header.body);
    if (!declaration)
        return 0;
    const auto* program = std::get_if<ProgramDeclaration>(&declaration->body);
    return program ? program->station : 0;
}

TimerKind timerKind(TimerSpelling spelling) {
    switch (spelling) {
    case TimerSpelling::TON:
    case TimerSpelling::T:
        return TimerKind::OnDelay;
    case TimerSpelling::TPS:
    case TimerSpelling::IT:
        return TimerKind::Pulse;
    case TimerSpelling::TOF:
        return TimerKind::OffDelay;
    }
    return TimerKind::OnDelay;
}

ParseResult parse(std::string_view source) {
    return Parser(source).run();
}

} // namespace rs::lang
