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
    for (auto& image : images) {
        for (const auto& slave : image.asi.slaves)
            if (project::hasChannels(static_cast<project::AsiSlaveType>(slave.type)) && !slave.b)
                m_channels.push_back(
                    {{lang::AddressKind::AsiInput, image.station, slave.number},
                     SafeInputChannels(static_cast<project::ChannelMonitoring>(slave.monitoring),
                                       slave.timeLimitMs)});
        m_units.push_back(std::make_unique<UnitEngine>(std::move(image), *m_bus));
    }
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
    for (auto& slave : m_channels)
        slave.channels.powerOn();
    for (auto& unit : m_units)
        unit->powerOn(m_remanent[unit->image().station % 32]);
    m_timeMs = 0;
    m_scans = 0;
    m_receivedMs = {};
    publish();
}

// A unit with the default CAN bus cycle time publishes after every scan; one
// with a cycle time set publishes at the end of the first scan at or past each
// multiple of it, so the others see its variables up to that much later.
void Simulation::publish(bool due) {
    for (const auto& unit : m_units) {
        const auto station = static_cast<std::size_t>(unit->image().station % 32);
        if (const int cycle = unit->image().canCycleMs) {
            if (due && m_timeMs < m_nextPublishMs[station])
                continue;
            m_nextPublishMs[station] = (m_timeMs / cycle + 1) * cycle;
        }
        (*m_bus)[station] = unit->memory();
    }
}

// Each safe slave's input from its channels, and each AS-i unit's
// SR_ASi_Slave_Chanf: the lowest slave in channel fault, 0 when none is.
void Simulation::updateChannels() {
    constexpr int kSlaveChannelFault = 16;
    UnitEngine* engine = nullptr;
    int firstFault = 0;
    for (std::size_t i = 0; i < m_channels.size(); ++i) {
        SlaveChannels& slave = m_channels[i];
        if (!engine)
            engine = unit(slave.input.unit);
        slave.channels.update(m_timeMs);
        engine->write(slave.input, slave.channels.input() ? 1 : 0);
        if (slave.channels.fault() && firstFault == 0)
            firstFault = slave.input.index;
        if (i + 1 == m_channels.size() || m_channels[i + 1].input.unit != slave.input.unit) {
            engine->write({lang::AddressKind::SystemRegister, slave.input.unit, kSlaveChannelFault},
                          firstFault);
            engine = nullptr;
            firstFault = 0;
        }
    }
}

void Simulation::deliverPacket(int node, int packet, const Packet& data) {
    for (auto& unit : m_units) {
        const auto station = static_cast<std::size_t>(unit->image().station % 32);
        if (m_offBus[station])
            continue;
        UnitMemory& memory = unit->memory();
        for (const auto& block : unit->image().externalComm) {
            if (block.gateway != node || block.packet != packet)
                continue;
            const std::size_t b = block.block;
            memory.externalValid[b] = data.valid;
            memory.externalBits[b] = data.valid ? data.bits : 0;
            memory.externalRegisters[2 * b] = data.valid ? data.register0 : 0;
            memory.externalRegisters[2 * b + 1] = data.valid ? data.register1 : 0;
            m_receivedMs[station][b] = m_timeMs;
        }
    }
}

void Simulation::timeOutExternalBlocks() {
    for (auto& unit : m_units) {
        const auto station = static_cast<std::size_t>(unit->image().station % 32);
        UnitMemory& memory = unit->memory();
        for (const auto& block : unit->image().externalComm) {
            const std::size_t b = block.block;
            if (memory.externalValid[b] && block.timeoutMs != 0 &&
                m_timeMs - m_receivedMs[station][b] > block.timeoutMs) {
                memory.externalValid[b] = 0;
                memory.externalBits[b] = 0;
                memory.externalRegisters[2 * b] = 0;
                memory.externalRegisters[2 * b + 1] = 0;
            }
        }
    }
}

void Simulation::scan() {
    updateChannels();
    timeOutExternalBlocks();
    for (auto& unit : m_units)
        unit->scan(m_timeMs, m_cycleMs);
    ++m_scans;
    m_timeMs += m_cycleMs;
    publish(true);
}

void Simulation::run(std::int64_t ms) {
    const std::int64_t end = m_timeMs + ms;
    while (m_timeMs < end)
        scan();
}

const UnitMemory& Simulation::published(int station) const {
    static const UnitMemory kNone{};
    return station >= 0 && station < 32 ? (*m_bus)[static_cast<std::size_t>(station)] : kNone;
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

Simulation::SlaveChannels* Simulation::slaveChannels(const lang::Address& address) {
    if (address.kind != lang::AddressKind::AsiInput || address.bit != -1 || address.asiB)
        return nullptr;
    for (auto& slave : m_channels)
        if (slave.input == address)
            return &slave;
    return nullptr;
}

bool Simulation::hasChannels(const lang::Address& address) const {
    return const_cast<Simulation*>(this)->slaveChannels(address) != nullptr;
}

bool Simulation::setChannel(const lang::Address& address, int channel, bool closed) {
    SlaveChannels* slave = slaveChannels(address);
    if (slave)
        slave->channels.setChannel(channel, closed);
    return slave != nullptr;
}

bool Simulation::channel(const lang::Address& address, int channel) const {
    const SlaveChannels* slave = const_cast<Simulation*>(this)->slaveChannels(address);
    return slave && slave->channels.channel(channel);
}

void Simulation::set(const lang::Address& address, std::int64_t value) {
    if (SlaveChannels* slave = slaveChannels(address)) {
        slave->channels.setChannel(1, value != 0);
        slave->channels.setChannel(2, value != 0);
        return;
    }
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
