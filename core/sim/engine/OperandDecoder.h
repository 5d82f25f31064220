// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "DecodedInstruction.h"
#include "compiler/Image.h"
#include "sim/UnitMemory.h"

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

namespace rs::sim::engine {

// Resolves each instruction's operand to where it lives: the unit's memory, a
// sink for forced targets (so that the program's writes to them are dropped),
// or a private copy of the other units' variables it reads, refreshed from the
// bus at the start of each scan so that a replay sees what the scan saw.
class OperandDecoder {
public:
    using Bus = std::array<UnitMemory, 32>;

    OperandDecoder(int station, UnitMemory& memory, const Bus& bus);

    // The image's code with operands resolved, the forced variables' writes to the sink.
    std::vector<DecodedInstruction> decode(const std::vector<compiler::Instruction>& code,
                                           const std::map<lang::Address, std::int64_t>& forces);
    // Copies the other units' variables that the code reads from the bus;
    // those of a unit cut off from this one read 0.
    void readBus(const std::array<bool, 32>& cutOff);

private:
    struct RemoteCopy {
        std::uint8_t* to;
        const std::uint8_t* from;
        std::size_t size;
        std::size_t station;
    };
    UnitMemory& remoteCopy(int station);
    template <typename Ref>
    Ref readRemote(const lang::Address& address, Ref (*locate)(UnitMemory&, const lang::Address&));
    BitRef decodeBit(const lang::Address& address, bool forWriting, bool forced);
    WordRef decodeWord(const lang::Address& address);

    int m_station;
    UnitMemory& m_memory;
    const Bus& m_bus;
    UnitMemory m_sink;                                    // where writes to forced variables go
    std::array<std::unique_ptr<UnitMemory>, 32> m_remote; // other units' variables as last read
    std::vector<RemoteCopy> m_remoteCopies;
};

} // namespace rs::sim::engine
