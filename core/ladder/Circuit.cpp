// SPDX-License-Identifier: GPL-3.0-or-later
#include "Circuit.h"

namespace rs::ladder {

namespace {

Circuit group(Circuit::Kind kind, std::vector<Circuit> parts) {
    Circuit circuit;
    circuit.kind = kind;
    circuit.parts = std::move(parts);
    normalize(circuit);
    return circuit;
}

} // namespace

Circuit Circuit::of(Element element) {
    Circuit circuit;
    circuit.element = std::move(element);
    return circuit;
}

Circuit Circuit::series(std::vector<Circuit> parts) {
    return group(Kind::Series, std::move(parts));
}

Circuit Circuit::parallel(std::vector<Circuit> parts) {
    return group(Kind::Parallel, std::move(parts));
}

void normalize(Circuit& circuit) {
    if (circuit.isElement())
        return;
    std::vector<Circuit> merged;
    for (auto& part : circuit.parts) {
        normalize(part);
        if (!part.isElement() && part.parts.empty())
            continue;
        if (part.kind == circuit.kind) {
            for (auto& inner : part.parts)
                merged.push_back(std::move(inner));
        } else {
            merged.push_back(std::move(part));
        }
    }
    circuit.parts = std::move(merged);
    if (circuit.parts.size() == 1) {
        Circuit only = std::move(circuit.parts.front());
        circuit = std::move(only);
    }
}

int nodeCount(const Circuit& circuit) {
    int count = 1;
    for (const auto& part : circuit.parts)
        count += nodeCount(part);
    return count;
}

} // namespace rs::ladder
