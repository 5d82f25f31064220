// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "text/PlutoLexer.h"

namespace rs::ui {

// Colours PL110 program text (docs/pl110.md) with the program text's
// colours: directives, declarations, the text form's keywords, addresses as
// the PL110's address reader reads them (a malformed one as invalid), time
// bases, numbers, names and comments.
class Pl110Lexer : public PlutoLexer {
    Q_OBJECT
public:
    explicit Pl110Lexer(QObject* parent = nullptr);

    const char* language() const override;

protected:
    void styleLine(std::string_view line) override;
};

} // namespace rs::ui
