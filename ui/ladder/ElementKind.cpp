// SPDX-License-Identifier: GPL-3.0-or-later
#include "ElementKind.h"

namespace rs::ui {

QString ElementKinds::name(ElementKind kind) {
    switch (kind) {
    case ElementKind::NormallyOpen:
        return tr("Contact (NO)");
    case ElementKind::NormallyClosed:
        return tr("Contact (NC)");
    case ElementKind::PositiveEdge:
        return tr("Positive Edge (P)");
    case ElementKind::NegativeEdge:
        return tr("Negative Edge (N)");
    case ElementKind::NotPositiveEdge:
        return tr("Not Positive Edge (/P)");
    case ElementKind::NotNegativeEdge:
        return tr("Not Negative Edge (/N)");
    case ElementKind::OnDelayTimer:
        return tr("On-Delay Timer (TON)");
    case ElementKind::PulseTimer:
        return tr("Pulse Timer (TPS)");
    case ElementKind::OffDelayTimer:
        return tr("Off-Delay Timer (TOF)");
    case ElementKind::Comparison:
        return tr("Comparison");
    case ElementKind::Coil:
        return tr("Coil");
    case ElementKind::Set:
        return tr("Set Latch");
    case ElementKind::Reset:
        return tr("Reset Latch");
    case ElementKind::Toggle:
        return tr("Toggle Latch");
    case ElementKind::Jump:
        return tr("Jump");
    case ElementKind::SequenceReset:
        return tr("Sequence Reset");
    case ElementKind::Arithmetic:
        return tr("Arithmetic");
    }
    return {};
}

QString ElementKinds::operandLabel(ElementKind kind) {
    switch (ladder::infoOf(kind).operandRole) {
    case ladder::OperandRole::Preset:
        return tr("Preset (time such as 2s50, or a register):");
    case ladder::OperandRole::Register:
        return tr("Register:");
    case ladder::OperandRole::TargetRegister:
        return tr("Target register:");
    case ladder::OperandRole::Step:
        return tr("Step (number, or +n / -n relative):");
    case ladder::OperandRole::Sequence:
        return tr("Sequence (such as S0.1):");
    case ladder::OperandRole::Variable:
        break;
    }
    return tr("Variable:");
}

} // namespace rs::ui
