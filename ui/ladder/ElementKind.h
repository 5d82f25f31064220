// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#ifndef Q_MOC_RUN
#include "ladder/ElementFields.h"
#include "ladder/ElementVocabulary.h"
#endif

#include <QCoreApplication>
#include <QString>

namespace rs::ui {

using ladder::ElementFields;
using ladder::ElementKind;
using ladder::ElementKindInfo;

// The element kinds of the language core (ladder/ElementVocabulary.h) in the
// reader's language.
class ElementKinds {
    Q_DECLARE_TR_FUNCTIONS(ElementKinds)
public:
    static QString name(ElementKind kind);
    // What the operand field holds for the kind ("Variable", "Preset", "Step" ...).
    static QString operandLabel(ElementKind kind);
};

} // namespace rs::ui
