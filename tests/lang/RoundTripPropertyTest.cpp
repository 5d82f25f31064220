// SPDX-License-Identifier: GPL-3.0-or-later
#include "RandomProgram.h"

#include "lang/Parser.h"
#include "lang/Printer.h"

#include <gtest/gtest.h>

using namespace rs;

// Thousands of random syntax trees: print, parse, and the tree comes back.
TEST(RoundTripProperty, PrintThenParseGivesTheSameTree) {
    for (unsigned seed = 1; seed <= 3000; ++seed) {
        test::RandomProgram generator(seed);
        const lang::Document document = generator.document();
        const std::string text = lang::print(document);
        const lang::ParseResult parsed = lang::parse(text);
        ASSERT_TRUE(parsed.diagnostics.empty())
            << "seed " << seed << ": " << parsed.diagnostics.front().line << ":"
            << parsed.diagnostics.front().column << ": " << parsed.diagnostics.front().message
            << "\n"
            << text;
        ASSERT_TRUE(parsed.document == document) << "seed " << seed << "\n" << text;
        ASSERT_EQ(lang::print(parsed.document), text) << "seed " << seed;
    }
}

// Random expressions, deep ones included, alone on a coil.
TEST(RoundTripProperty, DeepExpressionsSurvive) {
    test::RandomProgram generator(42);
    for (int i = 0; i < 3000; ++i) {
        lang::Statement statement;
        statement.target.address = {lang::AddressKind::Output, 0, 1};
        statement.condition = generator.expression(6);
        const std::string text =
            "! pgm_pluto:00\nS0.0_0\n" + lang::printStatement(statement) + "\n";
        const lang::ParseResult parsed = lang::parse(text);
        ASSERT_TRUE(parsed.diagnostics.empty()) << text << parsed.diagnostics.front().message;
        const auto& line = parsed.document.units[0].steps[0].lines.at(0);
        ASSERT_TRUE(std::get<lang::Statement>(line.body) == statement) << text;
    }
}
