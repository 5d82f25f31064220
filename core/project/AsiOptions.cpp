// SPDX-License-Identifier: GPL-3.0-or-later
#include "AsiOptions.h"

#include <algorithm>
#include <array>
#include <charconv>

namespace rs::project {

namespace {

using lang::Address;
using lang::AddressKind;

template <typename Enum, std::size_t N>
std::optional<Enum> ofWord(const std::array<std::pair<Enum, std::string_view>, N>& words,
                           std::string_view word) {
    for (const auto& [value, text] : words)
        if (text == word)
            return value;
    return std::nullopt;
}

template <typename Enum, std::size_t N>
std::string_view wordOf(const std::array<std::pair<Enum, std::string_view>, N>& words, Enum value) {
    for (const auto& [v, text] : words)
        if (v == value)
            return text;
    return {};
}

constexpr std::array<std::pair<AsiMode, std::string_view>, 5> kModeWords{{
    {AsiMode::Master, "master"},
    {AsiMode::MonitorOnly, "monitor"},
    {AsiMode::MonitorSlave, "monitor_slave"},
    {AsiMode::MonitorSlaveExtra, "monitor_slave_extra"},
    {AsiMode::Unused, "unused"},
}};

constexpr std::array<std::pair<AsiOptimisation, std::string_view>, 2> kOptimisationWords{{
    {AsiOptimisation::ShortStopTime, "stop_time"},
    {AsiOptimisation::DisturbanceImmunity, "immunity"},
}};

constexpr std::array<std::pair<AsiSlaveType, std::string_view>, 8> kTypeWords{{
    {AsiSlaveType::Undefined, "undefined"},
    {AsiSlaveType::SafeInput, "safe_input"},
    {AsiSlaveType::NonsafeStandard, "nonsafe_std"},
    {AsiSlaveType::NonsafeAB, "nonsafe_ab"},
    {AsiSlaveType::CombinedTransaction, "combined_ab"},
    {AsiSlaveType::Analogue, "analog"},
    {AsiSlaveType::SafeOutput, "safe_output"},
    {AsiSlaveType::PlutoAsSafeInput, "pluto_safe_input"},
}};

constexpr std::array<std::pair<ChannelMonitoring, std::string_view>, 5> kMonitoringWords{{
    {ChannelMonitoring::None, "none"},
    {ChannelMonitoring::Monitoring, "channel"},
    {ChannelMonitoring::MonitoringDebounce, "channel_debounce"},
    {ChannelMonitoring::Simultaneous, "simultaneous"},
    {ChannelMonitoring::SimultaneousDebounce, "simultaneous_debounce"},
}};

bool isAB(AsiSlaveType type) {
    return type == AsiSlaveType::NonsafeAB || type == AsiSlaveType::CombinedTransaction;
}

bool usesBlockSlot(AsiSlaveType type) {
    return type == AsiSlaveType::SafeOutput || type == AsiSlaveType::PlutoAsSafeInput;
}

char hexDigit(int value) {
    return "0123456789ABCDEF"[value & 0xF];
}

int hexValue(char c) {
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    return -1;
}

bool isDigit(int value) {
    return value >= 0 && value <= 0xF;
}

} // namespace

const std::vector<std::string_view>& asiSafeInputModels() {
    static const std::vector<std::string_view> models{"General", "URAX-A1R", "URAX-C1"};
    return models;
}

bool monitorsOwnChannels(std::string_view model) {
    return model.starts_with("URAX") && model != "URAX-C1";
}

std::string slaveLabel(int station, AsiSlaveAddress slave) {
    return "ASi" + std::to_string(station) + "." + std::to_string(slave.number) +
           (slave.b ? "B" : "");
}

std::optional<std::pair<int, AsiSlaveAddress>> readSlaveLabel(std::string_view word) {
    if (word.size() < 6 || (word[0] != 'A' && word[0] != 'a') ||
        (word[1] != 'S' && word[1] != 's') || (word[2] != 'I' && word[2] != 'i'))
        return std::nullopt;
    word.remove_prefix(3);
    AsiSlaveAddress slave;
    if (!word.empty() && (word.back() == 'B' || word.back() == 'b')) {
        slave.b = true;
        word.remove_suffix(1);
    }
    const auto dot = word.find('.');
    if (dot == std::string_view::npos)
        return std::nullopt;
    int station = -1;
    const auto number = [](std::string_view text, int& value) {
        auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        return error == std::errc() && end == text.data() + text.size() && !text.empty();
    };
    if (!number(word.substr(0, dot), station) || !number(word.substr(dot + 1), slave.number) ||
        station < 0 || station > 31 || slave.number < 1 || slave.number > kAsiSlaveCount)
        return std::nullopt;
    return std::pair{station, slave};
}

std::string profileWord(const AsiProfile& profile) {
    return std::string("S-") + hexDigit(profile.io) + "." + hexDigit(profile.id) + "." +
           hexDigit(profile.id2);
}

std::string profileText(const AsiProfile& profile) {
    return profileWord(profile) + " ID1=" + hexDigit(profile.id1);
}

std::optional<AsiProfile> readProfile(std::string_view text) {
    if (text.size() != 7 || (text[0] != 'S' && text[0] != 's') || text[1] != '-' ||
        text[3] != '.' || text[5] != '.')
        return std::nullopt;
    AsiProfile profile;
    profile.io = hexValue(text[2]);
    profile.id = hexValue(text[4]);
    profile.id2 = hexValue(text[6]);
    if (profile.io < 0 || profile.id < 0 || profile.id2 < 0)
        return std::nullopt;
    return profile;
}

std::vector<AsiSlaveType> slaveTypesAt(AsiSlaveAddress address, AsiSlaveType aSlave) {
    if (address.b) {
        if (aSlave != AsiSlaveType::Undefined && !isAB(aSlave))
            return {AsiSlaveType::Undefined};
        return {AsiSlaveType::Undefined, AsiSlaveType::NonsafeAB,
                AsiSlaveType::CombinedTransaction};
    }
    return {AsiSlaveType::Undefined,           AsiSlaveType::SafeInput,
            AsiSlaveType::NonsafeStandard,     AsiSlaveType::NonsafeAB,
            AsiSlaveType::CombinedTransaction, AsiSlaveType::Analogue,
            AsiSlaveType::SafeOutput,          AsiSlaveType::PlutoAsSafeInput};
}

bool hasProfile(AsiSlaveType type, std::string_view model) {
    switch (type) {
    case AsiSlaveType::Undefined:
    case AsiSlaveType::SafeOutput:
    case AsiSlaveType::PlutoAsSafeInput:
        return false;
    case AsiSlaveType::SafeInput:
        // "Profile/ID1 does not have to be selected for Urax slaves."
        return !model.starts_with("URAX");
    default:
        return true;
    }
}

bool hasChannels(AsiSlaveType type) {
    return type == AsiSlaveType::SafeInput || type == AsiSlaveType::PlutoAsSafeInput;
}

bool usesTimeLimit(ChannelMonitoring monitoring) {
    return monitoring == ChannelMonitoring::MonitoringDebounce ||
           monitoring == ChannelMonitoring::Simultaneous ||
           monitoring == ChannelMonitoring::SimultaneousDebounce;
}

AsiSlave defaultSlave(AsiSlaveType type) {
    AsiSlave slave;
    slave.type = type;
    switch (type) {
    case AsiSlaveType::SafeInput:
        slave.profile = {0x0, 0xB, 0xF, 0xF}; // S-0.B.F, the manual's new safe input
        break;
    case AsiSlaveType::NonsafeStandard:
        slave.profile = {0x7, 0x0, 0xF, 0xF}; // S-7.0: 4 inputs and 4 outputs
        break;
    case AsiSlaveType::NonsafeAB:
        slave.profile = {0x7, 0xA, 0xF, 0xF};
        break;
    case AsiSlaveType::CombinedTransaction:
        slave.profile = {0x7, 0xA, 0x7, 0xF}; // S-7.A.7, as the manual says
        break;
    case AsiSlaveType::Analogue:
        slave.profile = {0x7, 0x3, 0xF, 0xF};
        break;
    default:
        break;
    }
    return slave;
}

std::optional<std::string> setSlave(AsiOptions& options, AsiSlaveAddress address,
                                    const AsiSlave& slave) {
    const std::string where = "slave " + std::to_string(address.number) + (address.b ? "B" : "");
    if (address.number < 1 || address.number > kAsiSlaveCount)
        return "AS-i slaves are numbered 1-" + std::to_string(kAsiSlaveCount);
    AsiSlaveType aSlave = AsiSlaveType::Undefined;
    if (auto it = options.slaves.find({address.number, false}); it != options.slaves.end())
        aSlave = it->second.type;
    const auto offered = slaveTypesAt(address, aSlave);
    if (std::find(offered.begin(), offered.end(), slave.type) == offered.end())
        return address.b ? where + ": a B address takes only an A/B slave, beside an A/B slave"
                         : where + ": not a type of slave";
    if (slave.type == AsiSlaveType::Undefined) {
        options.slaves.erase(address); // a B slave may stay alone on its number
        return std::nullopt;
    }
    if (!isDigit(slave.parameter) || !isDigit(slave.profile.io) || !isDigit(slave.profile.id) ||
        !isDigit(slave.profile.id2) || !isDigit(slave.profile.id1))
        return where + ": parameter and profile are hexadecimal digits 0-F";
    if (hasChannels(slave.type) && usesTimeLimit(slave.monitoring) &&
        (slave.timeLimitMs < kMinAsiTimeLimitMs || slave.timeLimitMs > kMaxAsiTimeLimitMs))
        return where + ": the time limit must be 0.01-10 s";
    if (slave.type == AsiSlaveType::SafeInput &&
        std::find(asiSafeInputModels().begin(), asiSafeInputModels().end(), slave.model) ==
            asiSafeInputModels().end())
        return where + ": unknown model '" + slave.model + "'";
    if (usesBlockSlot(slave.type)) {
        int used = 0;
        for (const auto& [other, defined] : options.slaves)
            if (other != address && usesBlockSlot(defined.type))
                ++used;
        if (used >= kMaxAsiBlockSlaves)
            return where + ": a unit takes at most 16 Safe Output and Pluto as Safe Input slaves";
    }
    AsiSlave stored = slave;
    if (slave.type == AsiSlaveType::SafeInput && monitorsOwnChannels(slave.model))
        stored.monitoring = ChannelMonitoring::None; // the URAX does it
    if (!hasChannels(slave.type)) {
        stored.monitoring = ChannelMonitoring::Monitoring;
        stored.timeLimitMs = 1000;
    }
    if (slave.type != AsiSlaveType::SafeInput)
        stored.model = "General";
    options.slaves[address] = stored;
    if (!address.b && !isAB(slave.type))
        options.slaves.erase({address.number, true});
    return std::nullopt;
}

std::vector<Address> slaveVariables(const target::UnitTypeInfo& type, int station,
                                    AsiSlaveAddress address, AsiSlaveType slaveType) {
    std::vector<Address> list;
    if (!type.asiSlaves)
        return list;
    auto bits = [&](AddressKind kind, int count) {
        for (int bit = 1; bit <= count; ++bit)
            list.push_back({kind, station, address.number, bit, address.b});
    };
    switch (slaveType) {
    case AsiSlaveType::SafeInput:
    case AsiSlaveType::PlutoAsSafeInput:
        if (!address.b)
            list.push_back({AddressKind::AsiInput, station, address.number});
        bits(AddressKind::AsiOutput, 4);
        break;
    case AsiSlaveType::NonsafeStandard:
    case AsiSlaveType::CombinedTransaction:
        bits(AddressKind::AsiInput, 4);
        bits(AddressKind::AsiOutput, 4);
        break;
    case AsiSlaveType::NonsafeAB:
        bits(AddressKind::AsiInput, 4);
        bits(AddressKind::AsiOutput, 3);
        break;
    case AsiSlaveType::Undefined:
    case AsiSlaveType::Analogue:   // read and written through ASiAnalogInput/Output
    case AsiSlaveType::SafeOutput: // through ASiSafeOutput1
        break;
    }
    return list;
}

AsiSlaveAddress slaveOf(const Address& address) {
    return {address.index, address.asiB};
}

std::string_view slaveTypeName(AsiSlaveType type) {
    constexpr std::array<std::pair<AsiSlaveType, std::string_view>, 8> kNames{{
        {AsiSlaveType::Undefined, "Undefined"},
        {AsiSlaveType::SafeInput, "Safe Input"},
        {AsiSlaveType::NonsafeStandard, "Nonsafe Std"},
        {AsiSlaveType::NonsafeAB, "Nonsafe A/B"},
        {AsiSlaveType::CombinedTransaction, "Combined Transaction A/B"},
        {AsiSlaveType::Analogue, "Analog"},
        {AsiSlaveType::SafeOutput, "Safe Output"},
        {AsiSlaveType::PlutoAsSafeInput, "Pluto as Safe Input"},
    }};
    return wordOf(kNames, type);
}

std::string_view modeWord(AsiMode mode) {
    return wordOf(kModeWords, mode);
}
std::string_view optimisationWord(AsiOptimisation optimisation) {
    return wordOf(kOptimisationWords, optimisation);
}
std::string_view slaveTypeWord(AsiSlaveType type) {
    return wordOf(kTypeWords, type);
}
std::string_view monitoringWord(ChannelMonitoring monitoring) {
    return wordOf(kMonitoringWords, monitoring);
}
std::optional<AsiMode> modeOfWord(std::string_view word) {
    return ofWord(kModeWords, word);
}
std::optional<AsiOptimisation> optimisationOfWord(std::string_view word) {
    return ofWord(kOptimisationWords, word);
}
std::optional<AsiSlaveType> slaveTypeOfWord(std::string_view word) {
    return ofWord(kTypeWords, word);
}
std::optional<ChannelMonitoring> monitoringOfWord(std::string_view word) {
    return ofWord(kMonitoringWords, word);
}

} // namespace rs::project
