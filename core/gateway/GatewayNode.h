// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "LocalDataRequest.h"
#include "ModbusMap.h"
#include "project/Gateway.h"
#include "sim/Simulation.h"

#include <array>
#include <cstdint>

// A gateway running on the simulated bus (Gateway manual 4; docs/gateway.md):
// it takes the Plutos' global data and their ToGateway telegrams, sends Data
// to Pluto to their External Comm Blocks, and answers its fieldbus side,
// here the Modbus TCP map of Appendix D. Not thread-safe: a caller that
// answers requests on another thread than the one that scans holds one lock
// around answer() and exchange().
namespace rs::gateway {

// "The gateway has 300 ms timeout on additional data" (manual 4.3.4).
inline constexpr int kAdditionalDataTimeoutMs = 300;

class GatewayNode {
public:
    GatewayNode(int node, project::Gateway settings);

    int node() const { return m_node; }
    // The project's settings, as the fieldbus has since changed them (unit 4).
    const project::Gateway& settings() const { return m_settings; }

    // After each scan of `simulation`: the units' telegrams go into the
    // additional data areas configured for them (the first such area only,
    // manual 4.3), an area without one for 300 ms reads 0 again; Data to
    // Pluto goes out once a cycle time, each enabled packet to the units
    // that receive it, and is cleared after the timeout without a fieldbus
    // write; a pending local data request is answered; unit 33 is renewed.
    void exchange(sim::Simulation& simulation);

    // A request of the fieldbus side, on every unit of the map.
    ModbusResponse answer(const ModbusRequest& request);

    // Unit 33 as of the last exchange: Node Status, each Pluto's global
    // data, the additional data areas.
    const DataFromPluto& dataFromPluto() const { return m_fromPluto; }
    const DataToPluto& dataToPluto() const { return m_toPluto; }
    std::uint32_t additionalData(int area) const;

private:
    void takeTelegrams(const sim::Simulation& simulation);
    void sendToPluto(sim::Simulation& simulation);

    int m_node;
    project::Gateway m_settings;
    DataFromPluto m_fromPluto{};
    DataToPluto m_toPluto = kNoDataToPluto;
    LocalDataTables m_localData;
    std::array<std::uint32_t, project::kGatewayAreas> m_areas{};
    std::array<std::int64_t, project::kGatewayAreas> m_areaReceivedMs{};
    bool m_written = false; // a fieldbus write since the last exchange
    bool m_hasData = false; // written and not yet timed out
    std::int64_t m_writtenMs = 0;
    std::int64_t m_nextCycleMs = 0;
};

} // namespace rs::gateway
