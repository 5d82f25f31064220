// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Element.h"
#include "Output.h"

#include <optional>
#include <string>
#include <string_view>

// One element or output written as the language writes it ("/EStop", "P(I0.14)",
// "TON(2s50)", "(R0.1>=5)"; "Q0.2", "S(Q0.2)", "J(+1)", "R(S0.1)", "(R0.1+=2)"),
// read with the names the unit sees. The ladder editor's properties dialog
// edits elements this way, so what it accepts is exactly what the language does.
namespace rs::ladder {

struct ElementReading {
    std::optional<Element> element;
    std::string error; // why the text is not one element; empty when read
};

struct OutputReading {
    std::optional<Output> output;
    std::string error;
};

// `document` gives the names: the global ones and those of the unit `station`.
ElementReading readElement(const lang::Document& document, int station, std::string_view text);
OutputReading readOutput(const lang::Document& document, int station, std::string_view text);

std::string elementText(const Element& element);
std::string outputText(const Output& output);

} // namespace rs::ladder
