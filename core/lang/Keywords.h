// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Ast.h"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

// The language's words, spelled once: the printer writes them, the layout
// labels boxes with them, the editor's highlighter colours them. Words are
// given as the printer writes them; lookups ignore case, as the parser does.
namespace rs::lang {

// Instruction words, each written before '('.
inline constexpr std::string_view kRisingEdgeWord = "P";
inline constexpr std::string_view kFallingEdgeWord = "N";
inline constexpr std::string_view kSetWord = "S";
inline constexpr std::string_view kResetWord = "R"; // also a sequence's reset
inline constexpr std::string_view kToggleWord = "T";
inline constexpr std::string_view kJumpWord = "J";

std::string_view timerWord(TimerSpelling spelling);
std::optional<TimerSpelling> timerSpellingOf(std::string_view word);

// The word before '(' of a statement of the kind; empty for a coil and an assignment.
std::string_view statementWord(StatementKind kind);

// Every word written before '(', each once (the toggle's T is also a timer's).
const std::vector<std::string_view>& instructionWords();

// Declaration words: "! id_pluto:00=...", "! type_pluto:00=B46,is3", "! pgm_pluto:00".
std::string_view idKeyword(UnitFamily family);
std::optional<UnitFamily> familyOfIdKeyword(std::string_view word);
inline constexpr std::string_view kTypeKeyword = "type_pluto";
inline constexpr std::string_view kProgramKeyword = "pgm_pluto";
const std::vector<std::string_view>& declarationWords();

// "is2" / "is3" after a unit type; 0 for a word that is neither.
std::string_view instructionSetWord(int instructionSet);
int instructionSetOf(std::string_view word);

// Unit types after "type_pluto:NN=", in the order of rs::target::UnitType, which
// takes its names from here.
inline constexpr std::array<std::string_view, 13> kUnitTypeWords{
    "A16", "A20", "B16", "B20", "S20", "B22", "D20", "O2", "B46", "S46", "D45", "ASi", "B42_ASi"};
// Canonical spelling of a unit type ("b42_asi" -> "B42_ASi"), empty if unknown.
std::string canonicalUnitType(std::string_view type);

// I/O options after "! I0.5,": lower case, as written.
inline constexpr std::string_view kStaticOption = "static";
inline constexpr std::string_view kAPulseOption = "a_pulse";
inline constexpr std::string_view kBPulseOption = "b_pulse";
inline constexpr std::string_view kCPulseOption = "c_pulse";
inline constexpr std::string_view kNonInvertedOption = "non_inv";
inline constexpr std::string_view kNoFilterOption = "no_filt";
inline constexpr std::string_view kCrossTalkOption = "x_talk";
inline constexpr std::string_view kNoTestPulseOption = "no_test_pulse";
inline constexpr std::string_view kVoltageOption = "voltage";
inline constexpr std::string_view kCurrentOption = "current";
inline constexpr std::string_view kCounterUpOption = "counter_up";
inline constexpr std::string_view kCounterUpDownOption = "counter_updown";
inline constexpr std::array kIoOptionWords{
    kAPulseOption,      kBPulseOption,   kCPulseOption,    kStaticOption,
    kNonInvertedOption, kNoFilterOption, kCrossTalkOption, kNoTestPulseOption,
    kVoltageOption,     kCurrentOption,  kCounterUpOption, kCounterUpDownOption};
// Whether a lower-case word is one of kIoOptionWords.
bool isKnownIoOption(std::string_view option);

// Operators.
std::string_view compareWord(CompareOp op); // "=", ">", "<", ">=", "<="
std::string_view assignWord(AssignOp op);   // "++", "--", "+=", "-=", "*=", "/=", "="
std::string_view binaryWord(BinaryOp op);   // "+", "-", "*", "/"
std::optional<CompareOp> compareOpOf(std::string_view word);
std::optional<AssignOp> assignOpOf(std::string_view word); // "=" reads as Copy

} // namespace rs::lang
