// SPDX-License-Identifier: GPL-3.0-or-later
#include "Baseline.h"

#include "lang/Address.h"

#include <cstdio>
#include <sstream>

namespace rs::project {

namespace {

std::string hex(std::uint32_t value) {
    char text[9];
    std::snprintf(text, sizeof text, "%08X", static_cast<unsigned>(value));
    return text;
}

std::uint32_t readHex(const std::string& text, const char* what) {
    if (text.size() != 8 || text.find_first_not_of("0123456789ABCDEFabcdef") != std::string::npos)
        throw BaselineRecordError{std::string("@validated ") + what +
                                  " must be 8 hexadecimal digits, not '" + text + "'"};
    return static_cast<std::uint32_t>(std::stoul(text, nullptr, 16));
}

// "S0.0_0:1A2B3C4D,5E6F7A8B S0.1_0:" : each step, then its networks.
std::string networkList(int station, const ValidatedUnit& unit) {
    std::string text;
    for (const auto& [step, networks] : unit.networks) {
        if (!text.empty())
            text += ' ';
        text += lang::toString(lang::StepAddress{station, step.first, step.second}) + ':';
        for (std::size_t i = 0; i < networks.size(); ++i)
            text += (i ? "," : "") + hex(networks[i]);
    }
    return text;
}

void readNetworkList(const std::string& text, int station, ValidatedUnit& unit) {
    std::istringstream words(text);
    std::string word;
    while (words >> word) {
        const auto colon = word.find(':');
        const lang::AddressWord step = lang::readAddressWord(word.substr(0, colon));
        if (colon == std::string::npos || step.shape != lang::AddressWord::Shape::Step ||
            step.step.unit != station)
            throw BaselineRecordError{"@validated networks: '" + word +
                                      "' is not a step of this unit and its networks, as in "
                                      "S0.0_0:1A2B3C4D,5E6F7A8B"};
        auto& networks = unit.networks[{step.step.sequence, step.step.step}];
        std::istringstream list(word.substr(colon + 1));
        for (std::string item; std::getline(list, item, ',');)
            networks.push_back(readHex(item, "networks"));
    }
}

} // namespace

std::vector<Annotation> baselineRecords(const Baseline& baseline) {
    std::vector<Annotation> records;
    Annotation project{"validated", {}, {}};
    project.attributes = {{"date", baseline.date},
                          {"by", baseline.by},
                          {"comment", baseline.comment},
                          {"signature", hex(baseline.signature)}};
    records.push_back(std::move(project));
    for (const auto& [station, unit] : baseline.units) {
        Annotation record{"validated", {(station < 10 ? "0" : "") + std::to_string(station)}, {}};
        record.attributes = {{"signature", hex(unit.signature)},
                             {"networks", networkList(station, unit)}};
        records.push_back(std::move(record));
    }
    return records;
}

void readBaselineRecord(const Annotation& record, Baseline& baseline) {
    if (record.arguments.empty()) {
        baseline.date = record.value("date");
        baseline.by = record.value("by");
        baseline.comment = record.value("comment");
        baseline.signature = readHex(record.value("signature"), "signature");
        return;
    }
    const std::string& word = record.arguments[0];
    if (word.empty() || word.size() > 2 ||
        word.find_first_not_of("0123456789") != std::string::npos || std::stoi(word) > 31)
        throw BaselineRecordError{"@validated needs a station number 0-31 for a unit, as in "
                                  ";@validated 00 signature=\"1A2B3C4D\""};
    const int station = std::stoi(word);
    ValidatedUnit& unit = baseline.units[station];
    unit.signature = readHex(record.value("signature"), "signature");
    readNetworkList(record.value("networks"), station, unit);
}

} // namespace rs::project
