// SPDX-License-Identifier: GPL-3.0-or-later
#include "LibraryReader.h"

#include "BodyCheck.h"
#include "BodyTemplate.h"
#include "LibraryLimits.h"
#include "LibraryWords.h"
#include "project/Utf8Text.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdint>
#include <map>
#include <optional>

namespace rs::blocks {

namespace {

constexpr std::string_view kHeader = "rungsmith-library 1";

// A word of a line and the byte where it starts.
struct Word {
    std::string_view text;
    std::size_t offset = 0;
};

std::vector<Word> splitWords(std::string_view line, std::size_t from) {
    std::vector<Word> words;
    std::size_t i = from;
    while (i < line.size()) {
        while (i < line.size() && line[i] == ' ')
            ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ')
            ++i;
        if (i > start)
            words.push_back({line.substr(start, i - start), start});
    }
    return words;
}

bool isVersion(std::string_view version) {
    if (version.empty() || version.front() == '.' || version.back() == '.')
        return false;
    for (std::size_t i = 0; i < version.size(); ++i) {
        const char c = version[i];
        if (c == '.' && version[i - 1] == '.')
            return false;
        if (c != '.' && (c < '0' || c > '9'))
            return false;
    }
    return true;
}

std::string checkDefault(PinKind kind, std::string_view value) {
    const auto number = canonicalInteger(value);
    switch (kind) {
    case PinKind::Bit:
        return value == "0" || value == "1" ? "" : "a bit's default is 0 or 1";
    case PinKind::Register:
        return number && *number >= -32768 && *number <= 32767
                   ? ""
                   : "a register's default is a number from -32768 to 32767";
    case PinKind::DoubleRegister:
    case PinKind::Constant:
        return number && *number >= INT32_MIN && *number <= INT32_MAX
                   ? ""
                   : "the default is a 32-bit number written without leading zeros";
    case PinKind::Time:
        return isTimeConstant(value) ? ""
                                     : "a time's default is a time constant from 0s00 to 655s35";
    }
    return {};
}

std::string quoted(std::string_view text) {
    return "'" + std::string(text) + "'";
}

// Where a state's records are, for the checks that need all of them.
struct StatePlace {
    int line = 0;                       // its first record
    int column = 1;                     // of that record's language
    std::array<int, 3> languageLines{}; // en, sv, de: the line of its meaning, 0 if none
};

// Where the reader found what it stores in the model, for problems found
// once a block is complete.
struct BlockPlaces {
    int line = 0;
    int nameColumn = 1;
    int timersLine = 0;
    std::vector<int> pinLines;
    std::vector<int> privateLines;
    std::vector<int> bodyLines;
    std::vector<int> bodyColumns; // character column of the body text's first byte
    int descriptionLines = 0;
    std::map<int, std::size_t> stateIndex; // by code, into BlockDefinition::states
    std::vector<StatePlace> statePlaces;   // as BlockDefinition::states
};

class Reader {
public:
    explicit Reader(std::string_view text) : m_text(text) {}

    LibraryReadResult read() {
        if (m_text.size() > kMaxLibraryBytes) {
            error(1, 1,
                  "the library is larger than " + std::to_string(kMaxLibraryBytes) + " bytes");
            return std::move(m_result);
        }
        if (m_text.substr(0, 3) == "\xEF\xBB\xBF")
            m_text.remove_prefix(3);
        if (const auto fault = project::findTextFault(m_text)) {
            const std::size_t lineStart = m_text.rfind('\n', fault->offset);
            const std::size_t begin = lineStart == std::string_view::npos ? 0 : lineStart + 1;
            const auto line =
                static_cast<int>(std::count(m_text.begin(), m_text.begin() + begin, '\n')) + 1;
            error(line, project::characterColumn(m_text.substr(begin), fault->offset - begin),
                  fault->message);
            return std::move(m_result);
        }
        std::size_t start = 0;
        int number = 0;
        while (start < m_text.size()) {
            std::size_t end = m_text.find('\n', start);
            if (end == std::string_view::npos)
                end = m_text.size();
            readLine(++number, m_text.substr(start, end - start));
            start = end + 1;
        }
        if (!m_sawHeader)
            error(1, 1, "a library starts with '" + std::string(kHeader) + "'");
        finishBlock();
        if (m_sawHeader && m_result.library.name.empty())
            error(m_headerLine, 1, "the library has no name: write 'library NAME'");
        if (m_sawHeader && m_result.library.version.empty())
            error(m_headerLine, 1, "the library has no version: write 'version N.N'");
        return std::move(m_result);
    }

private:
    void error(int line, int column, std::string message) {
        m_result.diagnostics.push_back({lang::Severity::Error, line, column, std::move(message)});
    }
    void warning(int line, int column, std::string message) {
        m_result.diagnostics.push_back({lang::Severity::Warning, line, column, std::move(message)});
    }
    int column(std::size_t offset) const { return project::characterColumn(m_line, offset); }

    void readLine(int number, std::string_view line) {
        if (!line.empty() && line.back() == '\r')
            line.remove_suffix(1);
        while (!line.empty() && line.back() == ' ')
            line.remove_suffix(1);
        m_line = line;
        m_number = number;
        if (line.size() > kMaxLineBytes) {
            error(number, column(kMaxLineBytes),
                  "the line is longer than " + std::to_string(kMaxLineBytes) + " bytes");
            return;
        }
        for (std::size_t i = 0; i < line.size(); ++i) {
            const auto c = static_cast<unsigned char>(line[i]);
            if (c < 0x20 || c == 0x7F) {
                error(number, column(i),
                      "control character " + lang::visibleText(line.substr(i, 1)) +
                          ": a library holds printable text and spaces only");
                return;
            }
        }
        std::size_t keyStart = 0;
        while (keyStart < line.size() && line[keyStart] == ' ')
            ++keyStart;
        if (keyStart == line.size() || line[keyStart] == '#')
            return;
        std::size_t keyEnd = line.find(' ', keyStart);
        if (keyEnd == std::string_view::npos)
            keyEnd = line.size();
        const std::string_view key = line.substr(keyStart, keyEnd - keyStart);
        if (!m_sawHeader) {
            if (line.substr(keyStart) != kHeader) {
                error(number, column(keyStart),
                      "a library starts with '" + std::string(kHeader) + "'");
                m_sawHeader = true; // said once; read the rest
                m_headerLine = number;
                readKey(key, keyStart, keyEnd);
                return;
            }
            m_sawHeader = true;
            m_headerLine = number;
            return;
        }
        readKey(key, keyStart, keyEnd);
    }

    void readKey(std::string_view key, std::size_t keyStart, std::size_t keyEnd) {
        const std::vector<Word> words = splitWords(m_line, keyEnd);
        if (key == "block")
            return startBlock(words, keyStart);
        if (key == "description")
            return readDescription(keyEnd);
        if (!m_block) {
            if (key == "library")
                return readName(words, keyStart, m_result.library.name, kMaxNameLength,
                                m_libraryNameLine);
            if (key == "version")
                return readVersion(words, keyStart, m_result.library.version, m_libraryVersionLine);
            if (isBlockKey(key)) {
                error(m_number, column(keyStart),
                      quoted(key) + " belongs to a block: write 'block NAME' first");
                return;
            }
        } else {
            if (key == "kind")
                return readKind(words, keyStart);
            if (key == "version")
                return readVersion(words, keyStart, m_block->version, m_blockVersionLine);
            if (key == "pin")
                return readPin(words, keyStart);
            if (key == "private")
                return readPrivate(words, keyStart);
            if (key == "timers")
                return readTimers(words, keyStart);
            if (key == "system")
                return readSystem(words, keyStart);
            if (key == "body")
                return readBody(keyEnd);
            if (key == "state")
                return readState(words);
            if (key == "library") {
                error(m_number, column(keyStart), "'library' comes before the first block");
                return;
            }
        }
        error(m_number, column(keyStart), "unknown key " + quoted(key));
    }

    static bool isBlockKey(std::string_view key) {
        return key == "kind" || key == "pin" || key == "private" || key == "timers" ||
               key == "system" || key == "body" || key == "state";
    }

    // One word after the key; an error and false otherwise.
    bool oneWord(const std::vector<Word>& words, std::string_view what) {
        if (words.empty()) {
            error(m_number, column(m_line.size()), "expected " + std::string(what));
            return false;
        }
        if (words.size() > 1) {
            error(m_number, column(words[1].offset),
                  "unexpected " + quoted(words[1].text) + " after " + std::string(what));
            return false;
        }
        return true;
    }

    bool givenOnce(int& seenLine, std::string_view key, std::size_t keyStart) {
        if (seenLine != 0) {
            error(m_number, column(keyStart),
                  quoted(key) + " given twice (first at line " + std::to_string(seenLine) + ")");
            return false;
        }
        seenLine = m_number;
        return true;
    }

    bool checkName(const Word& word, std::size_t maxLength, std::string_view what) {
        if (!isLibraryName(word.text)) {
            error(m_number, column(word.offset),
                  "bad " + std::string(what) + " " + quoted(word.text) +
                      ": a letter, then letters, digits and '_' (ASCII)");
            return false;
        }
        if (word.text.size() > maxLength) {
            error(m_number, column(word.offset),
                  std::string(what) + " " + quoted(word.text) + " is longer than " +
                      std::to_string(maxLength) + " characters");
            return false;
        }
        return true;
    }

    void readName(const std::vector<Word>& words, std::size_t keyStart, std::string& name,
                  std::size_t maxLength, int& seenLine) {
        if (!givenOnce(seenLine, "library", keyStart) || !oneWord(words, "a name"))
            return;
        if (checkName(words[0], maxLength, "library name"))
            name = std::string(words[0].text);
    }

    void readVersion(const std::vector<Word>& words, std::size_t keyStart, std::string& version,
                     int& seenLine) {
        if (!givenOnce(seenLine, "version", keyStart) || !oneWord(words, "a version"))
            return;
        const Word& word = words[0];
        if (!isVersion(word.text) || word.text.size() > kMaxVersionLength) {
            error(m_number, column(word.offset),
                  "bad version " + quoted(word.text) + ": numbers separated by '.', at most " +
                      std::to_string(kMaxVersionLength) + " characters");
            return;
        }
        version = std::string(word.text);
    }

    void readDescription(std::size_t keyEnd) {
        const std::vector<Word> words = splitWords(m_line, keyEnd);
        if (words.empty()) {
            error(m_number, column(m_line.size()), "expected a language: en, sv or de");
            return;
        }
        const Word& language = words[0];
        Description& description = m_block ? m_block->description : m_result.library.description;
        std::string* text = language.text == "en"   ? &description.english
                            : language.text == "sv" ? &description.swedish
                            : language.text == "de" ? &description.german
                                                    : nullptr;
        if (!text) {
            error(m_number, column(language.offset),
                  "unknown language " + quoted(language.text) + ": en, sv or de");
            return;
        }
        int& count = m_block ? m_places.descriptionLines : m_libraryDescriptionLines;
        if (++count > static_cast<int>(kMaxDescriptionLines)) {
            if (count == static_cast<int>(kMaxDescriptionLines) + 1)
                error(m_number, column(language.offset),
                      "more than " + std::to_string(kMaxDescriptionLines) + " description lines");
            return;
        }
        const std::size_t textStart = language.offset + language.text.size() + 1;
        const std::string_view line =
            textStart <= m_line.size() ? m_line.substr(textStart) : std::string_view();
        // A language's lines follow each other; the first starts the text.
        const bool continues = m_lastDescription == text && m_lastDescriptionLine == m_number - 1;
        if (!text->empty() || continues)
            if (!continues) {
                error(m_number, column(language.offset),
                      "the " + std::string(language.text) +
                          " description is given twice: write its lines one after the other");
                return;
            }
        if (continues)
            *text += '\n';
        *text += line;
        m_lastDescription = text;
        m_lastDescriptionLine = m_number;
    }

    // `state CODE LANG TEXT`: one line per code and language, so unlike a
    // description a meaning is one line and given once.
    void readState(const std::vector<Word>& words) {
        if (words.empty()) {
            error(m_number, column(m_line.size()), "expected a state code: 16#8001");
            return;
        }
        const Word& codeWord = words[0];
        const std::optional<int> code = stateCodeOf(codeWord.text);
        if (!code) {
            error(m_number, column(codeWord.offset),
                  "bad state code " + quoted(codeWord.text) +
                      ": 16# and four hex digits, 16#0000 to 16#FFFF");
            return;
        }
        if (words.size() < 2) {
            error(m_number, column(m_line.size()), "expected a language: en, sv or de");
            return;
        }
        const Word& language = words[1];
        const int slot = language.text == "en"   ? 0
                         : language.text == "sv" ? 1
                         : language.text == "de" ? 2
                                                 : -1;
        if (slot < 0) {
            error(m_number, column(language.offset),
                  "unknown language " + quoted(language.text) + ": en, sv or de");
            return;
        }
        const std::size_t textStart = language.offset + language.text.size() + 1;
        if (textStart >= m_line.size()) {
            error(m_number, column(m_line.size()),
                  "expected what state " + stateCodeWord(*code) + " means");
            return;
        }
        const auto [found, added] = m_places.stateIndex.try_emplace(*code, m_block->states.size());
        if (added) {
            m_block->states.push_back({*code, {}});
            m_places.statePlaces.push_back({m_number, column(language.offset), {}});
        }
        int& seen = m_places.statePlaces[found->second].languageLines[slot];
        if (seen != 0) {
            error(m_number, column(language.offset),
                  "the " + std::string(language.text) + " meaning of state " +
                      stateCodeWord(*code) + " is given twice (first at line " +
                      std::to_string(seen) + ")");
            return;
        }
        seen = m_number;
        Description& meaning = m_block->states[found->second].meaning;
        std::string& text = slot == 0   ? meaning.english
                            : slot == 1 ? meaning.swedish
                                        : meaning.german;
        text = std::string(m_line.substr(textStart));
    }

    void startBlock(const std::vector<Word>& words, std::size_t keyStart) {
        finishBlock();
        if (!oneWord(words, "a block name"))
            return skipBlock();
        if (!checkName(words[0], kMaxNameLength, "block name"))
            return skipBlock();
        if (m_result.library.blocks.size() >= kMaxBlocks) {
            error(m_number, column(keyStart),
                  "more than " + std::to_string(kMaxBlocks) + " blocks in one library");
            return skipBlock();
        }
        if (const BlockDefinition* other = m_result.library.findBlock(words[0].text)) {
            error(m_number, column(words[0].offset),
                  "block " + quoted(words[0].text) + " is defined twice (as " +
                      quoted(other->name) + " before)");
        }
        m_block = BlockDefinition{};
        m_block->name = std::string(words[0].text);
        m_places = BlockPlaces{};
        m_places.line = m_number;
        m_places.nameColumn = column(words[0].offset);
        m_kindLine = m_blockVersionLine = m_systemLine = 0;
        m_lastDescription = nullptr;
        m_errorsBeforeBlock = lang::errorCount(m_result.diagnostics);
    }

    // A block line that cannot start a block: its keys are read into a block
    // that is thrown away, so they are still checked but reported once.
    void skipBlock() {
        m_block = BlockDefinition{};
        m_places = BlockPlaces{};
        m_places.line = m_number;
        m_discard = true;
        m_kindLine = m_blockVersionLine = m_systemLine = 0;
    }

    void readKind(const std::vector<Word>& words, std::size_t keyStart) {
        if (!givenOnce(m_kindLine, "kind", keyStart) || !oneWord(words, "macro or system"))
            return;
        const auto kind = blockKindOf(words[0].text);
        if (!kind) {
            error(m_number, column(words[0].offset),
                  "unknown block kind " + quoted(words[0].text) + ": macro or system");
            return;
        }
        m_block->kind = *kind;
    }

    void readSystem(const std::vector<Word>& words, std::size_t keyStart) {
        if (!givenOnce(m_systemLine, "system", keyStart) ||
            !oneWord(words, "a system instruction's name"))
            return;
        if (checkName(words[0], kMaxNameLength, "system instruction"))
            m_block->systemInstruction = std::string(words[0].text);
    }

    void readTimers(const std::vector<Word>& words, std::size_t keyStart) {
        if (!givenOnce(m_places.timersLine, "timers", keyStart) ||
            !oneWord(words, "a number of timers"))
            return;
        const auto count = canonicalInteger(words[0].text);
        if (!count || *count < 0 || *count > kMaxTimers) {
            error(m_number, column(words[0].offset),
                  "the number of timers is from 0 to " + std::to_string(kMaxTimers));
            return;
        }
        m_block->timers = static_cast<int>(*count);
    }

    void readPin(const std::vector<Word>& words, std::size_t keyStart) {
        if (m_block->pins.size() >= kMaxPins) {
            if (m_block->pins.size() == kMaxPins)
                error(m_number, column(keyStart),
                      "more than " + std::to_string(kMaxPins) + " pins in one block");
            m_block->pins.push_back({}); // counts the pins past the limit once
            m_places.pinLines.push_back(m_number);
            return;
        }
        if (words.size() < 4) {
            error(m_number, column(m_line.size()),
                  "a pin is 'pin NAME in|out KIND primary|secondary [default=V] [operands=...]'");
            return;
        }
        Pin pin;
        if (!checkName(words[0], kMaxPinNameLength, "pin name"))
            return;
        pin.name = std::string(words[0].text);
        if (const Pin* other = m_block->findPin(pin.name)) {
            error(m_number, column(words[0].offset),
                  "pin " + quoted(pin.name) + " is declared twice (as " + quoted(other->name) +
                      " before)");
            return;
        }
        const auto direction = pinDirectionOf(words[1].text);
        if (!direction) {
            error(m_number, column(words[1].offset),
                  "unknown direction " + quoted(words[1].text) + ": in or out");
            return;
        }
        pin.direction = *direction;
        const auto kind = pinKindOf(words[2].text);
        if (!kind) {
            error(m_number, column(words[2].offset),
                  "unknown pin kind " + quoted(words[2].text) +
                      ": bit, register, double-register, time or constant");
            return;
        }
        pin.kind = *kind;
        if (pin.kind == PinKind::Constant && pin.direction == PinDirection::Out) {
            error(m_number, column(words[2].offset), "a constant pin is an input");
            return;
        }
        const auto role = pinRoleOf(words[3].text);
        if (!role) {
            error(m_number, column(words[3].offset),
                  "unknown pin role " + quoted(words[3].text) + ": primary or secondary");
            return;
        }
        pin.role = *role;
        const std::vector<OperandKind> possible = possibleOperands(pin.kind, pin.direction);
        bool sawOperands = false;
        for (std::size_t i = 4; i < words.size(); ++i) {
            const Word& word = words[i];
            const std::size_t equals = word.text.find('=');
            const std::string_view attribute = word.text.substr(0, equals);
            const std::string_view value = equals == std::string_view::npos
                                               ? std::string_view()
                                               : word.text.substr(equals + 1);
            const std::size_t valueOffset = word.offset + attribute.size() + 1;
            if (attribute == "default" && equals != std::string_view::npos) {
                if (pin.defaultValue) {
                    error(m_number, column(word.offset), "'default' given twice");
                    return;
                }
                if (pin.direction == PinDirection::Out) {
                    error(m_number, column(word.offset), "an output pin has no default");
                    return;
                }
                const std::string problem = checkDefault(pin.kind, value);
                if (!problem.empty()) {
                    error(m_number, column(valueOffset),
                          "bad default " + quoted(value) + ": " + problem);
                    return;
                }
                pin.defaultValue = std::string(value);
            } else if (attribute == "operands" && equals != std::string_view::npos) {
                if (sawOperands) {
                    error(m_number, column(word.offset), "'operands' given twice");
                    return;
                }
                sawOperands = true;
                if (!readOperands(pin, value, valueOffset, possible))
                    return;
            } else {
                error(m_number, column(word.offset),
                      "unknown pin attribute " + quoted(word.text) +
                          ": default=VALUE or operands=KIND,...");
                return;
            }
        }
        if (!sawOperands)
            pin.operands = possible;
        m_block->pins.push_back(std::move(pin));
        m_places.pinLines.push_back(m_number);
    }

    bool readOperands(Pin& pin, std::string_view list, std::size_t offset,
                      const std::vector<OperandKind>& possible) {
        std::size_t start = 0;
        while (true) {
            const std::size_t comma = list.find(',', start);
            const std::string_view word =
                list.substr(start, comma == std::string_view::npos ? comma : comma - start);
            const int at = column(offset + start);
            const auto kind = operandKindOf(word);
            if (!kind) {
                error(m_number, at, "unknown operand kind " + quoted(word));
                return false;
            }
            if (std::find(possible.begin(), possible.end(), *kind) == possible.end()) {
                error(m_number, at,
                      "a " + std::string(wordOf(pin.kind)) + " " +
                          (pin.direction == PinDirection::In ? "input" : "output") +
                          " cannot take " + quoted(word));
                return false;
            }
            if (std::find(pin.operands.begin(), pin.operands.end(), *kind) != pin.operands.end()) {
                error(m_number, at, "operand kind " + quoted(word) + " named twice");
                return false;
            }
            pin.operands.push_back(*kind);
            if (comma == std::string_view::npos)
                break;
            start = comma + 1;
        }
        std::sort(pin.operands.begin(), pin.operands.end());
        return true;
    }

    void readPrivate(const std::vector<Word>& words, std::size_t keyStart) {
        if (m_block->privates.size() >= kMaxPrivates) {
            if (m_block->privates.size() == kMaxPrivates)
                error(m_number, column(keyStart),
                      "more than " + std::to_string(kMaxPrivates) +
                          " private variables in one block");
            m_block->privates.push_back({});
            m_places.privateLines.push_back(m_number);
            return;
        }
        if (words.size() != 2) {
            error(m_number, column(words.size() > 2 ? words[2].offset : m_line.size()),
                  "a private variable is 'private NAME memory|register|double-register'");
            return;
        }
        if (!checkName(words[0], kMaxPinNameLength, "private variable name"))
            return;
        if (const PrivateVariable* other = m_block->findPrivate(words[0].text)) {
            error(m_number, column(words[0].offset),
                  "private variable " + quoted(words[0].text) + " is declared twice (as " +
                      quoted(other->name) + " before)");
            return;
        }
        const auto kind = privateKindOf(words[1].text);
        if (!kind) {
            error(m_number, column(words[1].offset),
                  "unknown private variable kind " + quoted(words[1].text) +
                      ": memory, register or double-register");
            return;
        }
        m_block->privates.push_back({std::string(words[0].text), *kind});
        m_places.privateLines.push_back(m_number);
    }

    void readBody(std::size_t keyEnd) {
        if (m_block->body.size() >= kMaxBodyLines) {
            if (m_block->body.size() == kMaxBodyLines)
                error(m_number, 1,
                      "more than " + std::to_string(kMaxBodyLines) + " body lines in one block");
            m_block->body.emplace_back();
            m_places.bodyLines.push_back(m_number);
            m_places.bodyColumns.push_back(1);
            return;
        }
        const std::size_t textStart = std::min(keyEnd + 1, m_line.size());
        const std::string_view text = m_line.substr(textStart);
        const std::size_t first = text.find_first_not_of(' ');
        if (first != std::string_view::npos && text.substr(first, 2) == ";@") {
            error(m_number, column(textStart + first),
                  "';@' records belong to the project, not to a block's body");
        }
        m_block->body.emplace_back(text);
        m_places.bodyLines.push_back(m_number);
        m_places.bodyColumns.push_back(column(textStart));
    }

    // Checks what needs the whole block, then keeps it.
    void finishBlock() {
        if (!m_block)
            return;
        BlockDefinition block = std::move(*m_block);
        m_block.reset();
        if (m_discard) {
            m_discard = false;
            return;
        }
        const int line = m_places.line;
        const int at = m_places.nameColumn;
        const std::string name = quoted(block.name);
        if (m_kindLine == 0)
            error(line, at, "block " + name + " has no kind: write 'kind macro' or 'kind system'");
        if (m_blockVersionLine == 0)
            error(line, at, "block " + name + " has no version: write 'version N.N'");
        if (block.description.english.empty())
            error(line, at,
                  "block " + name + " has no English description: write 'description en TEXT'");
        if (block.kind == BlockKind::System && block.systemInstruction.empty() && m_kindLine != 0)
            error(line, at, "system block " + name + " names no instruction: write 'system NAME'");
        if (block.kind == BlockKind::Macro && m_systemLine != 0)
            error(m_systemLine, 1, "a macro block calls no system instruction");
        if (block.kind == BlockKind::Macro && block.body.empty())
            error(line, at, "macro block " + name + " has no body: write 'body STATEMENT' lines");
        for (std::size_t i = 0; i < block.states.size(); ++i)
            if (const StatePlace& place = m_places.statePlaces[i]; place.languageLines[0] == 0) {
                const std::string code = stateCodeWord(block.states[i].code);
                error(place.line, place.column,
                      "state " + code + " has no English meaning: write 'state " + code +
                          " en TEXT'");
            }
        // A body over a bad pin or variable would only repeat its problem.
        if (lang::errorCount(m_result.diagnostics) > m_errorsBeforeBlock)
            return;

        const BodyCheckResult checked = checkBody(block);
        for (const BodyProblem& problem : checked.problems)
            error(m_places.bodyLines[problem.bodyLine],
                  m_places.bodyColumns[problem.bodyLine] + problem.column - 1, problem.message);
        if (!checked.problems.empty())
            return;
        if (checked.timers != block.timers) {
            const std::string count = std::to_string(checked.timers);
            error(m_places.timersLine != 0 ? m_places.timersLine : line, 1,
                  "the body of " + name + " holds " + count + " timer" +
                      (checked.timers == 1 ? "" : "s") + ": write 'timers " + count + "'");
        }
        for (std::size_t i = 0; i < block.pins.size(); ++i)
            if (!checked.pinUsed[i] && block.kind == BlockKind::Macro)
                warning(m_places.pinLines[i], 1,
                        "pin " + quoted(block.pins[i].name) + " is not used in the body");
        for (std::size_t i = 0; i < block.privates.size(); ++i)
            if (!checked.privateUsed[i])
                warning(m_places.privateLines[i], 1,
                        "private variable " + quoted(block.privates[i].name) +
                            " is not used in the body");
        m_result.library.blocks.push_back(std::move(block));
    }

    std::string_view m_text;
    std::string_view m_line;
    int m_number = 0;
    bool m_sawHeader = false;
    int m_headerLine = 1;
    int m_libraryNameLine = 0;
    int m_libraryVersionLine = 0;
    int m_libraryDescriptionLines = 0;
    std::optional<BlockDefinition> m_block;
    BlockPlaces m_places;
    bool m_discard = false;
    int m_errorsBeforeBlock = 0;
    int m_kindLine = 0;
    int m_blockVersionLine = 0;
    int m_systemLine = 0;
    const std::string* m_lastDescription = nullptr;
    int m_lastDescriptionLine = 0;
    LibraryReadResult m_result;
};

} // namespace

LibraryReadResult readLibrary(std::string_view text) {
    return Reader(text).read();
}

} // namespace rs::blocks
