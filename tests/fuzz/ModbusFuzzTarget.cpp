// SPDX-License-Identifier: GPL-3.0-or-later
#include "FuzzFailure.h"

#include "gateway/GatewayNode.h"
#include "gateway/ModbusFrame.h"

#include <algorithm>
#include <cstdint>

namespace {

using rs::fuzz::fail;

} // namespace

// Any bytes clients send, frame after frame, to a gateway on a bus without
// Plutos: each frame is read or refused, and the answers keep the map's rules
// (a read of unit 33 returns exactly the registers asked for, within its
// table and the 100-register limit; unit 1 keeps its length; no write of
// unit 4 leaves settings outside the manual's ranges).
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    rs::sim::Simulation simulation({});
    rs::gateway::GatewayNode node(0, rs::project::Gateway{});
    node.exchange(simulation);
    while (size > 0) {
        // Each frame says its length in bytes 4-5 (MBAP); a short one ends the input.
        const std::size_t length =
            size >= 6 ? std::min<std::size_t>(size, 6 + (std::size_t{data[4]} << 8 | data[5]))
                      : size;
        const auto request = rs::gateway::readModbusFrame(data, length);
        data += length;
        size -= length;
        if (!request)
            continue;
        const rs::gateway::DataFromPluto table = node.dataFromPluto();
        const rs::gateway::ModbusResponse response = node.answer(*request);
        simulation.scan();
        node.exchange(simulation);
        if (node.dataToPluto()[0] != rs::gateway::kDataToPlutoLength)
            fail("the length of Data to Pluto changed");
        if (rs::project::gatewayProblem(node.settings()))
            fail("a configuration write left settings out of range");
        if (response.exception != rs::gateway::ModbusException::None) {
            if (!response.registers.empty())
                fail("an exception with registers");
            continue;
        }
        if (request->function == 3 &&
            response.registers.size() != static_cast<std::size_t>(request->count))
            fail("a read returned another number of registers than asked");
        if (request->unit != rs::gateway::kDataFromPlutoUnit)
            continue;
        if (request->function != 3 || request->count < 1 ||
            request->count > rs::gateway::kMaxRegistersPerRequest ||
            request->address < rs::gateway::kDataFromPlutoFirst ||
            request->address + request->count - 1 > rs::gateway::kDataFromPlutoLast)
            fail("a request outside unit 33 was answered");
        for (int i = 0; i < request->count; ++i)
            if (response.registers[static_cast<std::size_t>(i)] !=
                table[static_cast<std::size_t>(request->address + i)])
                fail("a read returned other registers than the table's");
    }
    return 0;
}
