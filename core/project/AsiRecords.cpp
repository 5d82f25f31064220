// SPDX-License-Identifier: GPL-3.0-or-later
#include "AsiRecords.h"

#include "RecordWords.h"

namespace rs::project {

namespace {

std::string hexText(int digit) {
    return std::string(1, "0123456789ABCDEF"[digit & 0xF]);
}

bool readNumber(std::string_view text, int& value) {
    const auto number = wholeNumber(text);
    value = number.value_or(value);
    return number.has_value();
}

int readHexDigit(const Annotation& record, std::string_view key, int fallback) {
    const std::string text = record.value(key);
    if (text.empty())
        return fallback;
    int value = -1;
    if (text.size() == 1) {
        const char c = text[0];
        value = c >= '0' && c <= '9'   ? c - '0'
                : c >= 'A' && c <= 'F' ? c - 'A' + 10
                : c >= 'a' && c <= 'f' ? c - 'a' + 10
                                       : -1;
    }
    if (value < 0)
        throw AsiRecordError{"@asi_slave " + std::string(key) +
                             " must be one hexadecimal digit 0-F, not '" + text + "'"};
    return value;
}

template <typename T, typename Read>
T readWord(const Annotation& record, std::string_view key, T fallback, Read read,
           std::string_view choices) {
    const std::string text = record.value(key);
    if (text.empty())
        return fallback;
    if (auto value = read(text))
        return *value;
    throw AsiRecordError{"@" + record.kind + " " + std::string(key) + " must be one of " +
                         std::string(choices) + ", not '" + text + "'"};
}

void readUnitRecord(const Annotation& record, std::map<int, AsiOptions>& all) {
    int station = -1;
    if (record.arguments.size() != 1 || !readNumber(record.arguments[0], station) || station < 0 ||
        station > 31)
        throw AsiRecordError{"@asi needs a station number 0-31, as in ;@asi 00 mode=\"master\""};
    AsiOptions& options = all[station];
    options.mode = readWord(record, "mode", AsiMode::Master, modeOfWord,
                            "master, monitor, monitor_slave, monitor_slave_extra, unused");
    options.optimisation = readWord(record, "optimize", AsiOptimisation::ShortStopTime,
                                    optimisationOfWord, "stop_time, immunity");
    if (std::string address = record.value("address"); !address.empty()) {
        if (!readNumber(address, options.slaveAddress) || options.slaveAddress < 1 ||
            options.slaveAddress > kAsiSlaveCount)
            throw AsiRecordError{"@asi address must be a slave address 1-31, not '" + address +
                                 "'"};
    }
}

void readSlaveRecord(const Annotation& record, std::map<int, AsiOptions>& all) {
    const auto label =
        record.arguments.size() == 1 ? readSlaveLabel(record.arguments[0]) : std::nullopt;
    if (!label)
        throw AsiRecordError{"@asi_slave needs a slave address ASi<unit>.<1-31>[B], as in "
                             ";@asi_slave ASi0.3 type=\"safe_input\""};
    const auto [station, address] = *label;
    const std::string typeText = record.value("type");
    const auto type = slaveTypeOfWord(typeText);
    if (!type || *type == AsiSlaveType::Undefined)
        throw AsiRecordError{"@asi_slave type must be one of safe_input, nonsafe_std, "
                             "nonsafe_ab, combined_ab, analog, safe_output, pluto_safe_input, "
                             "not '" +
                             typeText + "'"};
    AsiSlave slave = defaultSlave(*type);
    if (std::string model = record.value("model"); !model.empty())
        slave.model = model;
    slave.parameter = readHexDigit(record, "param", slave.parameter);
    if (std::string profile = record.value("profile"); !profile.empty()) {
        auto read = readProfile(profile);
        if (!read)
            throw AsiRecordError{"@asi_slave profile must be written S-<io>.<id>.<id2> in "
                                 "hexadecimal digits, as S-0.B.F, not '" +
                                 profile + "'"};
        read->id1 = slave.profile.id1;
        slave.profile = *read;
    }
    slave.profile.id1 = readHexDigit(record, "id1", slave.profile.id1);
    slave.monitoring =
        readWord(record, "monitoring", ChannelMonitoring::Monitoring, monitoringOfWord,
                 "none, channel, channel_debounce, simultaneous, simultaneous_debounce");
    if (std::string limit = record.value("time_limit_ms"); !limit.empty())
        if (!readNumber(limit, slave.timeLimitMs))
            throw AsiRecordError{"@asi_slave time_limit_ms must be a number of milliseconds, "
                                 "not '" +
                                 limit + "'"};
    AsiOptions& options = all[station];
    if (options.slaves.count(address))
        throw AsiRecordError{"@asi_slave " + slaveLabel(station, address) + " is already defined"};
    if (!address.b && options.slaves.count({address.number, true}) &&
        slaveTypesAt({address.number, true}, *type).size() == 1)
        throw AsiRecordError{"@asi_slave " + slaveLabel(station, address) +
                             " fills its address, but the B slave beside it is defined"};
    if (auto problem = setSlave(options, address, slave))
        throw AsiRecordError{"@asi_slave " + slaveLabel(station, address) + ": " + *problem};
}

} // namespace

std::vector<Annotation> asiRecords(int station, const AsiOptions& options) {
    std::vector<Annotation> records;
    Annotation unit{"asi", {stationText(station)}, {}};
    if (options.mode != AsiMode::Master)
        unit.attributes.emplace_back("mode", modeWord(options.mode));
    if (options.mode == AsiMode::MonitorSlave || options.mode == AsiMode::MonitorSlaveExtra)
        unit.attributes.emplace_back("address", std::to_string(options.slaveAddress));
    if (options.optimisation != AsiOptimisation::ShortStopTime)
        unit.attributes.emplace_back("optimize", optimisationWord(options.optimisation));
    if (!unit.attributes.empty())
        records.push_back(std::move(unit));
    for (const auto& [address, slave] : options.slaves) {
        Annotation record{"asi_slave", {slaveLabel(station, address)}, {}};
        record.attributes.emplace_back("type", slaveTypeWord(slave.type));
        if (slave.type == AsiSlaveType::SafeInput)
            record.attributes.emplace_back("model", slave.model);
        record.attributes.emplace_back("param", hexText(slave.parameter));
        if (hasProfile(slave.type, slave.model)) {
            record.attributes.emplace_back("profile", profileWord(slave.profile));
            record.attributes.emplace_back("id1", hexText(slave.profile.id1));
        }
        if (hasChannels(slave.type)) {
            record.attributes.emplace_back("monitoring", monitoringWord(slave.monitoring));
            if (usesTimeLimit(slave.monitoring))
                record.attributes.emplace_back("time_limit_ms", std::to_string(slave.timeLimitMs));
        }
        records.push_back(std::move(record));
    }
    return records;
}

void readAsiRecord(const Annotation& record, std::map<int, AsiOptions>& options) {
    if (record.kind == "asi")
        readUnitRecord(record, options);
    else
        readSlaveRecord(record, options);
}

} // namespace rs::project
