// SPDX-License-Identifier: GPL-3.0-or-later
#include "Scenario.h"

#include "lang/TextCase.h"
#include "sim/ScenarioReader.h"
#include "sim/ScenarioRun.h"

#include <cctype>
#include <limits>

namespace rs::pl110 {

namespace {

// The runner's view of the engine: a PL110 has one unit, no bus and no AS-i.
class Plant {
public:
    explicit Plant(ScanEngine& engine) : m_engine(engine) {}
    void restart() { m_engine.reset(); }
    void scan() { m_engine.scan(); }
    std::int64_t timeMs() const { return m_engine.timeMs(); }
    void setCycleMs(int cycleMs) { m_engine.setCycleMs(cycleMs); }
    void set(const Address& address, std::int64_t value) { m_engine.set(address, value); }
    void setChannel(const Address& address, int, bool on) { m_engine.set(address, on); }
    void release(const Address& address) { m_engine.release(address); }
    void setOnBus(int, bool) {}
    std::int64_t value(const Address& address) const { return m_engine.value(address); }
    const ScanEngine& engine() const { return m_engine; }

private:
    ScanEngine& m_engine;
};

} // namespace

ScenarioNames::ScenarioNames(const Program& program) {
    for (const Line& line : program.declarations)
        if (const auto* declaration = std::get_if<NameDeclaration>(&line.body))
            m_names.emplace_back(lang::toUpper(declaration->name), declaration->variable.address);
}

bool ScenarioNames::resolve(std::string_view word, Address& address, std::string& error) const {
    const AddressReading reading = readAddress(word);
    if (reading.shape == AddressReading::Shape::Address) {
        address = reading.address;
        return true;
    }
    if (reading.shape == AddressReading::Shape::Malformed) {
        error = reading.error;
        return false;
    }
    const std::string key = lang::toUpper(word);
    for (const auto& [name, declared] : m_names)
        if (name == key) {
            address = declared;
            return true;
        }
    error = "unknown operand '" + std::string(word) + "': use an address or a declared name";
    return false;
}

bool ScenarioNames::resolveChannel(std::string_view word, Address& address, int& channel,
                                   std::string& error) const {
    channel = 0;
    return resolve(word, address, error);
}

sim::ValueRange ScenarioNames::range(const Address& address) const {
    switch (address.width) {
    case Width::Bit:
        return {0, 1, "a bit"};
    case Width::Word:
        return {kWordMin, kWordMax, "a word"};
    case Width::Double:
        break;
    }
    return {std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max(),
            "a double word"};
}

Scenario parseScenario(std::string_view text, const ScenarioNames& names) {
    return sim::readScenario(text, names);
}

sim::ScenarioReport runScenario(const std::string& fileName, const Scenario& scenario,
                                ScanEngine& engine,
                                const std::function<void(const ScanEngine&)>& sample) {
    Plant plant(engine);
    return sim::runScenarioOn(fileName, scenario, plant, [&](const Plant& now) {
        if (sample)
            sample(now.engine());
    });
}

} // namespace rs::pl110
