// SPDX-License-Identifier: GPL-3.0-or-later
#include "OperandDecoder.h"

#include "InstructionMeaning.h"

#include <algorithm>
#include <cstring>

namespace rs::sim::engine {

namespace {

using compiler::Op;

// The bytes behind a reference, for copying another unit's variable.
std::size_t sizeOf(const BitRef& ref) {
    switch (ref.kind) {
    case BitRef::Kind::Byte:
        return 1;
    case BitRef::Kind::RegisterBit:
        return 2;
    case BitRef::Kind::Analog:
        return 4;
    case BitRef::Kind::None:
        break;
    }
    return 0;
}

std::size_t sizeOf(const WordRef& ref) {
    switch (ref.kind) {
    case WordRef::Kind::Register:
        return 2;
    case WordRef::Kind::Double:
    case WordRef::Kind::Wide:
        return 4;
    case WordRef::Kind::None:
        break;
    }
    return 0;
}

const void* placeOf(const BitRef& ref) {
    return ref.kind == BitRef::Kind::Byte          ? static_cast<const void*>(ref.byte)
           : ref.kind == BitRef::Kind::RegisterBit ? static_cast<const void*>(ref.word)
                                                   : static_cast<const void*>(ref.wide);
}

const void* placeOf(const WordRef& ref) {
    return ref.kind == WordRef::Kind::Wide ? static_cast<const void*>(ref.wide)
                                           : static_cast<const void*>(ref.word);
}

std::uint8_t handlerFor(const DecodedInstruction& d) {
    const bool byte = d.isBitKind(BitRef::Kind::Byte);
    switch (d.op) {
    case Op::Rung:
        return HRung;
    case Op::Contact:
        return byte ? HContactByte : HContact;
    case Op::Edge:
        return HEdge;
    case Op::Timer:
        return HTimer;
    case Op::LoadA:
        return HLoadA;
    case Op::LoadB:
        return HLoadB;
    case Op::Compare:
        return static_cast<std::uint8_t>(HEqual + d.aux);
    case Op::BranchOpen:
        return HBranchOpen;
    case Op::BranchNext:
        return HBranchNext;
    case Op::BranchClose:
        return HBranchClose;
    case Op::Coil:
        return byte ? HCoilByte : HCoil;
    case Op::Set:
        return byte ? HSetByte : HSet;
    case Op::Reset:
        return byte ? HResetByte : HReset;
    case Op::Toggle:
        return HToggle;
    case Op::Jump:
        return HJump;
    case Op::SequenceReset:
        return HSequenceReset;
    case Op::Arith:
        return HArith;
    case Op::System:
        return HSystem;
    case Op::Argument:
        return HArgument;
    }
    return HRung;
}

} // namespace

OperandDecoder::OperandDecoder(int station, UnitMemory& memory, const Bus& bus)
    : m_station(station), m_memory(memory), m_bus(bus) {}

UnitMemory& OperandDecoder::remoteCopy(int station) {
    auto& copy = m_remote[static_cast<std::size_t>(station) % 32];
    if (!copy)
        copy = std::make_unique<UnitMemory>();
    return *copy;
}

template <typename Ref>
Ref OperandDecoder::readRemote(const lang::Address& address,
                               Ref (*locate)(UnitMemory&, const lang::Address&)) {
    const auto station = static_cast<std::size_t>(address.unit) % 32;
    UnitMemory& copy = remoteCopy(address.unit);
    const Ref ref = locate(copy, address);
    if (const std::size_t size = sizeOf(ref)) {
        const auto offset = static_cast<const std::uint8_t*>(placeOf(ref)) -
                            reinterpret_cast<const std::uint8_t*>(&copy);
        m_remoteCopies.push_back({reinterpret_cast<std::uint8_t*>(&copy) + offset,
                                  reinterpret_cast<const std::uint8_t*>(&m_bus[station]) + offset,
                                  size, station});
    }
    return ref;
}

BitRef OperandDecoder::decodeBit(const lang::Address& address, bool forWriting, bool forced) {
    if (address.unit != m_station) // the compiler lets a unit only read others' variables
        return readRemote<BitRef>(address, [](UnitMemory& memory, const lang::Address& a) {
            return bitRef(memory, a, false);
        });
    if (forWriting && forced)
        return bitRef(m_sink, address, true);
    return bitRef(m_memory, address, forWriting);
}

WordRef OperandDecoder::decodeWord(const lang::Address& address) {
    if (address.unit != m_station)
        return readRemote<WordRef>(address, wordRef);
    return wordRef(m_memory, address);
}

std::vector<DecodedInstruction>
OperandDecoder::decode(const std::vector<compiler::Instruction>& code,
                       const std::map<lang::Address, std::int64_t>& forces) {
    m_remoteCopies.clear();
    std::vector<DecodedInstruction> decoded;
    decoded.reserve(code.size());
    for (const auto& in : code) {
        DecodedInstruction d{in.op, 0,     in.flags, in.aux,      0,
                             0,     false, in.slot,  in.constant, nullptr};
        const bool forced = forces.count(in.operand) != 0;
        switch (in.op) {
        case Op::Contact:
        case Op::Edge:
            d.pointAt(decodeBit(in.operand, false, forced));
            break;
        case Op::Coil:
        case Op::Set:
        case Op::Reset:
        case Op::Toggle:
            d.pointAt(decodeBit(in.operand, true, forced));
            break;
        case Op::LoadA:
        case Op::LoadB:
        case Op::Timer:
            if (!(in.flags & compiler::ConstantOperand))
                d.pointAt(decodeWord(in.operand));
            break;
        case Op::Arith:
            d.pointAt(decodeWord(in.operand));
            d.dropWrite = forced;
            d.aux = std::min(d.aux, kUnknownArithmetic);
            break;
        case Op::Argument: {
            // The operand's station, for what a system instruction asks of its unit.
            d.slot = static_cast<std::uint16_t>((in.flags & compiler::ConstantOperand)
                                                    ? m_station
                                                    : std::clamp(in.operand.unit, 0, 31));
            const bool written = in.aux & compiler::ArgumentWritten;
            if (in.flags & compiler::ConstantOperand)
                break;
            if (!(in.aux & compiler::ArgumentWord))
                d.pointAt(decodeBit(in.operand, written, forced));
            else if (written && forced)
                d.pointAt(wordRef(m_sink, in.operand));
            else
                d.pointAt(decodeWord(in.operand));
            break;
        }
        default:
            break;
        }
        d.handler = handlerFor(d);
        decoded.push_back(d);
    }
    std::sort(m_remoteCopies.begin(), m_remoteCopies.end(),
              [](const RemoteCopy& x, const RemoteCopy& y) { return x.to < y.to; });
    m_remoteCopies.erase(std::unique(m_remoteCopies.begin(), m_remoteCopies.end(),
                                     [](const RemoteCopy& x, const RemoteCopy& y) {
                                         return x.to == y.to && x.size == y.size;
                                     }),
                         m_remoteCopies.end());
    return decoded;
}

void OperandDecoder::readBus(const std::array<bool, 32>& cutOff) {
    for (const RemoteCopy& copy : m_remoteCopies) {
        if (cutOff[copy.station])
            std::memset(copy.to, 0, copy.size);
        else
            std::memcpy(copy.to, copy.from, copy.size);
    }
}

} // namespace rs::sim::engine
