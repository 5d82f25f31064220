// SPDX-License-Identifier: GPL-3.0-or-later
#include "RandomCondition.h"

namespace rs::test {

using namespace rs::lang;

Operand RandomCondition::bit() {
    switch (uniform(0, 6)) {
    case 0:
        return {"EStop", {AddressKind::Input, 0, 12}, {}};
    case 1:
        return {{}, {AddressKind::Input, 0, 1}, {}};
    case 2:
        return {{}, {AddressKind::Input, 0, 2}, {}};
    case 3:
        return {{}, {AddressKind::Memory, 0, 0}, {}};
    case 4:
        return {{}, {AddressKind::Output, 0, 2}, {}};
    case 5:
        return {{}, {AddressKind::RegisterBit, 0, 5, 3}, {}};
    default:
        return {{}, {AddressKind::GlobalMemory, 0, 1}, {}};
    }
}

Expr RandomCondition::leaf() {
    Expr e;
    e.negated = chance(30);
    switch (uniform(0, 7)) {
    case 0:
    case 1:
    case 2:
    case 3:
        e.kind = ExprKind::Contact;
        e.operand = bit();
        break;
    case 4:
        e.kind = ExprKind::Edge;
        e.operand = bit();
        e.risingEdge = chance(50);
        e.operandNegated = chance(25);
        break;
    case 5:
        e.kind = ExprKind::Timer;
        e.timer = static_cast<TimerSpelling>(uniform(0, 4));
        if (chance(25))
            e.preset.registerOperand = Operand{{}, {AddressKind::Register, 0, uniform(0, 3)}, {}};
        else
            e.preset.hundredths = uniform(0, 65535);
        break;
    default:
        e.kind = ExprKind::Compare;
        e.operand = {{}, {AddressKind::Register, 0, uniform(0, 1)}, {}};
        e.compare = static_cast<CompareOp>(uniform(0, 4));
        if (chance(50))
            e.right.operand = Operand{{}, {AddressKind::Register, 0, 2}, {}};
        else
            e.right.constant = uniform(-5, 5);
        break;
    }
    return e;
}

Expr RandomCondition::expression(int depth) {
    if (depth <= 0 || chance(30))
        return leaf();
    Expr group;
    group.kind = chance(50) ? ExprKind::And : ExprKind::Or;
    const int count = uniform(2, 4);
    while (static_cast<int>(group.children.size()) < count) {
        Expr child = expression(depth - 1);
        if (child.kind != group.kind) // canonical trees nest no group in its own kind
            group.children.push_back(std::move(child));
    }
    return group;
}

} // namespace rs::test
