// SPDX-License-Identifier: GPL-3.0-or-later
#include "Scenario.h"

#include "lang/TextCase.h"
#include "sim/ScenarioReader.h"
#include "sim/ScenarioRun.h"

#include <algorithm>
#include <limits>
#include <set>

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
                                const std::function<void(const ScanEngine&)>& sample,
                                const sim::CancelRequest& cancelled) {
    Plant plant(engine);
    return sim::runScenarioOn(
        fileName, scenario, plant,
        [&](const Plant& now) {
            if (sample)
                sample(now.engine());
        },
        cancelled);
}

std::vector<Address> touchedBy(const Scenario& scenario) {
    std::vector<Address> touched;
    for (const auto& step : scenario.steps)
        if (step.kind == Scenario::Step::Kind::Set || step.kind == Scenario::Step::Kind::Release ||
            step.kind == Scenario::Step::Kind::Expect)
            touched.push_back(step.operand);
    return touched;
}

std::vector<Address> traceSignals(const Program& program, const std::vector<Address>& touched) {
    std::set<Address> variables(touched.begin(), touched.end());
    for (const auto* lines : {&program.init, &program.main})
        for (const Line& line : *lines) {
            const auto* rung = std::get_if<Rung>(&line.body);
            if (!rung)
                continue;
            const Address& target = rung->output.target.address;
            variables.insert(target);
            if (rung->output.kind == OutputKind::Timer || rung->output.kind == OutputKind::Counter)
                variables.insert(asWord(target)); // the value beside the contact
        }
    return {variables.begin(), variables.end()};
}

std::vector<sim::VcdSignal> vcdSignals(const std::vector<Address>& variables) {
    std::vector<sim::VcdSignal> traced;
    for (const Address& address : variables) {
        std::string reference = toString(address);
        std::replace(reference.begin(), reference.end(), '.', '_');
        // T1 and C1 name a contact and a value: the value's signal says so.
        if ((address.area == Area::Timer || address.area == Area::Counter) &&
            address.width == Width::Word)
            reference += "_value";
        traced.push_back({"pl110", reference, address.width == Width::Bit});
    }
    return traced;
}

} // namespace rs::pl110
