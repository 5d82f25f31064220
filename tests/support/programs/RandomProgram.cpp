// SPDX-License-Identifier: GPL-3.0-or-later
#include "RandomProgram.h"

#include "lang/Parser.h"

#include <array>

namespace rs::test {

using namespace rs::lang;

namespace {

constexpr std::array<const char*, 8> kNames{"Motor_1",  "EStop",   "Säkerhetsgrind", "Δp",
                                            "Reset_PB", "Counter", "Lampa2",         "Ventil"};
constexpr std::array<const char*, 13> kTypes{"A16", "A20", "B16", "B20", "S20", "B22",    "D20",
                                             "O2",  "B46", "S46", "D45", "ASi", "B42_ASi"};
constexpr std::array<const char*, 12> kOptions{
    "a_pulse", "b_pulse",       "c_pulse", "static",  "non_inv",    "no_filt",
    "x_talk",  "no_test_pulse", "voltage", "current", "counter_up", "counter_updown"};

} // namespace

Operand RandomProgram::name() {
    return {kNames[uniform(0, kNames.size() - 1)], {}, {}};
}

Operand RandomProgram::bitOperand() {
    if (chance(15))
        return name();
    Address a;
    a.unit = chance(80) ? m_unit : uniform(0, 31);
    switch (uniform(0, 8)) {
    case 0:
        a.kind = AddressKind::Input;
        a.index = uniform(0, 17);
        break;
    case 1:
        a.kind = AddressKind::Output;
        a.index = uniform(0, 17);
        break;
    case 2:
        a.kind = AddressKind::InputOutput;
        a.index = uniform(10, 17);
        break;
    case 3:
        a.kind = AddressKind::Memory;
        a.index = uniform(0, 599);
        break;
    case 4:
        a.kind = AddressKind::GlobalMemory;
        a.index = uniform(0, 11);
        break;
    case 5:
        a.kind = AddressKind::SystemMemory;
        a.index = uniform(0, 131);
        break;
    case 6:
        a.kind = AddressKind::RegisterBit;
        a.index = uniform(0, 149);
        a.bit = uniform(0, 15);
        break;
    case 7:
        a.kind = AddressKind::AsiInput;
        a.index = uniform(1, 31);
        a.asiB = chance(30);
        a.bit = a.asiB || chance(50) ? uniform(1, 4) : -1;
        break;
    default:
        a.kind = AddressKind::AsiOutput;
        a.index = uniform(1, 31);
        a.asiB = chance(30);
        a.bit = uniform(1, 4);
        break;
    }
    return {{}, a, {}};
}

Operand RandomProgram::wordOperand() {
    if (chance(15))
        return name();
    Address a;
    a.unit = m_unit;
    switch (uniform(0, 5)) {
    case 0:
        a.kind = AddressKind::Register;
        a.index = uniform(0, 149);
        break;
    case 1:
        a.kind = AddressKind::DoubleRegister;
        a.index = 2 * uniform(0, 74);
        break;
    case 2:
        a.kind = AddressKind::DoubleRegisterLow;
        a.index = 2 * uniform(0, 74);
        break;
    case 3:
        a.kind = AddressKind::DoubleRegisterHigh;
        a.index = 2 * uniform(0, 74);
        break;
    case 4:
        a.kind = AddressKind::SystemRegister;
        a.index = uniform(0, 99);
        break;
    default:
        a.kind = AddressKind::AnalogInput;
        a.index = uniform(0, 7);
        break;
    }
    return {{}, a, {}};
}

Value RandomProgram::value() {
    Value v;
    if (chance(50))
        v.operand = wordOperand();
    else
        v.constant = chance(20) ? uniform(-2147483647, 2147483647) : uniform(-40000, 40000);
    return v;
}

Expr RandomProgram::leaf() {
    Expr e;
    e.negated = chance(25);
    switch (uniform(0, 5)) {
    case 0:
    case 1:
    case 2:
        e.kind = ExprKind::Contact;
        e.operand = bitOperand();
        break;
    case 3:
        e.kind = ExprKind::Edge;
        e.operand = bitOperand();
        e.risingEdge = chance(50);
        e.operandNegated = chance(30);
        break;
    case 4:
        e.kind = ExprKind::Timer;
        e.timer = static_cast<TimerSpelling>(uniform(0, 4));
        if (chance(20))
            e.preset.registerOperand = wordOperand();
        else
            e.preset.hundredths = uniform(0, 65535);
        break;
    default:
        e.kind = ExprKind::Compare;
        e.operand = wordOperand();
        e.compare = static_cast<CompareOp>(uniform(0, 4));
        e.right = value();
        break;
    }
    return e;
}

Expr RandomProgram::expression(int depth) {
    if (depth <= 0 || chance(35))
        return leaf();
    Expr group;
    group.kind = chance(50) ? ExprKind::And : ExprKind::Or;
    int count = uniform(2, 4);
    while (static_cast<int>(group.children.size()) < count) {
        Expr child = expression(depth - 1);
        if (child.kind == group.kind)
            continue; // canonical trees hold no AND directly inside an AND
        group.children.push_back(std::move(child));
    }
    return group;
}

Statement RandomProgram::statement() {
    Statement s;
    switch (uniform(0, 9)) {
    case 0:
    case 1:
    case 2:
        s.kind = StatementKind::Coil;
        s.target = bitOperand();
        break;
    case 3:
        s.kind = StatementKind::Set;
        s.target = bitOperand();
        break;
    case 4:
        s.kind = StatementKind::Reset;
        s.target = bitOperand();
        break;
    case 5:
        s.kind = StatementKind::Toggle;
        s.target = bitOperand();
        break;
    case 6:
        s.kind = StatementKind::Jump;
        s.relativeJump = chance(50);
        s.jumpStep = s.relativeJump ? uniform(-20, 20) : uniform(0, 254);
        break;
    case 7:
        s.kind = StatementKind::SequenceReset;
        s.target.address = {AddressKind::Sequence, m_unit, uniform(1, 9)};
        break;
    default: {
        s.kind = StatementKind::Assign;
        auto& a = *s.assignment;
        a.target = wordOperand();
        a.op = static_cast<AssignOp>(uniform(0, 7));
        if (a.op != AssignOp::Increment && a.op != AssignOp::Decrement)
            a.left = value();
        if (a.op == AssignOp::Binary) {
            a.binary = static_cast<BinaryOp>(uniform(0, 3));
            a.right = value();
        }
        break;
    }
    }
    bool conditionOptional = s.kind != StatementKind::Coil || chance(90);
    if (conditionOptional && chance(85))
        s.condition = expression(uniform(0, 4));
    return s;
}

std::string RandomProgram::text(int maxLength) {
    static constexpr std::array<const char*, 12> pieces{
        "a", "Muting", " ", "*****", "=", "(I0.1)", ";", "ö", "日本", "\t", "@", "\"x\""};
    std::string out;
    int length = uniform(0, maxLength);
    for (int i = 0; i < length; ++i)
        out += pieces[uniform(0, pieces.size() - 1)];
    while (!out.empty() && (out.back() == ' ' || out.back() == '\t'))
        out.pop_back();
    return out;
}

std::optional<std::string> RandomProgram::maybeComment() {
    if (!chance(30))
        return std::nullopt;
    std::string comment = " " + text(6);
    while (!comment.empty() && comment.back() == ' ')
        comment.pop_back();
    return comment;
}

Line RandomProgram::line(bool statements, bool unitSection) {
    int kind = uniform(0, 9);
    if (kind <= 1)
        return {BlankLine{}, std::nullopt, {}};
    if (kind <= 3)
        return {CommentLine{text(8), chance(30)}, std::nullopt, {}};
    if (statements)
        return {statement(), maybeComment(), {}};
    Declaration d;
    switch (uniform(0, unitSection ? 3 : 2)) {
    case 0: {
        IdDeclaration id{static_cast<UnitFamily>(uniform(0, 3)), uniform(0, 31), ""};
        static constexpr char hex[] = "0123456789ABCDEF";
        for (int i = 0; i < 12; ++i)
            id.idfix += hex[uniform(0, 15)];
        d.body = id;
        break;
    }
    case 1:
        d.body = TypeDeclaration{uniform(0, 31), kTypes[uniform(0, kTypes.size() - 1)],
                                 chance(30) ? 0 : uniform(2, 3)};
        break;
    case 2: {
        Operand variable = bitOperand();
        if (variable.isName())
            variable = {{}, {AddressKind::Memory, m_unit, uniform(0, 599)}, {}};
        d.body = NameDeclaration{variable, name().name, {}};
        break;
    }
    default: {
        IoDeclaration io{{{}, {AddressKind::Input, m_unit, uniform(0, 17)}, {}}, {}};
        int count = uniform(1, 3);
        for (int i = 0; i < count; ++i)
            io.options.push_back(kOptions[uniform(0, kOptions.size() - 1)]);
        d.body = io;
        break;
    }
    }
    return {d, maybeComment(), {}};
}

std::vector<Line> RandomProgram::lines(int count, bool statements, bool unitSection) {
    std::vector<Line> out;
    for (int i = 0; i < count; ++i) {
        Line next = line(statements, unitSection);
        bool blank = std::holds_alternative<BlankLine>(next.body);
        if (blank && !out.empty() && std::holds_alternative<BlankLine>(out.back().body))
            continue;
        out.push_back(std::move(next));
    }
    return out;
}

Document RandomProgram::document() {
    Document doc;
    if (chance(70))
        doc.preamble.push_back(
            {Directive{"name", "Project " + std::to_string(uniform(0, 999))}, maybeComment(), {}});
    auto preamble = lines(uniform(0, 6), false, false);
    doc.preamble.insert(doc.preamble.end(), preamble.begin(), preamble.end());
    while (!doc.preamble.empty() && std::holds_alternative<BlankLine>(doc.preamble.front().body))
        doc.preamble.erase(doc.preamble.begin());
    int units = uniform(0, 3);
    for (int u = 0; u < units; ++u) {
        m_unit = uniform(0, 31);
        UnitProgram unit;
        unit.header = {Declaration{ProgramDeclaration{m_unit}, {}}, maybeComment(), {}};
        unit.declarations = lines(uniform(0, 5), false, true);
        int steps = uniform(0, 4);
        for (int s = 0; s < steps; ++s) {
            Step step{{m_unit, uniform(0, 9), uniform(0, 254)}, maybeComment(), {}, {}};
            step.lines = lines(uniform(0, 8), true, true);
            unit.steps.push_back(std::move(step));
        }
        doc.units.push_back(std::move(unit));
    }
    // The file's last line is never blank.
    auto& last = doc.units.empty()                ? doc.preamble
                 : doc.units.back().steps.empty() ? doc.units.back().declarations
                                                  : doc.units.back().steps.back().lines;
    if (!last.empty() && std::holds_alternative<BlankLine>(last.back().body))
        last.pop_back();
    return doc;
}

} // namespace rs::test
