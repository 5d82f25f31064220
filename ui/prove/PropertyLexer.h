// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "text/PlutoLexer.h"

namespace rs::ui {

// Colours property files (../shared/spec/properties.md) with the program
// text's colours: the verbs and `within`, `next` and `cycle` as keywords,
// operands as in the code, durations as times, comments after ';' or '#'.
class PropertyLexer : public PlutoLexer {
    Q_OBJECT
public:
    explicit PropertyLexer(QObject* parent = nullptr);

    const char* language() const override;

protected:
    void styleLine(std::string_view line) override;
};

} // namespace rs::ui
