// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "SafeInputChannels.h"
#include "UnitEngine.h"

#include <memory>
#include <vector>

namespace rs::sim {

// A project's units running together on one simulated bus, on virtual time.
// Every unit sees the others' global variables as they were at the end of
// the previous scan cycle, whatever order the units scan in, so a run is the
// same every time.
class Simulation {
public:
    explicit Simulation(std::vector<compiler::UnitImage> images, int cycleMs = 10);

    // Power on again: virtual time 0, every unit in its first scan.
    void restart();

    // One scan cycle: every unit scans once, then the bus carries the results.
    void scan();
    // Whole scans until at least `ms` of virtual time has passed.
    void run(std::int64_t ms);

    std::int64_t timeMs() const { return m_timeMs; }
    std::uint64_t scans() const { return m_scans; }
    int cycleMs() const { return m_cycleMs; }
    void setCycleMs(int ms) { m_cycleMs = ms; }

    std::vector<int> stations() const;
    UnitEngine* unit(int station);
    const UnitEngine* unit(int station) const;

    // What station `station` last put on the bus (its variables as the other
    // units and a gateway see them); all 0 for a station out of 0-31.
    const UnitMemory& published(int station) const;

    // Reads any variable of any unit; S<u>.<s> gives sequence s's active step.
    std::int64_t value(const lang::Address& address) const;
    // Inputs (I, IQ buttons, IA, AS-i inputs) and system registers that stand
    // for measured values (supply voltage, I5 voltage, Q16/Q17 current) take
    // the value from the next scan on; any other variable is forced.
    void set(const lang::Address& address, std::int64_t value);
    void force(const lang::Address& address, std::int64_t value);
    void release(const lang::Address& address);

    // The two channels of a safe input slave that the unit's AS-i options
    // define (ASi<u>.<x>, `address`): set() of its input sets both. False, and
    // nothing set, for any other address.
    bool setChannel(const lang::Address& address, int channel, bool closed);
    bool hasChannels(const lang::Address& address) const;
    bool channel(const lang::Address& address, int channel) const;

    // Remanent variables (R100..R131, M100..M131 as configured) of a unit,
    // kept by restart().
    void setRemanent(int station, std::vector<lang::Address> addresses);

    // Takes a unit off the bus (a cable pulled) or puts it back, from the next
    // scan on. A unit off the bus runs on alone: it sees no other unit and no
    // other sees it (SM_Pluto<n>_Present 0, its global variables read 0 on the
    // others and theirs 0 on it). restart() puts every unit back.
    void setOnBus(int station, bool on);
    bool isOnBus(int station) const;

    // A Data to Pluto packet of gateway `node` on the bus (Gateway manual
    // 4.4): every unit whose External communication setting takes packet
    // `packet` of that gateway receives it into the block set for it, from
    // the next scan on. A packet that is not `valid` (the fieldbus marked its
    // area invalid, or the gateway timed it out) clears the block. A block
    // that receives nothing for its timeout is cleared too.
    struct Packet {
        bool valid = false;
        std::uint16_t bits = 0; // bit i is data bit 16 * block + i
        std::int16_t register0 = 0;
        std::int16_t register1 = 0;
    };
    void deliverPacket(int node, int packet, const Packet& data);

private:
    struct SlaveChannels {
        lang::Address input; // ASi<u>.<x>
        SafeInputChannels channels;
    };

    // Every unit's variables onto the bus; with `due`, only those of the units
    // whose CAN bus cycle time has come round.
    void publish(bool due = false);
    void updateChannels();
    void timeOutExternalBlocks();
    SlaveChannels* slaveChannels(const lang::Address& address);
    void tellPresence();

    std::unique_ptr<UnitEngine::Bus> m_bus; // stable address: engines point into it
    std::vector<std::unique_ptr<UnitEngine>> m_units;
    std::array<std::vector<lang::Address>, 32> m_remanent;
    std::array<bool, 32> m_offBus{};
    std::vector<SlaveChannels> m_channels;          // by station and slave
    std::array<std::int64_t, 32> m_nextPublishMs{}; // units with a CAN bus cycle time
    // When each unit's External Comm Blocks last received a packet.
    std::array<std::array<std::int64_t, UnitMemory::kExternalBlocks>, 32> m_receivedMs{};
    int m_cycleMs;
    std::int64_t m_timeMs = 0;
    std::uint64_t m_scans = 0;
};

// Whether set() gives this variable a value as the outside world would
// (an input or a measured value) rather than forcing it.
bool isOutsideValue(const lang::Address& address);

} // namespace rs::sim
