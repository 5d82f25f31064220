// SPDX-License-Identifier: GPL-3.0-or-later
#include "ladder/ElementVocabulary.h"
#include "ladder/ElementFields.h"
#include "ladder/ElementText.h"
#include "ladder/LadderToText.h"
#include "lang/Parser.h"
#include "lang/Printer.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

// Every element kind makes a syntax-tree node that prints as the language
// writes the kind, and the node reads back as the same kind: from the node
// itself, from the ladder element it converts to, and from the fields of the
// properties dialog.
namespace {

using namespace rs::ladder;
using rs::lang::Address;
using rs::lang::AddressKind;
using rs::lang::Operand;
using rs::lang::printOperand;
using rs::lang::Value;

rs::lang::Document vocabularyDocument() {
    return rs::lang::parse("! id_pluto:00=000034AD4AE1\n"
                           "! type_pluto:00=B46,is3\n"
                           "! I0.12=EStop\n"
                           "! pgm_pluto:00\n"
                           "! R0.1=Count\n"
                           "S0.0_0\n")
        .document;
}

class RandomParts {
public:
    explicit RandomParts(unsigned seed) : m_random(seed) {}

    ElementParts of(ElementKind kind) {
        ElementParts parts;
        const ElementKindInfo& info = infoOf(kind);
        parts.negated = info.canNegate && coin();
        switch (info.operandRole) {
        case OperandRole::Variable:
            parts.operand = bit();
            parts.operandNegated = isEdge(kind) && coin();
            break;
        case OperandRole::Preset:
            if (coin())
                parts.preset.registerOperand = word();
            else
                parts.preset.hundredths = number(0, 99999);
            break;
        case OperandRole::Register:
        case OperandRole::TargetRegister:
            parts.operand = word();
            break;
        case OperandRole::Step:
            parts.relativeJump = coin();
            parts.jumpStep = parts.relativeJump ? number(-5, 5) : number(0, 9);
            break;
        case OperandRole::Sequence:
            parts.operand = address(AddressKind::Sequence, number(1, 5));
            break;
        }
        // A timer keeps T and IT, the manuals' other spellings of TON and TPS.
        const rs::lang::TimerSpelling spellings[] = {
            rs::lang::TimerSpelling::TON, rs::lang::TimerSpelling::TPS,
            rs::lang::TimerSpelling::TOF, rs::lang::TimerSpelling::T, rs::lang::TimerSpelling::IT};
        parts.timer = spellings[number(0, 4)];
        parts.compare = static_cast<rs::lang::CompareOp>(number(0, 4));
        parts.right = value();
        parts.assignment.op = static_cast<rs::lang::AssignOp>(number(0, 7));
        parts.assignment.binary = static_cast<rs::lang::BinaryOp>(number(0, 3));
        parts.assignment.left = value();
        parts.assignment.right = value();
        return parts;
    }

private:
    int number(int low, int high) { return std::uniform_int_distribution(low, high)(m_random); }
    bool coin() { return number(0, 1) == 1; }

    static Operand address(AddressKind kind, int index) {
        Operand operand;
        operand.address = Address{kind, 0, index};
        return operand;
    }
    Operand bit() {
        if (number(0, 5) == 0) {
            Operand named = address(AddressKind::Input, 12);
            named.name = "EStop";
            return named;
        }
        // An unnamed operand never stands at a named address: the editor
        // writes an address that has a name with the name.
        const AddressKind kinds[] = {AddressKind::Input, AddressKind::Output, AddressKind::Memory};
        const AddressKind kind = kinds[number(0, 2)];
        const int index = number(0, 15);
        return address(kind, kind == AddressKind::Input && index == 12 ? 13 : index);
    }
    Operand word() {
        if (number(0, 5) == 0) {
            Operand named = address(AddressKind::Register, 1);
            named.name = "Count";
            return named;
        }
        const int index = number(0, 19);
        return address(AddressKind::Register, index >= 1 ? index + 1 : index);
    }
    Value value() {
        if (coin())
            return Value{word(), 0, {}};
        return Value{std::nullopt, number(-100, 100), {}};
    }

    std::mt19937 m_random;
};

std::string printed(const Value& value) {
    return value.operand ? printOperand(*value.operand) : std::to_string(value.constant);
}

// The text the editor wrote for each kind before kinds made syntax trees.
std::string textTheEditorWrote(ElementKind kind, const ElementParts& p) {
    const std::string o = (p.operandNegated ? "/" : "") + printOperand(p.operand);
    const std::string no = p.negated ? "/" : "";
    const std::string preset = p.preset.registerOperand ? printOperand(*p.preset.registerOperand)
                                                        : rs::lang::formatTime(p.preset.hundredths);
    const char* const timerWords[] = {"TON", "TPS", "TOF", "T", "IT"};
    const std::string spelled = timerWords[static_cast<int>(p.timer)];
    auto timer = [&](const char* standard, std::set<std::string> spellings) {
        return no + (spellings.count(spelled) ? spelled : standard) + "(" + preset + ")";
    };
    const char* const compares[] = {"=", ">", "<", ">=", "<="};
    const char* const binaries[] = {" + ", " - ", " * ", " / "};
    const auto& a = p.assignment;
    switch (kind) {
    case ElementKind::NormallyOpen:
    case ElementKind::Coil:
        return o;
    case ElementKind::NormallyClosed:
        return "/" + o;
    case ElementKind::PositiveEdge:
        return "P(" + o + ")";
    case ElementKind::NegativeEdge:
        return "N(" + o + ")";
    case ElementKind::NotPositiveEdge:
        return "/P(" + o + ")";
    case ElementKind::NotNegativeEdge:
        return "/N(" + o + ")";
    case ElementKind::OnDelayTimer:
        return timer("TON", {"TON", "T"});
    case ElementKind::PulseTimer:
        return timer("TPS", {"TPS", "IT"});
    case ElementKind::OffDelayTimer:
        return timer("TOF", {"TOF"});
    case ElementKind::Comparison:
        return no + "(" + o + compares[static_cast<int>(p.compare)] + printed(p.right) + ")";
    case ElementKind::Set:
        return "S(" + o + ")";
    case ElementKind::Reset:
    case ElementKind::SequenceReset:
        return "R(" + o + ")";
    case ElementKind::Toggle:
        return "T(" + o + ")";
    case ElementKind::Jump:
        return "J(" + std::string(p.relativeJump ? (p.jumpStep < 0 ? "-" : "+") : "") +
               std::to_string(std::abs(p.jumpStep)) + ")";
    case ElementKind::Arithmetic:
        switch (a.op) {
        case rs::lang::AssignOp::Increment:
            return "(" + o + "++)";
        case rs::lang::AssignOp::Decrement:
            return "(" + o + "--)";
        case rs::lang::AssignOp::AddAssign:
            return "(" + o + " += " + printed(a.left) + ")";
        case rs::lang::AssignOp::SubAssign:
            return "(" + o + " -= " + printed(a.left) + ")";
        case rs::lang::AssignOp::MulAssign:
            return "(" + o + " *= " + printed(a.left) + ")";
        case rs::lang::AssignOp::DivAssign:
            return "(" + o + " /= " + printed(a.left) + ")";
        case rs::lang::AssignOp::Copy:
            return "(" + o + " = " + printed(a.left) + ")";
        case rs::lang::AssignOp::Binary:
            return "(" + o + " = " + printed(a.left) + binaries[static_cast<int>(a.binary)] +
                   printed(a.right) + ")";
        }
    }
    return {};
}

std::string print(const ElementNode& node) {
    if (const auto* expr = std::get_if<rs::lang::Expr>(&node))
        return rs::lang::printExpression(*expr);
    return rs::lang::printStatement(std::get<rs::lang::Statement>(node));
}

TEST(ElementVocabulary, ListsEveryKindOnceWithItsOwnKey) {
    std::set<ElementKind> kinds;
    std::set<std::string> keys;
    for (const ElementKindInfo& info : elementKinds()) {
        kinds.insert(info.kind);
        keys.insert(info.insertKey);
        EXPECT_EQ(&infoOf(info.kind), &info);
    }
    EXPECT_EQ(kinds.size(), elementKinds().size());
    EXPECT_EQ(keys.size(), elementKinds().size());
}

TEST(ElementVocabulary, EveryKindMakesANodeThatPrintsAsTheKindAndReadsBack) {
    const auto document = vocabularyDocument();
    RandomParts random(14);
    for (int round = 0; round < 60; ++round)
        for (const ElementKindInfo& info : elementKinds()) {
            const ElementParts parts = random.of(info.kind);
            const ElementNode node = makeNode(info.kind, parts);
            const std::string text = print(node);
            SCOPED_TRACE(text);
            EXPECT_EQ(text, textTheEditorWrote(info.kind, parts));
            EXPECT_EQ(kindOf(node), info.kind);
            EXPECT_EQ(makeNode(info.kind, partsOf(node)), node);
            EXPECT_EQ(std::holds_alternative<rs::lang::Statement>(node), info.output);

            // The language reads the text as an element or output of the kind,
            // and the dialog's fields of it make the same text, a timer in its
            // standard spelling as the dialog always wrote it.
            ElementParts standard = parts;
            standard.timer = rs::lang::TimerSpelling::TON;
            const std::string dialogText = textTheEditorWrote(info.kind, standard);
            if (info.output) {
                const OutputReading read = readOutput(document, 0, text);
                ASSERT_TRUE(read.output) << read.error;
                EXPECT_EQ(kindOf(*read.output), info.kind);
                EXPECT_EQ(outputText(*read.output), text);
                const ElementFields fields = fieldsOf(*read.output);
                EXPECT_EQ(fields.kind, info.kind);
                EXPECT_EQ(textOf(fields).text, dialogText);
            } else {
                const ElementReading read = readElement(document, 0, text);
                ASSERT_TRUE(read.element) << read.error;
                EXPECT_EQ(kindOf(*read.element), info.kind);
                EXPECT_EQ(elementText(*read.element), text);
                const ElementFields fields = fieldsOf(*read.element);
                EXPECT_EQ(fields.kind, info.kind);
                EXPECT_EQ(textOf(fields).text, dialogText);
            }
        }
}

TEST(ElementVocabulary, AnAndOrAnOrIsNoKind) {
    rs::lang::Expr both;
    both.kind = rs::lang::ExprKind::And;
    both.children.resize(2);
    EXPECT_FALSE(kindOf(ElementNode{both}));
}

TEST(ElementFields, TypedWordsStandAsWritten) {
    EXPECT_EQ(textOf({ElementKind::OnDelayTimer, "2s50", "", true, ""}).text, "/TON(2s50)");
    EXPECT_EQ(textOf({ElementKind::Comparison, "Count", ">= 5", false, ""}).text, "(Count>=5)");
    EXPECT_EQ(textOf({ElementKind::Arithmetic, "R0.1", "= R0.2 * 3", false, ""}).text,
              "(R0.1 = R0.2 * 3)");
    EXPECT_EQ(textOf({ElementKind::Jump, "-2", "", false, ""}).text, "J(-2)");
    EXPECT_EQ(textOf({ElementKind::PositiveEdge, "/I0.1", "", false, ""}).text, "P(/I0.1)");
    // Negation is offered only where the kind has it.
    EXPECT_EQ(textOf({ElementKind::Set, "Q0.1", "", true, ""}).text, "S(Q0.1)");
}

TEST(ElementFields, SaysWhyFieldsMakeNoElement) {
    EXPECT_EQ(textOf({ElementKind::NormallyOpen, " ", "", false, ""}).error,
              "the element is empty");
    EXPECT_EQ(textOf({ElementKind::Coil, "", "", false, ""}).error, "the output is empty");
    EXPECT_FALSE(textOf({ElementKind::Comparison, "R0.1", "5", false, ""}).error.empty());
    EXPECT_FALSE(textOf({ElementKind::Arithmetic, "R0.1", "++ 2", false, ""}).error.empty());
    EXPECT_FALSE(textOf({ElementKind::Jump, "next", "", false, ""}).error.empty());
}

} // namespace
