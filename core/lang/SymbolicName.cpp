// SPDX-License-Identifier: GPL-3.0-or-later
#include "SymbolicName.h"

#include "Keywords.h"
#include "TextCase.h"

#include <QChar>
#include <QList>
#include <QString>
#include <QStringDecoder>

#include <array>

namespace rs::lang {

namespace {

struct SystemEntry {
    std::string_view upperName;
    AddressKind kind;
    int index;
};

// Names that mean the same number on every unit type that has them.
constexpr std::array<SystemEntry, 35> kSystemNames{{
    {"SM_STEPNEW", AddressKind::SystemMemory, 0},
    {"SM_DITTO", AddressKind::SystemMemory, 1},
    {"SM_FLASH", AddressKind::SystemMemory, 2},
    {"SM_1HZ", AddressKind::SystemMemory, 3},
    {"SM_10HZ", AddressKind::SystemMemory, 4},
    {"SM_FASTFLASH", AddressKind::SystemMemory, 5},
    {"SM_DOUBLEFLASH", AddressKind::SystemMemory, 6},
    {"SM_SYSINIT", AddressKind::SystemMemory, 9},
    {"SM_TIMERFREEZE", AddressKind::SystemMemory, 10},
    {"SM_OVERFLOW", AddressKind::SystemMemory, 11},
    {"SM_DIVBYZERO", AddressKind::SystemMemory, 12},
    {"SM_BUTTON", AddressKind::SystemMemory, 39},
    {"SR_REMAIN", AddressKind::SystemRegister, 2},
    {"SR_EXECFREETIME", AddressKind::SystemRegister, 8},
    {"SR_EXECTIME", AddressKind::SystemRegister, 9},
    {"SR_PLUTODISPLAY", AddressKind::SystemRegister, 10},
    {"SR_ERRORCODE", AddressKind::SystemRegister, 11},
    {"SR_ERRORLOG1", AddressKind::SystemRegister, 12},
    {"SR_ERRORLOG2", AddressKind::SystemRegister, 13},
    {"SR_ERRORLOG3", AddressKind::SystemRegister, 14},
    {"SR_ASI_SLAVE_MISSING", AddressKind::SystemRegister, 15},
    {"SR_ASI_SLAVE_CHANF", AddressKind::SystemRegister, 16},
    {"SR_SUPPLVOLT", AddressKind::SystemRegister, 40},
    {"SR_I5_VOLT", AddressKind::SystemRegister, 41},
    {"SR_IQ11_VOLT", AddressKind::SystemRegister, 41},
    {"SR_I1_VOLT", AddressKind::SystemRegister, 41},
    {"SR_Q16_CURRENT", AddressKind::SystemRegister, 42},
    {"SR_Q17_CURRENT", AddressKind::SystemRegister, 43},
    {"SR_IQ10_VOLT", AddressKind::SystemRegister, 44},
    {"SR_I6_VOLT", AddressKind::SystemRegister, 45},
    {"SR_IQ12_VOLT", AddressKind::SystemRegister, 45},
    {"SR_I2_VOLT", AddressKind::SystemRegister, 45},
    {"SR_I7_VOLT", AddressKind::SystemRegister, 46},
    {"SR_IQ13_VOLT", AddressKind::SystemRegister, 46},
    {"SR_I3_VOLT", AddressKind::SystemRegister, 46},
}};

} // namespace

std::string foldName(std::string_view name) {
    for (unsigned char c : name)
        if (c >= 0x80)
            return QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size()))
                .toCaseFolded()
                .toStdString();
    return toLower(name);
}

std::optional<std::string> checkSymbolicName(std::string_view name, int instructionSet) {
    // Not QString::fromUtf8: it drops a leading byte-order mark, which the lexer does not.
    QStringDecoder decoder(QStringDecoder::Utf8, QStringDecoder::Flag::ConvertInitialBom);
    const QString text = decoder(QByteArrayView(name.data(), static_cast<qsizetype>(name.size())));
    if (text.isEmpty())
        return "a symbolic name cannot be empty";
    const QString quoted = "'" + text + "'";
    auto codePoints = text.toUcs4();
    char32_t first = codePoints.front();
    if (first == '_')
        return (quoted + " starts with '_'; a name must start with a letter").toStdString();
    if (QChar::isDigit(first))
        return (quoted + " starts with a digit; a name must start with a letter").toStdString();
    if (!QChar::isLetter(first))
        return (quoted + " must start with a letter").toStdString();
    for (char32_t c : codePoints) {
        if (c == '.') {
            if (instructionSet >= 3)
                return (quoted + ": '.' is allowed in names with instruction set 2 only")
                    .toStdString();
            continue;
        }
        if (c != '_' && !QChar::isLetterOrNumber(c))
            return (quoted + ": '" + QString::fromUcs4(&c, 1) +
                    "' is not allowed; use letters, digits and '_'")
                .toStdString();
    }
    if (name.back() == '.')
        return (quoted + " ends with '.'").toStdString();
    const std::string upper = toUpper(name);
    for (auto word : instructionWords())
        if (upper == word)
            return (quoted + " is an instruction of the language").toStdString();
    if (readAddressWord(name).shape != AddressWord::Shape::NotAnAddress)
        return (quoted + " looks like an address").toStdString();
    if (systemName(name, 0).valid())
        return (quoted + " is the name of a system memory or register").toStdString();
    return std::nullopt;
}

Address systemName(std::string_view name, int unit) {
    if (name.size() < 4 || (name[0] != 'S' && name[0] != 's'))
        return {};
    const std::string upper = toUpper(name);
    for (const auto& entry : kSystemNames)
        if (entry.upperName == upper)
            return {entry.kind, unit, entry.index};
    // SM_Pluto0_Present .. SM_Pluto31_Present
    constexpr std::string_view prefix = "SM_PLUTO";
    constexpr std::string_view suffix = "_PRESENT";
    if (upper.size() > prefix.size() + suffix.size() && upper.starts_with(prefix) &&
        upper.ends_with(suffix)) {
        std::string_view digits(upper);
        digits = digits.substr(prefix.size(), digits.size() - prefix.size() - suffix.size());
        if (digits.empty() || digits.size() > 2 ||
            digits.find_first_not_of("0123456789") != std::string_view::npos)
            return {};
        int station = std::stoi(std::string(digits));
        if (station <= 31)
            return {AddressKind::SystemMemory, unit, 100 + station};
    }
    return {};
}

} // namespace rs::lang
