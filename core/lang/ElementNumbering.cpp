// SPDX-License-Identifier: GPL-3.0-or-later
#include "ElementNumbering.h"

namespace rs::lang {

std::optional<ElementNumber> elementAt(const UnitProgram& unit, int line, int column) {
    std::optional<ElementNumber> found;
    forEachStatement(unit, [&](const Step&, const Statement& statement, std::uint32_t number) {
        if (found || statement.location.line != line)
            return;
        found = ElementNumber{number, kOutputElement};
        if (!statement.condition)
            return;
        const PreOrderNumbering<Expr> numbering(*statement.condition, partsOf);
        const auto& nodes = numbering.nodes();
        for (std::size_t i = 0; i < nodes.size(); ++i) {
            const Expr& node = *nodes[i];
            const bool element = node.kind != ExprKind::And && node.kind != ExprKind::Or;
            if (element && node.location.column <= column)
                found->element = static_cast<std::uint16_t>(i + 1);
        }
    });
    return found;
}

} // namespace rs::lang
