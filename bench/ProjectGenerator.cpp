// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProjectGenerator.h"

#include "lang/Printer.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <map>
#include <random>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace rs::bench {

namespace {

// The address plan of every unit keeps each kind of use in its own range, as
// a careful programmer would, so the code reads like a real program:
constexpr int kMaxTimers = 50;            // per unit, the PLC's limit
constexpr int kMainMemories = 500;        // M0..M499: coils of the main code
constexpr int kSequenceMemoryBase = 500;  // M500..M598: coils of the steps
constexpr int kMemoriesPerSequence = 11;  //   11 for each of the at most 9 sequences
constexpr int kMaxSequences = 9;          // sequences 1..9
constexpr int kGlobalMemories = 12;       // GM0..GM11
constexpr int kRegisters = 120;           // R0..R119: 16-bit registers
constexpr int kDoubleRegisterBase = 120;  // DR120..DR138: R120..R139 used only through them
constexpr int kDoubleRegisters = 10;      //   DR120, DR122 .. DR138
constexpr int kBitRegisterBase = 140;     // R140..R149: used bit by bit
constexpr int kBitRegisters = 10;         //   R140 .. R149
constexpr int kPresetRegisterBase = 100;  // R100..R119 also hold timer presets
constexpr int kMaxStepsPerSequence = 200; // below the language's 255

struct Described {
    std::string_view name; // start of a symbolic name
    std::string_view description;
};

// Swedish entries because Pluto programs are often written in Swedish; they
// also take the lexer and the name folding off their ASCII fast paths.
constexpr std::array<Described, 12> kInputs{{
    {"EStop", "Emergency stop"},
    {"Nödstopp", "Nödstopp, manöverpanel"},
    {"LightCurtain", "Light curtain"},
    {"Ljusridå", "Ljusridå, inmatning"},
    {"DoorSwitch", "Guard door switch"},
    {"Grindbrytare", "Grindbrytare, bakre grind"},
    {"TwoHand", "Two-hand control"},
    {"MuteSensor", "Muting sensor"},
    {"EnableDevice", "Enabling device"},
    {"SafetyMat", "Safety mat"},
    {"RopeSwitch", "Rope pull switch"},
    {"KeySwitch", "Mode key switch"},
}};

constexpr std::array<Described, 4> kContactors{{
    {"Contactor", "Safety contactor"},
    {"Kontaktor", "Kontaktor, huvudmotor"},
    {"Valve", "Safety valve"},
    {"Brake", "Motor brake"},
}};

constexpr std::array<Described, 4> kGlobalMemoryNames{{
    {"CellReady", "Cell ready for the line"},
    {"ZoneClear", "Robot zone clear"},
    {"Handover", "Part handover"},
    {"Zonfri", "Zonen fri"},
}};

constexpr std::array<std::string_view, 4> kLamps{"Indicator lamp", "Horn", "Lampa, återställ",
                                                 "Status lamp"};
constexpr std::array<std::string_view, 3> kButtons{"Reset button with lamp", "Start button",
                                                   "Kvittering med lampa"};

constexpr std::array<std::string_view, 12> kMemoryWords{
    "Permit", "Interlock", "CycleOn", "GuardOk",  "Förregling", "Drift",
    "Fault",  "Ack",       "Restart", "AutoMode", "SetupMode",  "HoldToRun"};
constexpr std::array<std::string_view, 6> kRegisterWords{"PartCount", "Speed", "Räknare",
                                                         "Position",  "Delay", "Level"};
constexpr std::array<std::string_view, 2> kDoubleRegisterWords{"TotalCount", "Energy"};
constexpr std::array<std::string_view, 2> kBitRegisterWords{"Flags", "Status"};

constexpr std::array<std::string_view, 8> kCellKinds{"press line", "robot cell", "conveyor",
                                                     "palletiser", "packaging",  "svetscell",
                                                     "lackering",  "test stand"};

constexpr std::array<std::string_view, 15> kStatementComments{
    "Interlock with the guard door", "Start permit",
    "Förregling mot skyddsgrind",    "Restart inhibit",
    "Muting of the light curtain",   "Two-hand control",
    "Operator acknowledge",          "Återställning efter nödstopp",
    "Count finished parts",          "Conveyor running",
    "Both channels agree",           "Zone clear for the robot",
    "Lamp flashes while waiting",    "Stopp vid fel",
    "Feedback from the contactor"};

constexpr std::array<std::string_view, 12> kNetworkComments{
    "Emergency stop circuit", "Guard door interlocks",   "Light curtain with muting",
    "Nödstoppskrets",         "Conveyor control",        "Robot zone handover",
    "Press safety",           "Reset and restart logic", "Counters and statistics",
    "Lamp and horn",          "Skyddsgrindar",           "Hydraulic valves"};

constexpr std::array<std::string_view, 4> kExplanations{
    "The reset needs both channels released first.", "Outputs drop when either channel opens.",
    "Utgångarna släpper när någon kanal bryts.", "Muting ends when one sensor is free."};

constexpr std::array<std::string_view, 6> kSequenceNames{
    "Clamp and press cycle", "Muting sequence", "Door lock sequence",
    "Startsekvens",          "Robot handover",  "Test of the contactors"};

constexpr std::array<std::string_view, 7> kStepComments{
    "Wait for start", "Close clamp", "Press down",    "Vänta på grind",
    "Return",         "Release",     "Check feedback"};

constexpr std::array<std::string_view, 11> kSystemMemories{
    "SM_StepNew",     "SM_Ditto",   "SM_Flash",    "SM_1Hz",       "SM_10Hz",  "SM_FastFlash",
    "SM_DoubleFlash", "SM_SysInit", "SM_Overflow", "SM_DivByZero", "SM_Button"};

constexpr std::array<int, 14> kRoundPresets{10,  20,  50,   100,  150,  200,  250,
                                            300, 500, 1000, 1500, 3000, 6000, 65535};

constexpr std::array<std::string_view, 5> kCompareOps{"=", ">", "<", ">=", "<="};

// std::uniform_int_distribution differs between standard libraries; taking
// the engine's output (which the standard fixes) modulo n keeps a seed's
// project the same everywhere. The bias is irrelevant here.
class Random {
public:
    explicit Random(std::uint32_t seed) : m_engine(seed) {}

    int below(int n) { return static_cast<int>(m_engine() % static_cast<std::uint32_t>(n)); }
    int between(int low, int high) { return low + below(high - low + 1); }
    bool percent(int p) { return below(100) < p; }

    template <typename T> const T& pick(const std::vector<T>& items) {
        return items[static_cast<std::size_t>(below(static_cast<int>(items.size())))];
    }
    template <typename T, std::size_t N> const T& pick(const std::array<T, N>& items) {
        return items[static_cast<std::size_t>(below(static_cast<int>(N)))];
    }

private:
    std::mt19937 m_engine;
};

enum class Terminal : std::uint8_t { Input, Output, Button };

struct Unit {
    int station = 0;
    bool doubleFamily = false;
    std::array<std::size_t, 8> inputKinds{};  // kInputs entry of I0..I7
    std::array<Terminal, 8> upperTerminals{}; // roles of terminals 10..17
    std::vector<int> inputs;                  // terminals read as I
    std::vector<int> outputs;                 // terminals written as Q
    int sequences = 0;
    int timersLeft = kMaxTimers;
    bool networkRecords = false; // the IDE's ";@network" groups instead of plain comments
};

std::string twoDigits(int number) {
    char buffer[8];
    std::snprintf(buffer, sizeof buffer, "%02d", number);
    return buffer;
}

std::string address(std::string_view prefix, int unit, int index) {
    return std::string(prefix) + std::to_string(unit) + '.' + std::to_string(index);
}

std::string stepHeader(int unit, int sequence, int step) {
    return "S" + std::to_string(unit) + '.' + std::to_string(sequence) + '_' + std::to_string(step);
}

int characterCount(std::string_view text) {
    int count = 0;
    for (unsigned char c : text)
        if ((c & 0xC0) != 0x80)
            ++count;
    return count;
}

// Writes the text in the canonical printer's layout (comment column,
// spacing, upper-case addresses), so printing the parsed project gives the
// same bytes back and the print benchmark writes what the read one read.
class Generator {
public:
    explicit Generator(const GeneratorOptions& options)
        : m_options(options), m_random(options.seed) {}

    std::string run() {
        for (int station = 0; station < m_options.units; ++station)
            m_units.push_back(planUnit(station));
        preamble();
        for (Unit& unit : m_units)
            unitCode(unit);
        return std::move(m_out);
    }

private:
    // ----- layout
    void line(std::string_view code, std::string_view comment = {}) {
        m_out += code;
        if (!comment.empty()) {
            const int width = characterCount(code);
            m_out.append(width < lang::kCommentColumn - 1
                             ? static_cast<std::size_t>(lang::kCommentColumn - 1 - width)
                             : 1,
                         ' ');
            m_out += "; ";
            m_out += comment;
        }
        m_out += '\n';
    }
    void commentLine(std::string_view text) {
        m_out += "; ";
        m_out += text;
        m_out += '\n';
    }
    // A comment under a statement, at the comment column, as in the manuals.
    void explanation(std::string_view text) {
        m_out.append(lang::kCommentColumn - 1, ' ');
        commentLine(text);
    }
    void blank() { m_out += '\n'; }

    std::string_view maybeComment(int percent) {
        return m_random.percent(percent) ? m_random.pick(kStatementComments) : std::string_view{};
    }

    // ----- plan
    Unit planUnit(int station) {
        Unit unit;
        unit.station = station;
        unit.doubleFamily = m_random.percent(40);
        unit.networkRecords = m_random.percent(50);
        for (int terminal = 0; terminal < 8; ++terminal) {
            unit.inputKinds[static_cast<std::size_t>(terminal)] =
                static_cast<std::size_t>(m_random.below(static_cast<int>(kInputs.size())));
            unit.inputs.push_back(terminal);
        }
        for (int terminal = 0; terminal < 4; ++terminal)
            unit.outputs.push_back(terminal);
        for (int i = 0; i < 8; ++i) {
            const int roll = m_random.below(100);
            const Terminal role = roll < 40   ? Terminal::Input
                                  : roll < 75 ? Terminal::Output
                                              : Terminal::Button;
            unit.upperTerminals[static_cast<std::size_t>(i)] = role;
            if (role != Terminal::Output)
                unit.inputs.push_back(10 + i);
            if (role != Terminal::Input)
                unit.outputs.push_back(10 + i);
        }
        return unit;
    }

    // ----- preamble: project name, units, global names
    void preamble() {
        line("$name Generated plant, seed " + std::to_string(m_options.seed));
        line(";@project description=\"Synthetic plant: " + std::to_string(m_options.units) +
             " units x " + std::to_string(m_options.statementsPerUnit) +
             " statements, for the benchmarks\"");
        blank();
        for (const Unit& unit : m_units) {
            const std::string station = twoDigits(unit.station);
            std::string idfix = "000000000000";
            if (m_random.percent(70))
                for (char& c : idfix)
                    c = "0123456789ABCDEF"[m_random.below(16)];
            line(std::string(unit.doubleFamily ? "! id_pluto_Double:" : "! id_pluto:") + station +
                 "=" + idfix);
            line(";@unit " + station + " description=\"Cell " + station + ", " +
                 std::string(m_random.pick(kCellKinds)) + "\"");
            line("! type_pluto:" + station + (unit.doubleFamily ? "=B46,is3" : "=A20,is3"));
        }
        blank();
        commentLine("Global names: safety inputs, contactors and global memories of every unit");
        for (const Unit& unit : m_units) {
            const std::string station = twoDigits(unit.station);
            for (int terminal = 0; terminal < 8; ++terminal) {
                const Described& input =
                    kInputs[unit.inputKinds[static_cast<std::size_t>(terminal)]];
                declareGlobal(address("I", unit.station, terminal),
                              std::string(input.name) + station + "_" + std::to_string(terminal),
                              m_random.percent(50) ? input.description : std::string_view{});
            }
            for (int terminal = 0; terminal < 4; ++terminal) {
                const Described& contactor = m_random.pick(kContactors);
                declareGlobal(address("Q", unit.station, terminal),
                              std::string(contactor.name) + station + "_" +
                                  std::to_string(terminal),
                              contactor.description);
            }
            for (int index = 0; index < kGlobalMemories / 2; ++index) {
                const Described& memory = m_random.pick(kGlobalMemoryNames);
                declareGlobal(address("GM", unit.station, index),
                              std::string(memory.name) + station + "_" + std::to_string(index),
                              memory.description);
            }
        }
    }

    void declareGlobal(const std::string& variable, const std::string& name,
                       std::string_view comment) {
        line("! " + variable + "=" + name, comment);
        m_globalNames[variable] = name;
    }

    // ----- one unit
    void unitCode(Unit& unit) {
        m_localNames.clear();
        blank();
        line("! pgm_pluto:" + twoDigits(unit.station));
        ioDeclarations(unit);
        blank();
        localNames(unit);

        const int total = m_options.statementsPerUnit;
        const int inSequences = total >= 20 ? total * 15 / 100 : 0;
        unit.sequences = inSequences ? std::clamp(inSequences / 40, 1, kMaxSequences) : 0;
        blank();
        mainCode(unit, total - inSequences);
        for (int sequence = 1; sequence <= unit.sequences; ++sequence) {
            const int share =
                inSequences / unit.sequences + (sequence == 1 ? inSequences % unit.sequences : 0);
            blank();
            sequenceCode(unit, sequence, share);
        }
    }

    void ioDeclarations(const Unit& unit) {
        static constexpr std::array<std::string_view, 3> pulses{"a_pulse", "b_pulse", "c_pulse"};
        const std::string cell = ", cell " + twoDigits(unit.station);
        for (int terminal = 0; terminal < 8; ++terminal) {
            std::string options;
            if (m_random.percent(20)) {
                options = ",static";
            } else {
                options = "," + std::string(m_random.pick(pulses));
                if (m_random.percent(30))
                    options += ",non_inv";
            }
            if (m_random.percent(15))
                options += ",no_filt";
            const Described& input = kInputs[unit.inputKinds[static_cast<std::size_t>(terminal)]];
            line("! " + address("I", unit.station, terminal) + options,
                 std::string(input.description) + cell);
        }
        // Only the A20 family can switch off the test pulses of Q2/Q3.
        for (int terminal = 2; terminal < 4; ++terminal)
            if (!unit.doubleFamily && m_random.percent(30))
                line("! " + address("Q", unit.station, terminal) + ",no_test_pulse",
                     "Test pulses disturb the valve");
        for (int i = 0; i < 8; ++i) {
            const int terminal = 10 + i;
            const std::string_view pulse = m_random.pick(pulses);
            switch (unit.upperTerminals[static_cast<std::size_t>(i)]) {
            case Terminal::Input: {
                const Described& kind = m_random.pick(kInputs);
                line("! " + address("I", unit.station, terminal) + "," + std::string(pulse),
                     std::string(kind.description) + cell);
                break;
            }
            case Terminal::Output: {
                const std::string_view option = m_random.percent(30) ? "static" : pulse;
                line("! " + address("Q", unit.station, terminal) + "," + std::string(option),
                     m_random.pick(kLamps));
                break;
            }
            case Terminal::Button:
                line("! " + address("IQ", unit.station, terminal) + "," + std::string(pulse),
                     m_random.pick(kButtons));
                break;
            }
        }
    }

    // Names are word + index, so they differ from each other and from the
    // global ones (word + station + '_' + index).
    void localNames(const Unit& unit) {
        auto declare = [&](const std::string& variable, std::string_view word, int index) {
            const std::string name = std::string(word) + std::to_string(index);
            line("! " + variable + "=" + name, maybeComment(25));
            m_localNames[variable] = name;
        };
        for (int i = 0; i < 24; ++i) {
            const int index = i * 25 + m_random.below(25);
            declare(address("M", unit.station, index), m_random.pick(kMemoryWords), index);
        }
        for (int i = 0; i < 12; ++i) {
            const int index = i * 10 + m_random.below(10);
            declare(address("R", unit.station, index), m_random.pick(kRegisterWords), index);
        }
        for (int i = 0; i < 2; ++i) {
            const int index = kDoubleRegisterBase +
                              2 * (i * kDoubleRegisters / 2 + m_random.below(kDoubleRegisters / 2));
            declare(address("DR", unit.station, index), kDoubleRegisterWords[i], index);
        }
        for (int i = 0; i < 2; ++i) {
            const int index =
                kBitRegisterBase + i * kBitRegisters / 2 + m_random.below(kBitRegisters / 2);
            declare(address("R", unit.station, index), kBitRegisterWords[i], index);
        }
    }

    // A variable by its symbolic name when it has one (mostly), else its address.
    std::string spell(const std::string& variable) {
        if (auto it = m_localNames.find(variable); it != m_localNames.end() && m_random.percent(45))
            return it->second;
        if (auto it = m_globalNames.find(variable);
            it != m_globalNames.end() && m_random.percent(45))
            return it->second;
        return variable;
    }

    // ----- operands. Every random draw is a statement of its own: the order
    // in which C++ evaluates the operands of '+' or a call's arguments is
    // unspecified, and would make the project depend on the compiler.
    std::string input(const Unit& unit) {
        return spell(address("I", unit.station, m_random.pick(unit.inputs)));
    }

    std::string sequenceMemory(const Unit& unit, int sequence) {
        const int index = m_random.below(kMemoriesPerSequence);
        return spell(address("M", unit.station,
                             kSequenceMemoryBase + (sequence - 1) * kMemoriesPerSequence + index));
    }

    std::string registerBit(const Unit& unit) {
        const int index = m_random.below(kBitRegisters);
        const int bit = m_random.below(16);
        const std::string word = address("R", unit.station, kBitRegisterBase + index);
        // A named register's bits are written "Name.b".
        if (auto it = m_localNames.find(word); it != m_localNames.end() && m_random.percent(50))
            return it->second + "." + std::to_string(bit);
        return word + "." + std::to_string(bit);
    }

    std::string registerOperand(const Unit& unit, int base, int count) {
        return spell(address("R", unit.station, base + m_random.below(count)));
    }

    std::string doubleRegister(const Unit& unit) {
        return spell(address("DR", unit.station,
                             kDoubleRegisterBase + 2 * m_random.below(kDoubleRegisters)));
    }

    // A bit to read: own inputs, memories, outputs and registers, other
    // units' global variables, system memories.
    std::string contact(const Unit& unit) {
        const int roll = m_random.below(100);
        if (roll < 38)
            return input(unit);
        if (roll < 63)
            return spell(address("M", unit.station, m_random.below(kMainMemories)));
        if (roll < 68 && unit.sequences > 0)
            return sequenceMemory(unit, m_random.between(1, unit.sequences));
        if (roll < 75)
            return spell(address("Q", unit.station, m_random.pick(unit.outputs)));
        if (roll < 80)
            return spell(address("GM", unit.station, m_random.below(kGlobalMemories)));
        if (roll < 87 && m_units.size() > 1) {
            int other = m_random.below(static_cast<int>(m_units.size()) - 1);
            if (other >= unit.station)
                ++other;
            if (m_random.percent(50))
                return spell(address("GM", other, m_random.below(kGlobalMemories)));
            return spell(address("I", other, m_random.below(8)));
        }
        if (roll < 94)
            return registerBit(unit);
        if (m_random.percent(20))
            return "SM_Pluto" + std::to_string(m_random.pick(m_units).station) + "_Present";
        return std::string(m_random.pick(kSystemMemories));
    }

    std::string constant() {
        if (m_random.percent(5))
            return "-" + std::to_string(m_random.between(1, 100));
        return std::to_string(m_random.between(0, 1000));
    }

    std::string comparison(const Unit& unit) {
        std::string text = "(";
        const std::string_view op = m_random.pick(kCompareOps);
        const int roll = m_random.below(100);
        if (roll < 70) {
            text += registerOperand(unit, 0, kRegisters);
            text += op;
            text += m_random.percent(70) ? constant() : registerOperand(unit, 0, kRegisters);
        } else if (roll < 85) {
            text += doubleRegister(unit);
            text += op;
            text += m_random.percent(70) ? constant() : doubleRegister(unit);
        } else {
            const bool supply = m_random.percent(50);
            if (m_random.percent(50))
                text += supply ? "SR_SupplVolt" : "SR_ExecTime";
            else
                text += address("SR", unit.station, supply ? 40 : 9);
            text += op;
            text += std::to_string(supply ? m_random.between(180, 260) : m_random.between(1, 5000));
        }
        text += ')';
        return m_random.percent(8) ? "/" + text : text;
    }

    std::string edge(const Unit& unit) {
        std::string text = m_random.percent(70) ? "P(" : "N(";
        if (m_random.percent(12))
            text += '/';
        text += m_random.percent(70) ? input(unit) : contact(unit);
        text += ')';
        return m_random.percent(10) ? "/" + text : text;
    }

    std::string timer(Unit& unit) {
        --unit.timersLeft;
        const int roll = m_random.below(100);
        const std::string_view kind = roll < 50   ? "TON"
                                      : roll < 70 ? "TPS"
                                      : roll < 90 ? "TOF"
                                      : roll < 95 ? "T"
                                                  : "IT";
        std::string text(kind);
        text += '(';
        // The old spellings T( and IT( get time constants, as in the manuals.
        if (kind.size() == 3 && m_random.percent(15))
            text += registerOperand(unit, kPresetRegisterBase, kRegisters - kPresetRegisterBase);
        else if (m_random.percent(70))
            text += lang::formatTime(m_random.pick(kRoundPresets));
        else
            text += lang::formatTime(m_random.between(1, 65535));
        text += ')';
        return m_random.percent(15) ? "/" + text : text;
    }

    // ----- expressions, in the printer's spelling: an OR in an AND is in
    // parentheses, nothing else is; a group always has two terms or more.
    std::string condition(Unit& unit, int depth) {
        const int roll = m_random.below(100);
        const int terms = roll < 85 ? 1 : roll < 97 ? 2 : 3;
        std::string text = term(unit, depth);
        for (int i = 1; i < terms; ++i) {
            text += " + ";
            text += term(unit, depth);
        }
        return text;
    }

    // An AND of factors; when timed, a timer ends it, so that all the rest is its input.
    std::string term(Unit& unit, int depth, bool timed = false) {
        const int roll = m_random.below(100);
        const int factors = roll < 64 ? 1 : roll < 90 ? 2 : roll < 98 ? 3 : 4;
        std::string text;
        for (int i = 0; i < factors; ++i) {
            if (i)
                text += " * ";
            text += factor(unit, factors > 1 || timed ? depth : 0);
        }
        if (timed) {
            text += " * ";
            text += timer(unit);
        }
        return text;
    }

    std::string factor(Unit& unit, int depth) {
        const int roll = m_random.below(100);
        if (depth > 0 && roll < 8) {
            std::string text = "(";
            text += term(unit, depth - 1);
            text += " + ";
            text += term(unit, depth - 1);
            if (m_random.percent(20)) {
                text += " + ";
                text += term(unit, depth - 1);
            }
            return text + ")";
        }
        if (roll < 24)
            return edge(unit);
        if (roll < 31)
            return comparison(unit);
        if (m_random.percent(25))
            return "/" + contact(unit);
        return contact(unit);
    }

    // ----- statements
    std::string bitTarget(const Unit& unit) {
        const int roll = m_random.below(100);
        if (roll < 68)
            return spell(address("M", unit.station, m_random.below(kMainMemories)));
        if (roll < 80)
            return spell(address("Q", unit.station, m_random.pick(unit.outputs)));
        if (roll < 88)
            return spell(address("GM", unit.station, m_random.below(kGlobalMemories)));
        return registerBit(unit);
    }

    std::string assignment(const Unit& unit) {
        static constexpr std::array<std::string_view, 4> binary{" + ", " - ", " * ", " / "};
        static constexpr std::array<std::string_view, 4> compound{" += ", " -= ", " *= ", " /= "};
        std::string text = "(";
        if (m_random.percent(15)) {
            // Double registers have no "/=".
            text += doubleRegister(unit);
            switch (m_random.below(5)) {
            case 0:
                text += "++";
                break;
            case 1:
                text += " += " + std::to_string(m_random.between(1, 100000));
                break;
            case 2:
                text += " = ";
                text += doubleRegister(unit);
                break;
            case 3:
                text += " *= " + std::to_string(m_random.between(2, 10));
                break;
            default:
                text += " = ";
                text += doubleRegister(unit);
                text += m_random.percent(50) ? " + " : " * ";
                text += doubleRegister(unit);
                break;
            }
            return text + ")";
        }
        text += registerOperand(unit, 0, kRegisters);
        const int roll = m_random.below(100);
        if (roll < 20) {
            text += "++";
        } else if (roll < 30) {
            text += "--";
        } else if (roll < 55) {
            text += m_random.pick(compound);
            text += std::to_string(m_random.between(1, 50));
        } else if (roll < 65) {
            text += m_random.pick(compound);
            text += registerOperand(unit, 0, kRegisters);
        } else if (roll < 80) {
            text += " = ";
            text += constant();
        } else if (roll < 88) {
            text += " = ";
            text += registerOperand(unit, 0, kRegisters);
        } else {
            text += " = ";
            text += registerOperand(unit, 0, kRegisters);
            text += m_random.pick(binary);
            text += registerOperand(unit, 0, kRegisters);
        }
        return text + ")";
    }

    // A statement with a trailing comment in `percent` of the cases.
    void statement(const std::string& code, int percent) {
        const std::string_view comment = maybeComment(percent);
        line(code, comment);
    }

    void networkStart(const Unit& unit, bool first) {
        const std::string_view text = m_random.pick(kNetworkComments);
        if (!first)
            blank();
        if (unit.networkRecords)
            line(";@network comment=\"" + std::string(text) + "\"");
        else
            commentLine(text);
    }

    void mainCode(Unit& unit, int count) {
        line(stepHeader(unit.station, 0, 0), "Main PLC code");
        int written = 0;
        for (int sequence = 1; sequence <= unit.sequences && written < count; ++sequence) {
            const std::string condition = this->condition(unit, 0);
            line("R(" + address("S", unit.station, sequence) + ") = " + condition,
                 "Hold the sequence in step 0");
            ++written;
        }
        int leftInNetwork = 0;
        while (written < count) {
            if (leftInNetwork == 0) {
                networkStart(unit, written == 0);
                leftInNetwork = m_random.between(4, 16);
            }
            written += mainStatement(unit, count - written);
            --leftInNetwork;
        }
    }

    // Writes one statement, or a latch pair when room allows; returns how many.
    int mainStatement(Unit& unit, int room) {
        const int roll = m_random.below(100);
        std::string code;
        if (roll < 3 && unit.timersLeft > 0) {
            code = bitTarget(unit) + " = ";
            code += term(unit, 1, true);
            statement(code, 40);
        } else if (roll < 50) {
            code = bitTarget(unit) + " = ";
            code += condition(unit, m_random.percent(10) ? 2 : 1);
            statement(code, 8);
            if (!unit.networkRecords && m_random.percent(4))
                explanation(m_random.pick(kExplanations));
        } else if (roll < 62 && room >= 2) {
            const std::string target = bitTarget(unit);
            statement("S(" + target + ") = " + condition(unit, 0), 20);
            line("R(" + target + ") = " + condition(unit, 0));
            return 2;
        } else if (roll < 66) {
            code = "T(" + bitTarget(unit) + ") = P(";
            code += input(unit) + ")";
            statement(code, 8);
        } else if (roll < 84) {
            code = assignment(unit) + " = ";
            code += m_random.percent(60) ? edge(unit) : condition(unit, 1);
            statement(code, 8);
        } else if (roll < 90) {
            statement(assignment(unit), 8);
        } else {
            code = bitTarget(unit) + " = ";
            code += contact(unit);
            statement(code, 8);
        }
        return 1;
    }

    void sequenceCode(Unit& unit, int sequence, int count) {
        // Enough statements per step that a long sequence stays within the step numbers.
        const int minBody = 1 + count / kMaxStepsPerSequence;
        int left = count;
        for (int step = 0; left > 0; ++step) {
            const bool last = left <= minBody + 4;
            std::string_view comment;
            if (step == 0)
                comment = m_random.pick(kSequenceNames);
            else if (m_random.percent(40))
                comment = m_random.pick(kStepComments);
            line(stepHeader(unit.station, sequence, step), comment);
            const int body = last ? left - 1 : m_random.between(minBody, minBody + 2);
            for (int i = 0; i < body; ++i)
                stepStatement(unit, sequence);
            left -= body;
            if (!last && m_random.percent(20)) {
                line("J(0) = " + condition(unit, 0), "Abort");
                --left;
            }
            std::string jump = last ? "J(0) = " : "J(+1) = ";
            if (unit.timersLeft > 0 && m_random.percent(15))
                jump += term(unit, 0, true);
            else
                jump += condition(unit, 0);
            line(jump);
            --left;
        }
    }

    void stepStatement(Unit& unit, int sequence) {
        const int roll = m_random.below(100);
        if (roll < 45) {
            statement(sequenceMemory(unit, sequence), 15); // on while the step is active
        } else if (roll < 70) {
            std::string code = sequenceMemory(unit, sequence) + " = ";
            code += condition(unit, 1);
            line(code);
        } else if (roll < 85) {
            statement("(" + registerOperand(unit, 0, kRegisters) + " = 0) = SM_StepNew", 8);
        } else {
            std::string code = "S(" + bitTarget(unit) + ") = ";
            code += condition(unit, 1);
            statement(code, 8);
        }
    }

    const GeneratorOptions& m_options;
    Random m_random;
    std::vector<Unit> m_units;
    std::map<std::string, std::string> m_globalNames; // by address
    std::map<std::string, std::string> m_localNames;  // of the unit being written
    std::string m_out;
};

} // namespace

std::string generateProject(const GeneratorOptions& options) {
    if (options.units < 1 || options.units > 32)
        throw std::invalid_argument("units must be 1..32");
    if (options.statementsPerUnit < 1 || options.statementsPerUnit > 50000)
        throw std::invalid_argument("statements per unit must be 1..50000");
    return Generator(options).run();
}

} // namespace rs::bench
