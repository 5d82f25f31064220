#include "ElementKind.h"

#include "ladder/ElementText.h"
#include "lang/Printer.h"

#include <algorithm>

namespace rs::ui {

namespace {

QString operandText(const lang::Operand& operand) {
    return QString::fromStdString(lang::printOperand(operand));
}

// The text inside "( )" after the operand: ">=5" of "(R0.1>=5)", "+= 2" of "(R0.1 += 2)".
QString valueAfter(const std::string& text, const QString& operand) {
    QString inner = QString::fromStdString(text).trimmed();
    if (inner.startsWith(QLatin1Char('/')))
        inner.remove(0, 1);
    if (inner.startsWith(QLatin1Char('(')) && inner.endsWith(QLatin1Char(')')))
        inner = inner.mid(1, inner.size() - 2);
    if (inner.startsWith(operand))
        inner.remove(0, operand.size());
    return inner.trimmed();
}

} // namespace

const std::vector<ElementKindInfo>& ElementKinds::all() {
    static const std::vector<ElementKindInfo> kinds = {
        {ElementKind::NormallyOpen, false, QT_TR_NOOP("Contact (NO)"), "C", "-| |-"},
        {ElementKind::NormallyClosed, false, QT_TR_NOOP("Contact (NC)"), "/", "-|/|-"},
        {ElementKind::PositiveEdge, false, QT_TR_NOOP("Positive Edge (P)"), "P", "-|P|-"},
        {ElementKind::NegativeEdge, false, QT_TR_NOOP("Negative Edge (N)"), "N", "-|N|-"},
        {ElementKind::NotPositiveEdge, false, QT_TR_NOOP("Not Positive Edge (/P)"), "Shift+P",
         "-|/P|-"},
        {ElementKind::NotNegativeEdge, false, QT_TR_NOOP("Not Negative Edge (/N)"), "Shift+N",
         "-|/N|-"},
        {ElementKind::OnDelayTimer, false, QT_TR_NOOP("On-Delay Timer (TON)"), "O", "[TON]"},
        {ElementKind::PulseTimer, false, QT_TR_NOOP("Pulse Timer (TPS)"), "U", "[TPS]"},
        {ElementKind::OffDelayTimer, false, QT_TR_NOOP("Off-Delay Timer (TOF)"), "F", "[TOF]"},
        {ElementKind::Comparison, false, QT_TR_NOOP("Comparison"), "=", "[>=]"},
        {ElementKind::Coil, true, QT_TR_NOOP("Coil"), "L", "-( )"},
        {ElementKind::Set, true, QT_TR_NOOP("Set Latch"), "S", "-(S)"},
        {ElementKind::Reset, true, QT_TR_NOOP("Reset Latch"), "R", "-(R)"},
        {ElementKind::Toggle, true, QT_TR_NOOP("Toggle Latch"), "T", "-(T)"},
        {ElementKind::Jump, true, QT_TR_NOOP("Jump"), "J", "-(J)"},
        {ElementKind::SequenceReset, true, QT_TR_NOOP("Sequence Reset"), "Q", "-(RS)"},
        {ElementKind::Arithmetic, true, QT_TR_NOOP("Arithmetic"), "+", "[+=]"},
    };
    return kinds;
}

const ElementKindInfo& ElementKinds::info(ElementKind kind) {
    const auto& kinds = all();
    return *std::find_if(kinds.begin(), kinds.end(),
                         [kind](const ElementKindInfo& info) { return info.kind == kind; });
}

QString ElementKinds::name(ElementKind kind) {
    return tr(info(kind).name);
}

bool ElementKinds::hasValue(ElementKind kind) {
    return kind == ElementKind::Comparison || kind == ElementKind::Arithmetic;
}

bool ElementKinds::canNegate(ElementKind kind) {
    return kind == ElementKind::OnDelayTimer || kind == ElementKind::PulseTimer ||
           kind == ElementKind::OffDelayTimer || kind == ElementKind::Comparison;
}

QString ElementKinds::operandLabel(ElementKind kind) {
    switch (kind) {
    case ElementKind::OnDelayTimer:
    case ElementKind::PulseTimer:
    case ElementKind::OffDelayTimer:
        return tr("Preset (time such as 2s50, or a register):");
    case ElementKind::Comparison:
        return tr("Register:");
    case ElementKind::Arithmetic:
        return tr("Target register:");
    case ElementKind::Jump:
        return tr("Step (number, or +n / -n relative):");
    case ElementKind::SequenceReset:
        return tr("Sequence (such as S0.1):");
    default:
        return tr("Variable:");
    }
}

QString ElementKinds::compose(ElementKind kind, const QString& operand, const QString& value,
                              bool negated) {
    const QString o = operand.trimmed();
    const QString v = value.trimmed();
    const QString no = negated ? QStringLiteral("/") : QString();
    switch (kind) {
    case ElementKind::NormallyOpen:
        return o;
    case ElementKind::NormallyClosed:
        return QStringLiteral("/") + o;
    case ElementKind::PositiveEdge:
        return QStringLiteral("P(%1)").arg(o);
    case ElementKind::NegativeEdge:
        return QStringLiteral("N(%1)").arg(o);
    case ElementKind::NotPositiveEdge:
        return QStringLiteral("/P(%1)").arg(o);
    case ElementKind::NotNegativeEdge:
        return QStringLiteral("/N(%1)").arg(o);
    case ElementKind::OnDelayTimer:
        return no + QStringLiteral("TON(%1)").arg(o);
    case ElementKind::PulseTimer:
        return no + QStringLiteral("TPS(%1)").arg(o);
    case ElementKind::OffDelayTimer:
        return no + QStringLiteral("TOF(%1)").arg(o);
    case ElementKind::Comparison:
        return no + QStringLiteral("(%1%2)").arg(o, v);
    case ElementKind::Coil:
        return o;
    case ElementKind::Set:
        return QStringLiteral("S(%1)").arg(o);
    case ElementKind::Reset:
    case ElementKind::SequenceReset:
        return QStringLiteral("R(%1)").arg(o);
    case ElementKind::Toggle:
        return QStringLiteral("T(%1)").arg(o);
    case ElementKind::Jump:
        return QStringLiteral("J(%1)").arg(o);
    case ElementKind::Arithmetic:
        return QStringLiteral("(%1%2)").arg(o, v);
    }
    return o;
}

ElementFields fieldsOf(const ladder::Element& element) {
    ElementFields fields;
    if (const auto* contact = std::get_if<ladder::Contact>(&element)) {
        using K = ladder::ContactKind;
        switch (contact->kind) {
        case K::NormallyOpen:
            fields.kind = ElementKind::NormallyOpen;
            break;
        case K::NormallyClosed:
            fields.kind = ElementKind::NormallyClosed;
            break;
        case K::PositiveEdge:
            fields.kind = ElementKind::PositiveEdge;
            break;
        case K::NegativeEdge:
            fields.kind = ElementKind::NegativeEdge;
            break;
        case K::NotPositiveEdge:
            fields.kind = ElementKind::NotPositiveEdge;
            break;
        case K::NotNegativeEdge:
            fields.kind = ElementKind::NotNegativeEdge;
            break;
        }
        fields.operand = (contact->operandNegated ? QStringLiteral("/") : QString()) +
                         operandText(contact->operand);
    } else if (const auto* timer = std::get_if<ladder::TimerBox>(&element)) {
        const lang::TimerKind kind = lang::timerKind(timer->spelling);
        fields.kind = kind == lang::TimerKind::Pulse      ? ElementKind::PulseTimer
                      : kind == lang::TimerKind::OffDelay ? ElementKind::OffDelayTimer
                                                          : ElementKind::OnDelayTimer;
        fields.operand = timer->preset.registerOperand
                             ? operandText(*timer->preset.registerOperand)
                             : QString::fromStdString(lang::formatTime(timer->preset.hundredths));
        fields.negated = timer->negated;
    } else if (const auto* compare = std::get_if<ladder::ComparisonBox>(&element)) {
        fields.kind = ElementKind::Comparison;
        fields.operand = operandText(compare->left);
        fields.value = valueAfter(ladder::elementText(element), fields.operand);
        fields.negated = compare->negated;
    }
    return fields;
}

ElementFields fieldsOf(const ladder::Output& output) {
    ElementFields fields;
    using K = lang::StatementKind;
    switch (output.kind) {
    case K::Coil:
        fields.kind = ElementKind::Coil;
        break;
    case K::Set:
        fields.kind = ElementKind::Set;
        break;
    case K::Reset:
        fields.kind = ElementKind::Reset;
        break;
    case K::Toggle:
        fields.kind = ElementKind::Toggle;
        break;
    case K::Jump:
        fields.kind = ElementKind::Jump;
        break;
    case K::SequenceReset:
        fields.kind = ElementKind::SequenceReset;
        break;
    case K::Assign:
        fields.kind = ElementKind::Arithmetic;
        break;
    }
    if (output.kind == K::Jump) {
        const QString text = QString::fromStdString(ladder::outputText(output));
        fields.operand = text.mid(2, text.size() - 3); // inside "J( )"
    } else if (output.kind == K::Assign) {
        fields.operand = operandText(output.assignment.target);
        fields.value = valueAfter(ladder::outputText(output), fields.operand);
    } else {
        fields.operand = operandText(output.target);
    }
    if (output.comment)
        fields.comment = QString::fromStdString(*output.comment).trimmed();
    return fields;
}

} // namespace rs::ui
