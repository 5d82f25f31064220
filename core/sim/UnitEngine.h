// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Conduction.h"
#include "GatewayTelegram.h"
#include "Timer.h"
#include "UnitMemory.h"
#include "compiler/Image.h"

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

namespace rs::sim {

// Runs one unit's compiled image, scan by scan, on virtual time. It reads
// other units' global variables from the bus image it is given, as they were
// at the start of the scan, never from their live memory. How it runs a scan
// is in core/sim/engine/ (docs/simulator.md, "Speed").
class UnitEngine {
public:
    using Bus = std::array<UnitMemory, 32>;

    UnitEngine(compiler::UnitImage image, const Bus& published);
    ~UnitEngine();
    UnitEngine(const UnitEngine&) = delete;
    UnitEngine& operator=(const UnitEngine&) = delete;

    // Power on: every variable 0 except the remanent ones listed (R100..R131,
    // M100..M131 as configured), sequences in step 0, timers and edges fresh,
    // the next scan is the first (SM_SysInit).
    void powerOn(const std::vector<lang::Address>& keep = {});

    // One scan at virtual time `timeMs`, `cycleMs` after the previous one.
    void scan(std::int64_t timeMs, int cycleMs);

    const compiler::UnitImage& image() const;
    UnitMemory& memory();
    const UnitMemory& memory() const;
    int activeStep(int sequence) const;
    bool hasSequence(int sequence) const;
    // What each instruction did in the last scan. A scan runs without marking
    // conduction; the first call after it runs that scan again, marking, from
    // the state the scan started with (docs/simulator.md, "What a scan
    // reports"), so, like scan(), it must not run alongside another call.
    const std::vector<Conduction>& conduction() const;
    // The state of each instruction's element on its own in the last scan,
    // whatever power reached it (ElementState bits, indexed like the code): a
    // contact closed, a comparison true, a timer's output on or counting, a
    // bit output's variable 1 after the scan. Marked with the conduction, so
    // the same rules apply.
    const std::vector<std::uint8_t>& elementStates() const;
    // Marks conduction while scanning instead, for callers that read it after
    // every scan.
    void setEagerConduction(bool eager);
    bool eagerConduction() const;
    // The state of timer occurrence `slot` (Instruction::slot of a Timer), to
    // show its elapsed time.
    const Timer& timer(std::size_t slot) const;

    // The units on the bus, for SM_Pluto0_Present .. SM_Pluto31_Present.
    void setPresent(const std::array<bool, 32>& present);
    // The units whose variables this unit cannot reach over the bus (it or
    // they are off it): they read 0. A unit of another project stays
    // reachable, its variables set from outside.
    void setCutOff(const std::array<bool, 32>& cutOff);

    // A forced variable keeps its value: the program's writes to it are dropped.
    void force(const lang::Address& address, std::int64_t value);
    void release(const lang::Address& address);
    const std::map<lang::Address, std::int64_t>& forces() const;

    // The telegrams the unit's ToGateway blocks sent in the last scan.
    const std::vector<GatewayTelegram>& telegrams() const;

    // Reads and writes a variable of this unit as a scenario or the GUI does.
    std::int64_t read(const lang::Address& address) const;
    void write(const lang::Address& address, std::int64_t value);

private:
    struct Tiers; // the scan state and the ways to run it, in UnitEngine.cpp

    void decode();
    void runSteps(bool marking, int cycleMs);
    void replay();
    void applyForces();

    std::unique_ptr<Tiers> m_tiers;
};

} // namespace rs::sim
