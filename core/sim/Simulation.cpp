// SPDX-License-Identifier: GPL-3.0-or-later
#include "Simulation.h"

#include <algorithm>

namespace rs::sim {

bool isOutsideValue(const lang::Address& address) {
    switch (address.kind) {
    case lang::AddressKind::Input:
    case lang::AddressKind::InputOutput:
    case lang::AddressKind::AnalogInput:
        return true;
    case lang::AddressKind::AsiInput:
        return true;
    case lang::AddressKind::SystemRegister:
        return address.index >= 40 && address.index <= 46; // voltages and currents
    default:
        return false;
    }
}

Simulation::Simulation(std::vector<compiler::UnitImage> images, int cycleMs)
    : m_bus(std::make_unique<UnitEngine::Bus>()), m_cycleMs(cycleMs) {
    std::sort(images.begin(), images.end(),
              [](const auto& a, const auto& b) { return a.station < b.station; });
    for (auto& image : images)
        m_units.push_back(std::make_unique<UnitEngine>(std::move(image), *m_bus));
    tellPresence();
    publish();
}

void Simulation::tellPresence() {
    std::array<bool, 32> onBus{};
    for (const auto& unit : m_units) {
        const auto station = static_cast<std::size_t>(unit->image().station % 32);
        onBus[station] = !m_offBus[station];
    }
    for (auto& unit : m_units) {
        const auto station = static_cast<std::size_t>(unit->image().station % 32);
        std::array<bool, 32> cutOff{};
        for (std::size_t other = 0; other < 32; ++other)
            cutOff[other] = other != station && (m_offBus[station] || m_offBus[other]);
        unit->setPresent(m_offBus[station] ? std::array<bool, 32>{} // setPresent adds the unit
                                           : onBus);
        unit->setCutOff(cutOff);
    }
}

void Simulation::setOnBus(int station, bool on) {
    m_offBus[static_cast<std::size_t>(station) % 32] = !on;
    tellPresence();
}

bool Simulation::isOnBus(int station) const {
    return !m_offBus[static_cast<std::size_t>(station) % 32];
}

std::vector<int> Simulation::stations() const {
    std::vector<int> stations;
    for (const auto& unit : m_units)
        stations.push_back(unit->image().station);
    return stations;
}

UnitEngine* Simulation::unit(int station) {
    for (auto& unit : m_units)
        if (unit->image().station == station)
            return unit.get();
    return nullptr;
}

const UnitEngine* Simulation::unit(int station) const {
    return const_cast<Simulation*>(this)->unit(station);
}

void Simulation::setRemanent(int station, std::vector<lang::Address> addresses) {
    m_remanent[static_cast<std::size_t>(station) % 32] = std::move(addresses);
}

void Simulation::restart() {
    m_offBus = {};
    tellPresence();
    for (auto& unit : m_units)
        unit->powerOn(m_remanent[unit->image().station % 32]);
    m_timeMs = 0;
    m_scans = 0;
    publish();
}

void Simulation::publish() {
    for (const auto& unit : m_units)
        (*m_bus)[unit->image().station % 32] = unit->memory();
}

void Simulation::scan() {
    for (auto& unit : m_units)
        unit->scan(m_timeMs, m_cycleMs);
    publish();
    ++m_scans;
    m_timeMs += m_cycleMs;
}

void Simulation::run(std::int64_t ms) {
    const std::int64_t end = m_timeMs + ms;
    while (m_timeMs < end)
        scan();
}

// A unit that is not in the project stands for one of another project on
// the bus: its global bits are what its bus slot holds, 0 until set.
std::int64_t Simulation::value(const lang::Address& address) const {
    if (const UnitEngine* engine = unit(address.unit))
        return engine->read(address);
    if (address.unit < 0 || address.unit > 31)
        return 0;
    return bitRef((*m_bus)[static_cast<std::size_t>(address.unit)], address, false).read();
}

void Simulation::set(const lang::Address& address, std::int64_t value) {
    UnitEngine* engine = unit(address.unit);
    if (!engine) {
        if (address.unit >= 0 && address.unit <= 31)
            bitRef((*m_bus)[static_cast<std::size_t>(address.unit)], address, true)
                .write(value != 0);
        return;
    }
    if (isOutsideValue(address))
        engine->write(address, value);
    else
        engine->force(address, value);
}

void Simulation::force(const lang::Address& address, std::int64_t value) {
    if (UnitEngine* engine = unit(address.unit))
        engine->force(address, value);
}

void Simulation::release(const lang::Address& address) {
    if (UnitEngine* engine = unit(address.unit))
        engine->release(address);
}

} // namespace rs::sim
