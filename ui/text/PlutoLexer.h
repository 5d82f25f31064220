// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <Qsci/qscilexercustom.h>

#include <string_view>

namespace rs::ui {

// Colours Pluto program text. Words are classified with the language core's
// own lexer and address reader, so what is coloured as an address is exactly
// what the parser reads as one. Pluto has no construct that spans lines, so
// every line is styled on its own.
class PlutoLexer : public QsciLexerCustom {
    Q_OBJECT
public:
    enum Style {
        Default = 0,
        Comment,
        Record,        // ";@unit 00 description=..." structured comments
        Declaration,   // '!' and id_pluto, type_pluto, pgm_pluto
        Option,        // I/O options, unit types and instruction sets in declarations
        Directive,     // '$' and the directive's name
        DirectiveText, // the directive's free text
        StepHeader,    // S0.1_2
        Address,       // I0.0, DR0.4.Lo, ASi0.1B.2
        Keyword,       // P N S R T J TON TPS TOF IT before '('
        Time,          // 5s10
        Number,
        Operator,
        Name,    // symbolic names
        Invalid, // characters and address-shaped words the language rejects
        StyleCount
    };

    explicit PlutoLexer(QObject* parent = nullptr);

    const char* language() const override;
    QString description(int style) const override;
    QColor defaultColor(int style) const override;
    QColor defaultPaper(int style) const override;
    QFont defaultFont(int style) const override;
    // Addresses hold dots ("DR0.4.Lo"): a double-click selects the whole word.
    const char* wordCharacters() const override;

    void styleText(int start, int end) override;

    // Colours for a dark background instead of a light one.
    void setDark(bool dark);

protected:
    // Styles one line, without its end, from where the styling stands.
    virtual void styleLine(std::string_view line);

private:
    bool m_dark = false;
};

} // namespace rs::ui
