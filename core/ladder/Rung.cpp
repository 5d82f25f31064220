// SPDX-License-Identifier: GPL-3.0-or-later
#include "Rung.h"

#include <algorithm>

namespace rs::ladder {

namespace {

bool holdsMemory(const Circuit& circuit) {
    if (!circuit.isElement())
        return std::any_of(circuit.parts.begin(), circuit.parts.end(), holdsMemory);
    if (std::holds_alternative<TimerBox>(circuit.element))
        return true;
    const auto* contact = std::get_if<Contact>(&circuit.element);
    return contact && isEdge(contact->kind);
}

// Whether writing `written` can change what reading `read` gives within the
// scan. Inputs are sampled before the scan, so only outputs read back what
// was written; an illuminated push button writes its lamp, which is its output.
bool touches(const lang::Operand& written, const lang::Operand& read) {
    const lang::Address& w = written.address;
    const lang::Address& r = read.address;
    if (!w.valid() || !r.valid())
        return written.name == read.name;
    if (w.kind == lang::AddressKind::InputOutput)
        return r.kind == lang::AddressKind::Output && r.unit == w.unit && r.index == w.index;
    return w == r;
}

// What a condition without timers reads: the bits of its contacts, and
// whether it compares any word.
void collectReads(const Circuit& circuit, std::vector<const lang::Operand*>& bits, bool& compares) {
    if (!circuit.isElement()) {
        for (const auto& part : circuit.parts)
            collectReads(part, bits, compares);
        return;
    }
    if (const auto* contact = std::get_if<Contact>(&circuit.element))
        bits.push_back(&contact->operand);
    else if (std::holds_alternative<ComparisonBox>(circuit.element))
        compares = true;
}

bool writesWhatConditionReads(const Output& output, const std::vector<const lang::Operand*>& bits,
                              bool readsWords) {
    switch (output.kind) {
    case lang::StatementKind::Coil:
    case lang::StatementKind::Set:
    case lang::StatementKind::Reset:
    case lang::StatementKind::Toggle:
        if (output.target.address.kind == lang::AddressKind::RegisterBit && readsWords)
            return true;
        return std::any_of(bits.begin(), bits.end(),
                           [&](const lang::Operand* bit) { return touches(output.target, *bit); });
    case lang::StatementKind::Assign:
        return readsWords || std::any_of(bits.begin(), bits.end(), [&](const lang::Operand* bit) {
                   return bit->address.kind == lang::AddressKind::RegisterBit ||
                          touches(output.assignment.target, *bit);
               });
    case lang::StatementKind::Jump:
    case lang::StatementKind::SequenceReset:
        return false; // both act at the end of the scan or on another sequence
    }
    return true;
}

} // namespace

bool isExpressible(const Rung& rung) {
    if (rung.outputs.empty())
        return false;
    if (rung.outputs.size() == 1 || !rung.condition)
        return true;
    if (holdsMemory(*rung.condition))
        return false;
    std::vector<const lang::Operand*> bits;
    bool readsWords = false;
    collectReads(*rung.condition, bits, readsWords);
    for (std::size_t i = 0; i + 1 < rung.outputs.size(); ++i)
        if (writesWhatConditionReads(rung.outputs[i], bits, readsWords))
            return false;
    return true;
}

bool canJoin(const Rung& rung, const Rung& next) {
    if (rung.condition != next.condition)
        return false;
    Rung joined = rung;
    joined.outputs.insert(joined.outputs.end(), next.outputs.begin(), next.outputs.end());
    return isExpressible(joined);
}

} // namespace rs::ladder
