#pragma once

#ifndef Q_MOC_RUN
#include "ladder/Element.h"
#include "ladder/Output.h"
#endif

#include <QCoreApplication>
#include <QKeySequence>
#include <QString>

#include <vector>

namespace rs::ui {

// Every kind of element and output the ladder editor inserts, with the key
// that inserts it and the way the language writes it.
enum class ElementKind {
    NormallyOpen,
    NormallyClosed,
    PositiveEdge,
    NegativeEdge,
    NotPositiveEdge,
    NotNegativeEdge,
    OnDelayTimer,
    PulseTimer,
    OffDelayTimer,
    Comparison,
    Coil,
    Set,
    Reset,
    Toggle,
    Jump,
    SequenceReset,
    Arithmetic,
};

struct ElementKindInfo {
    ElementKind kind;
    bool output;
    const char* name;     // untranslated; shown through ElementKinds::tr
    const char* shortcut; // a single key, as QKeySequence spells it
    const char* label;    // the toolbar button's text, a picture of the symbol
};

class ElementKinds {
    Q_DECLARE_TR_FUNCTIONS(ElementKinds)
public:
    static const std::vector<ElementKindInfo>& all();
    static const ElementKindInfo& info(ElementKind kind);
    static QString name(ElementKind kind);
    static bool isOutput(ElementKind kind) { return info(kind).output; }
    // Whether the kind has a value besides its operand (comparison, arithmetic)
    // or can be negated (timers, comparison).
    static bool hasValue(ElementKind kind);
    static bool canNegate(ElementKind kind);
    // What the operand field holds for the kind ("Variable", "Preset", "Step" ...).
    static QString operandLabel(ElementKind kind);
    // The language's text of an element or output of the kind.
    static QString compose(ElementKind kind, const QString& operand, const QString& value,
                           bool negated);
};

// How an existing element or output reads in the properties dialog.
struct ElementFields {
    ElementKind kind = ElementKind::NormallyOpen;
    QString operand;
    QString value;
    bool negated = false;
    QString comment;
};

ElementFields fieldsOf(const ladder::Element& element);
ElementFields fieldsOf(const ladder::Output& output);

} // namespace rs::ui
