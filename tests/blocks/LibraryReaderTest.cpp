// SPDX-License-Identifier: GPL-3.0-or-later
#include "blocks/LibraryReader.h"
#include "blocks/LibraryLimits.h"
#include "blocks/LibraryWriter.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

using namespace rs::blocks;

namespace {

const std::string kLibraryHead = "rungsmith-library 1\nlibrary Test\nversion 1.0\n";

// A block that reads without problems; tests change one line of it.
const std::string kCopyBlock = "block Copy\n"
                               "    kind macro\n"
                               "    version 2.1\n"
                               "    description en Copies In to Out.\n"
                               "    pin In in bit primary\n"
                               "    pin Out out bit primary\n"
                               "    timers 0\n"
                               "    body {Out} = {In}\n";

std::string problems(std::string_view text) {
    std::string out;
    for (const auto& diagnostic : readLibrary(text).diagnostics)
        out += rs::lang::formatDiagnostic("t.rslib", diagnostic) + "\n";
    return out;
}

// kLibraryHead + kCopyBlock with `from` replaced by `to`.
std::string changed(const std::string& from, const std::string& to) {
    std::string text = kLibraryHead + kCopyBlock;
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
}

} // namespace

TEST(LibraryReader, ReadsEveryField) {
    const std::string text = "# a comment, and blank lines, are ignored\n"
                             "\n"
                             "rungsmith-library 1\n"
                             "library Demo_1\n"
                             "version 3.0.1\n"
                             "description en A demo.\n"
                             "description sv En demo.\n"
                             "description de Eine Demo.\n"
                             "block Timed\n"
                             "  kind macro\n"
                             "  version 1.2\n"
                             "  description en First line.\n"
                             "  description en  Second, indented.\n"
                             "  description sv Första raden: åäö.\n"
                             "  description de Erste Zeile: äöüß.\n"
                             "  state 16#8001 en Waiting.\n"
                             "  state 16#c001 en  Failed, indented.\n"
                             "  state 16#8001 sv Väntar.\n"
                             "  state 16#8001 de Wartet.\n"
                             "  pin Start in bit primary operands=input,memory\n"
                             "  pin Delay in time secondary default=2s50\n"
                             "  pin Limit in register secondary default=-7 operands=number\n"
                             "  pin Big in double-register secondary default=100000\n"
                             "  pin K in constant secondary default=5\n"
                             "  pin Done out bit primary operands=output\n"
                             "  pin Count out register secondary\n"
                             "  private m memory\n"
                             "  private r register\n"
                             "  private d double-register\n"
                             "  timers 2\n"
                             "  body {#m} = {Start} * TON({Delay}) + {Start} * TPS(0s20)\n"
                             "  body ({#r} = {Limit})\n"
                             "  body\n"
                             "  body  ; a comment naming {Done}\n"
                             "  body ({#d} = {Big})\n"
                             "  body ({Count} = {K})\n"
                             "  body {Done} = {#m}\n"
                             "block Analog\n"
                             "  kind system\n"
                             "  version 1\n"
                             "  system ReadVoltage\n"
                             "  description en Reads a voltage.\n"
                             "  pin Input in register primary\n";
    const LibraryReadResult read = readLibrary(text);
    ASSERT_EQ(problems(text), "");
    const BlockLibrary& library = read.library;
    EXPECT_EQ(library.name, "Demo_1");
    EXPECT_EQ(library.version, "3.0.1");
    EXPECT_EQ(library.description.english, "A demo.");
    EXPECT_EQ(library.description.swedish, "En demo.");
    EXPECT_EQ(library.description.german, "Eine Demo.");
    ASSERT_EQ(library.blocks.size(), 2u);

    const BlockDefinition& timed = library.blocks[0];
    EXPECT_EQ(timed.name, "Timed");
    EXPECT_EQ(timed.kind, BlockKind::Macro);
    EXPECT_EQ(timed.version, "1.2");
    EXPECT_EQ(timed.description.english, "First line.\n Second, indented.");
    EXPECT_EQ(timed.description.in("sv"), "Första raden: åäö.");
    EXPECT_EQ(timed.description.in("de"), "Erste Zeile: äöüß.");
    EXPECT_EQ(timed.description.in("fr"), timed.description.english);
    ASSERT_EQ(timed.states.size(), 2u);
    EXPECT_EQ(timed.states[0], (StateMeaning{0x8001, {"Waiting.", "Väntar.", "Wartet."}}));
    EXPECT_EQ(timed.states[1], (StateMeaning{0xC001, {" Failed, indented.", "", ""}}));
    EXPECT_EQ(timed.states[1].meaning.in("de"), " Failed, indented.");
    ASSERT_EQ(timed.pins.size(), 7u);
    const Pin& start = timed.pins[0];
    EXPECT_EQ(start.name, "Start");
    EXPECT_EQ(start.direction, PinDirection::In);
    EXPECT_EQ(start.kind, PinKind::Bit);
    EXPECT_EQ(start.role, PinRole::Primary);
    EXPECT_FALSE(start.defaultValue);
    EXPECT_EQ(start.operands, (std::vector{OperandKind::Input, OperandKind::Memory}));
    const Pin& delay = timed.pins[1];
    EXPECT_EQ(delay.kind, PinKind::Time);
    EXPECT_EQ(delay.role, PinRole::Secondary);
    EXPECT_EQ(delay.defaultValue, "2s50");
    EXPECT_EQ(delay.operands, (std::vector{OperandKind::Register, OperandKind::TimeConstant}));
    EXPECT_EQ(timed.pins[2].kind, PinKind::Register);
    EXPECT_EQ(timed.pins[2].defaultValue, "-7");
    EXPECT_EQ(timed.pins[2].operands, std::vector{OperandKind::Number});
    EXPECT_EQ(timed.pins[3].kind, PinKind::DoubleRegister);
    EXPECT_EQ(timed.pins[4].kind, PinKind::Constant);
    EXPECT_EQ(timed.pins[5].direction, PinDirection::Out);
    EXPECT_EQ(timed.pins[6].operands,
              (std::vector{OperandKind::Register, OperandKind::SystemRegister}));
    EXPECT_EQ(timed.findPin("DELAY"), &timed.pins[1]);
    ASSERT_EQ(timed.privates.size(), 3u);
    EXPECT_EQ(timed.privates[0], (PrivateVariable{"m", PrivateKind::Memory}));
    EXPECT_EQ(timed.privates[1].kind, PrivateKind::Register);
    EXPECT_EQ(timed.privates[2].kind, PrivateKind::DoubleRegister);
    EXPECT_EQ(timed.timers, 2);
    ASSERT_EQ(timed.body.size(), 7u);
    EXPECT_EQ(timed.body[2], "");
    EXPECT_EQ(timed.body[3], " ; a comment naming {Done}");

    const BlockDefinition& analog = library.blocks[1];
    EXPECT_EQ(analog.kind, BlockKind::System);
    EXPECT_EQ(analog.systemInstruction, "ReadVoltage");
    EXPECT_TRUE(analog.body.empty());
    EXPECT_EQ(library.findBlock("analog"), &analog);

    // The canonical text reads back to the same model; the states come after
    // the description, each code's languages together, the code upper case.
    const std::string written = writeLibrary(library);
    EXPECT_NE(written.find("    description de Erste Zeile: äöüß.\n"
                           "    state 16#8001 en Waiting.\n"
                           "    state 16#8001 sv Väntar.\n"
                           "    state 16#8001 de Wartet.\n"
                           "    state 16#C001 en  Failed, indented.\n"
                           "    pin Start "),
              std::string::npos)
        << written;
    EXPECT_EQ(readLibrary(written).library, library);
}

TEST(LibraryReader, AcceptsByteOrderMarkAndCrLf) {
    std::string text = "\xEF\xBB\xBF" + kLibraryHead + kCopyBlock;
    std::string crlf;
    for (char c : text)
        crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    EXPECT_EQ(problems(crlf), "");
    EXPECT_EQ(readLibrary(crlf).library, readLibrary(kLibraryHead + kCopyBlock).library);
}

struct BadCase {
    std::string from;
    std::string to;
    std::string expected;
};

TEST(LibraryReader, ReportsEachErrorAtItsLineAndColumn) {
    const BadCase cases[] = {
        {"    kind macro\n", "    kind macro\n    colour red\n",
         "t.rslib:6:5: error: unknown key 'colour'\n"},
        {"    kind macro", "    kind function",
         "t.rslib:5:10: error: unknown block kind 'function': macro or system\n"},
        {"    kind macro\n", "    kind macro\n    kind system\n",
         "t.rslib:6:5: error: 'kind' given twice (first at line 5)\n"},
        {"    pin Out out bit primary\n",
         "    pin Out out bit primary\n    pin out in bit primary\n",
         "t.rslib:10:9: error: pin 'out' is declared twice (as 'Out' before)\n"},
        {"block Copy\n",
         "block Copy\n    kind macro\n    version 1\n    description en x\n"
         "    pin A in bit primary\n    body Q0.0 = {A}\nblock COPY\n",
         "t.rslib:10:7: error: block 'COPY' is defined twice (as 'Copy' before)\n"},
        {"body {Out} = {In}", "body {Out} = {Inn}",
         "t.rslib:11:18: error: '{Inn}' names no pin of the block\n"},
        {"body {Out} = {In}", "body {Out} = {#x} * {In}",
         "t.rslib:11:18: error: '{#x}' names no private variable of the block\n"},
        {"body {Out} = {In}", "body {Out} = {In} *",
         "t.rslib:11:24: error: expected an operand after '*'\n"},
        {"body {Out} = {In}", "body {Out} = {In",
         "t.rslib:11:21: error: placeholder without its closing '}'\n"},
        {"body {Out} = {In}", "body {Out} = {In}\n    body S0.1_0",
         "t.rslib:12:10: error: a block's body holds statements only, no declarations, "
         "directives or step headers\n"},
        {"body {Out} = {In}", "body {Out} = {In}\n    body J(+1) = {In}",
         "t.rslib:12:10: error: a block's body cannot jump or reset a sequence: the step around "
         "an instance decides that\n"},
        {"body {Out} = {In}", "body ;@end",
         "t.rslib:11:10: error: ';@' records belong to the project, not to a block's body\n"},
        {"body {Out} = {In}", "body {Out} = TON(1s00) * {In}",
         "t.rslib:10:1: error: the body of 'Copy' holds 1 timer: write 'timers 1'\n"},
        {"    pin In in bit primary", "    pin In in bit primary default=2",
         "t.rslib:8:35: error: bad default '2': a bit's default is 0 or 1\n"},
        {"    pin Out out bit primary", "    pin Out out bit primary default=1",
         "t.rslib:9:29: error: an output pin has no default\n"},
        {"    pin In in bit primary", "    pin In in bit primary operands=number",
         "t.rslib:8:36: error: a bit input cannot take 'number'\n"},
        {"    pin In in bit primary", "    pin In in bit primary operands=input,bogus",
         "t.rslib:8:42: error: unknown operand kind 'bogus'\n"},
        {"    pin In in bit primary", "    pin In in bit primary colour=red",
         "t.rslib:8:27: error: unknown pin attribute 'colour=red': default=VALUE or "
         "operands=KIND,...\n"},
        {"    pin In in bit primary", "    pin In sideways bit primary",
         "t.rslib:8:12: error: unknown direction 'sideways': in or out\n"},
        {"    pin In in bit primary", "    pin 1n in bit primary",
         "t.rslib:8:9: error: bad pin name '1n': a letter, then letters, digits and '_' (ASCII)\n"},
        {"    description en Copies In to Out.\n", "    description fr Copie.\n",
         "t.rslib:7:17: error: unknown language 'fr': en, sv or de\n"
         "t.rslib:4:7: error: block 'Copy' has no English description: write 'description en "
         "TEXT'\n"},
        {"    version 2.1", "    version 2..1",
         "t.rslib:6:13: error: bad version '2..1': numbers separated by '.', at most 20 "
         "characters\n"},
        {"    kind macro", "    kind macro\n    system Foo",
         "t.rslib:6:1: error: a macro block calls no system instruction\n"},
        {"    kind macro", "    kind system",
         "t.rslib:4:7: error: system block 'Copy' names no instruction: write 'system NAME'\n"},
        {"version 1.0\n", "version 1.0\npin A in bit primary\n",
         "t.rslib:4:1: error: 'pin' belongs to a block: write 'block NAME' first\n"},
        {"    pin In in bit primary", "    pin In\tin bit primary",
         "t.rslib:8:11: error: control character \\t: a library holds printable text and spaces "
         "only\n"},
        {"Out.\n", "Out.\n    state 8001 en Waiting.\n",
         "t.rslib:8:11: error: bad state code '8001': 16# and four hex digits, 16#0000 to "
         "16#FFFF\n"},
        {"Out.\n", "Out.\n    state 16#10000 en Waiting.\n",
         "t.rslib:8:11: error: bad state code '16#10000': 16# and four hex digits, 16#0000 to "
         "16#FFFF\n"},
        {"Out.\n", "Out.\n    state 16#80G1 en Waiting.\n",
         "t.rslib:8:11: error: bad state code '16#80G1': 16# and four hex digits, 16#0000 to "
         "16#FFFF\n"},
        {"Out.\n", "Out.\n    state 16#8001\n",
         "t.rslib:8:18: error: expected a language: en, sv or de\n"},
        {"Out.\n", "Out.\n    state 16#8001 fr Attend.\n",
         "t.rslib:8:19: error: unknown language 'fr': en, sv or de\n"},
        {"Out.\n", "Out.\n    state 16#8001 en   \n",
         "t.rslib:8:21: error: expected what state 16#8001 means\n"},
        {"Out.\n",
         "Out.\n    state 16#800a en Waiting.\n    state 16#800A sv Väntar.\n"
         "    state 16#800A sv Väntar igen.\n",
         "t.rslib:10:19: error: the sv meaning of state 16#800A is given twice (first at line "
         "9)\n"},
        {"Out.\n",
         "Out.\n    state 16#8001 en Waiting.\n    state 16#C001 sv Fel.\n"
         "    state 16#C001 de Fehler.\n",
         "t.rslib:9:19: error: state 16#C001 has no English meaning: write 'state 16#C001 en "
         "TEXT'\n"},
        {"version 1.0\n", "version 1.0\nstate 16#8001 en Waiting.\n",
         "t.rslib:4:1: error: 'state' belongs to a block: write 'block NAME' first\n"},
        {"Copies In to Out.", "Copies \xC3 to Out.",
         "t.rslib:7:27: error: invalid UTF-8: the file must be UTF-8 text\n"},
    };
    for (const BadCase& bad : cases)
        EXPECT_EQ(problems(changed(bad.from, bad.to)), bad.expected) << bad.to;
}

TEST(LibraryReader, NeedsTheHeaderNameAndVersion) {
    EXPECT_EQ(problems(""), "t.rslib:1:1: error: a library starts with 'rungsmith-library 1'\n");
    EXPECT_EQ(problems("library X\nversion 1\n"),
              "t.rslib:1:1: error: a library starts with 'rungsmith-library 1'\n");
    EXPECT_EQ(problems("rungsmith-library 1\n"),
              "t.rslib:1:1: error: the library has no name: write 'library NAME'\n"
              "t.rslib:1:1: error: the library has no version: write 'version N.N'\n");
    EXPECT_EQ(problems("rungsmith-library 1\nlibrary A\nlibrary B\nversion 1\n"),
              "t.rslib:3:1: error: 'library' given twice (first at line 2)\n");
    EXPECT_EQ(problems(kLibraryHead + "block X\n"),
              "t.rslib:4:7: error: block 'X' has no kind: write 'kind macro' or 'kind system'\n"
              "t.rslib:4:7: error: block 'X' has no version: write 'version N.N'\n"
              "t.rslib:4:7: error: block 'X' has no English description: write 'description en "
              "TEXT'\n"
              "t.rslib:4:7: error: macro block 'X' has no body: write 'body STATEMENT' lines\n");
}

TEST(LibraryReader, ReportsColumnsInCharacters) {
    // "åäö" are two bytes each: the bad placeholder is still at character 29.
    EXPECT_EQ(problems(changed("body {Out} = {In}", "body {Out} = {In} ; åäö {Nope}")),
              "t.rslib:11:29: error: '{Nope}' names no pin of the block\n");
}

TEST(LibraryReader, EnforcesItsLimits) {
    EXPECT_EQ(problems(std::string(kMaxLibraryBytes + 1, '#')),
              "t.rslib:1:1: error: the library is larger than 4194304 bytes\n");
    EXPECT_EQ(problems(kLibraryHead + "#" + std::string(kMaxLineBytes, 'x') + "\n"),
              "t.rslib:4:4001: error: the line is longer than 4000 bytes\n");
    EXPECT_EQ(problems(changed("block Copy", "block " + std::string(41, 'B'))),
              "t.rslib:4:7: error: block name '" + std::string(41, 'B') +
                  "' is longer than 40 characters\n");
    EXPECT_EQ(problems(changed("pin In ", "pin " + std::string(33, 'P') + " ")),
              "t.rslib:8:9: error: pin name '" + std::string(33, 'P') +
                  "' is longer than 32 characters\n");

    std::string blocks = kLibraryHead;
    for (std::size_t i = 0; i <= kMaxBlocks; ++i)
        blocks += "block B" + std::to_string(i) +
                  "\nkind macro\nversion 1\ndescription en x\nbody Q0.0 = I0.0\n";
    const LibraryReadResult many = readLibrary(blocks);
    EXPECT_EQ(many.library.blocks.size(), kMaxBlocks);
    ASSERT_EQ(many.diagnostics.size(), 1u);
    EXPECT_EQ(many.diagnostics[0].message, "more than 1000 blocks in one library");
    EXPECT_EQ(many.diagnostics[0].line, 4 + 5 * static_cast<int>(kMaxBlocks));

    std::string pins;
    for (std::size_t i = 0; i <= kMaxPins; ++i)
        pins += "    pin P" + std::to_string(i) + " in bit primary\n";
    const std::string tooManyPins = changed("    pin In in bit primary\n", pins);
    const LibraryReadResult wide = readLibrary(tooManyPins);
    ASSERT_FALSE(wide.ok());
    EXPECT_EQ(wide.diagnostics[0].message, "more than 64 pins in one block");
    EXPECT_EQ(wide.diagnostics[0].line, 8 + static_cast<int>(kMaxPins));

    std::string body;
    for (std::size_t i = 0; i <= kMaxBodyLines; ++i)
        body += "    body {Out} = {In}\n";
    const LibraryReadResult longBody = readLibrary(changed("    body {Out} = {In}\n", body));
    ASSERT_EQ(longBody.diagnostics.size(), 1u);
    EXPECT_EQ(longBody.diagnostics[0].message, "more than 2000 body lines in one block");

    EXPECT_EQ(problems(changed("timers 0", "timers 51")),
              "t.rslib:10:12: error: the number of timers is from 0 to 50\n");
}

TEST(LibraryReader, TheShippedLibrariesAreCanonicalAndClean) {
    for (const std::string name : {"Analog01", "Rungsmith_Basics", "Rungsmith_Safety",
                                   "Rungsmith_Speed", "Rungsmith_System"}) {
        std::ifstream file(RUNGSMITH_LIBRARIES "/" + name + ".rslib", std::ios::binary);
        std::stringstream text;
        text << file.rdbuf();
        const LibraryReadResult read = readLibrary(text.str());
        EXPECT_TRUE(read.diagnostics.empty()) << problems(text.str());
        EXPECT_EQ(read.library.name, name);
        EXPECT_EQ(writeLibrary(read.library), text.str());
        for (const auto& block : read.library.blocks) {
            EXPECT_FALSE(block.description.swedish.empty()) << block.name;
            EXPECT_FALSE(block.description.german.empty()) << block.name;
        }
    }
}

TEST(LibraryReader, TheDocumentedExampleReadsWithoutProblems) {
    std::ifstream file(RUNGSMITH_DOCS "/block-libraries.md", std::ios::binary);
    std::stringstream text;
    text << file.rdbuf();
    const std::string doc = text.str();
    const std::size_t start = doc.find("```\n# Comments");
    ASSERT_NE(start, std::string::npos);
    const std::size_t end = doc.find("```\n", start + 4);
    const std::string example = doc.substr(start + 4, end - start - 4);
    const LibraryReadResult read = readLibrary(example);
    EXPECT_EQ(problems(example), "");
    ASSERT_EQ(read.library.blocks.size(), 3u);
    EXPECT_EQ(read.library.blocks[1].kind, BlockKind::System);
    EXPECT_EQ(read.library.blocks[2].states,
              (std::vector<StateMeaning>{{0x0000, {"stopped", "stoppad", "angehalten"}},
                                         {0x8000, {"running", "i drift", "in Betrieb"}}}));
}
