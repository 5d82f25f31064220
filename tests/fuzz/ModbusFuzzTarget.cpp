// SPDX-License-Identifier: GPL-3.0-or-later
#include "gateway/ModbusFrame.h"
#include "gateway/ModbusMap.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace {

[[noreturn]] void fail(const char* what) {
    std::fprintf(stderr, "%s\n", what);
    std::abort();
}

} // namespace

// Any bytes a client sends: the frame is read or refused, and an answer keeps
// the map's rules (a read returns exactly the registers asked for, within
// unit 33's table and the 100-register limit).
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto request = rs::gateway::readModbusFrame(data, size);
    if (!request)
        return 0;
    rs::gateway::DataFromPluto table{};
    for (std::size_t i = 0; i < table.size(); ++i)
        table[i] = static_cast<std::uint16_t>(i * 257);
    rs::gateway::DataToPluto toPluto = rs::gateway::kNoDataToPluto;
    const rs::gateway::ModbusResponse response = rs::gateway::answer(*request, table, toPluto);
    if (toPluto[0] != rs::gateway::kDataToPlutoLength)
        fail("the length of Data to Pluto changed");
    if (request->unit == rs::gateway::kDataToPlutoUnit)
        return 0;
    if (response.exception != rs::gateway::ModbusException::None) {
        if (!response.registers.empty())
            fail("an exception with registers");
        return 0;
    }
    if (request->unit != rs::gateway::kDataFromPlutoUnit || request->function != 3 ||
        request->count < 1 || request->count > rs::gateway::kMaxRegistersPerRequest ||
        request->address < rs::gateway::kDataFromPlutoFirst ||
        request->address + request->count - 1 > rs::gateway::kDataFromPlutoLast)
        fail("a request outside the map was answered");
    if (response.registers.size() != static_cast<std::size_t>(request->count))
        fail("a read returned another number of registers than asked");
    for (int i = 0; i < request->count; ++i)
        if (response.registers[static_cast<std::size_t>(i)] !=
            table[static_cast<std::size_t>(request->address + i)])
            fail("a read returned other registers than the table's");
    return 0;
}
