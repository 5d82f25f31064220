// SPDX-License-Identifier: GPL-3.0-or-later
#include "UnitMemory.h"

namespace rs::sim {

namespace {

using lang::AddressKind;

template <typename Array> auto* at(Array& array, int index) {
    return index >= 0 && index < static_cast<int>(array.size())
               ? &array[static_cast<std::size_t>(index)]
               : nullptr;
}

BitRef byteRef(std::uint8_t* byte) {
    BitRef ref;
    if (byte) {
        ref.kind = BitRef::Kind::Byte;
        ref.byte = byte;
    }
    return ref;
}

} // namespace

bool readsAsNumber(AddressKind kind) {
    switch (kind) {
    case AddressKind::Register:
    case AddressKind::DoubleRegister:
    case AddressKind::DoubleRegisterLow:
    case AddressKind::DoubleRegisterHigh:
    case AddressKind::SystemRegister:
    case AddressKind::AnalogInput:
        return true;
    default:
        return false;
    }
}

BitRef bitRef(UnitMemory& m, const lang::Address& a, bool forWriting) {
    switch (a.kind) {
    case AddressKind::Input:
        return byteRef(at(m.inputs, a.index));
    case AddressKind::Output:
        return byteRef(at(m.outputs, a.index));
    case AddressKind::InputOutput:
        // An illuminated push button: the button is read, the lamp is written.
        return byteRef(forWriting ? at(m.outputs, a.index) : at(m.inputs, a.index));
    case AddressKind::AnalogInput: {
        BitRef ref;
        if (auto* value = at(m.analogInputs, a.index)) {
            ref.kind = BitRef::Kind::Analog;
            ref.wide = value;
        }
        return ref;
    }
    case AddressKind::Memory:
        return byteRef(at(m.memories, a.index));
    case AddressKind::GlobalMemory:
        return byteRef(at(m.globalMemories, a.index));
    case AddressKind::SystemMemory:
        return byteRef(at(m.systemMemories, a.index));
    case AddressKind::RegisterBit: {
        BitRef ref;
        if (auto* word = at(m.registers, a.index); word && a.bit >= 0 && a.bit < 16) {
            ref.kind = BitRef::Kind::RegisterBit;
            ref.word = word;
            ref.bit = a.bit;
        }
        return ref;
    }
    case AddressKind::AsiInput:
        if (a.bit < 0)
            return byteRef(at(m.asiSafeInputs, a.index));
        [[fallthrough]];
    case AddressKind::AsiOutput: {
        auto& slaves = a.kind == AddressKind::AsiInput ? m.asiInputs : m.asiOutputs;
        auto* slave = at(slaves, a.index + (a.asiB ? 32 : 0));
        return byteRef(slave && a.bit >= 1 && a.bit <= 4
                           ? &(*slave)[static_cast<std::size_t>(a.bit - 1)]
                           : nullptr);
    }
    default:
        return {};
    }
}

WordRef wordRef(UnitMemory& m, const lang::Address& a) {
    WordRef ref;
    switch (a.kind) {
    case AddressKind::Register:
    case AddressKind::DoubleRegisterLow:
        if ((ref.word = at(m.registers, a.index)))
            ref.kind = WordRef::Kind::Register;
        break;
    case AddressKind::DoubleRegisterHigh:
        if ((ref.word = at(m.registers, a.index + 1)))
            ref.kind = WordRef::Kind::Register;
        break;
    case AddressKind::DoubleRegister:
        if (a.index % 2 == 0 && a.index + 1 < UnitMemory::kRegisters) {
            ref.word = &m.registers[static_cast<std::size_t>(a.index)];
            ref.kind = WordRef::Kind::Double;
        }
        break;
    case AddressKind::SystemRegister:
        if ((ref.wide = at(m.systemRegisters, a.index)))
            ref.kind = WordRef::Kind::Wide;
        break;
    case AddressKind::AnalogInput:
        if ((ref.wide = at(m.analogInputs, a.index)))
            ref.kind = WordRef::Kind::Wide;
        break;
    default:
        break;
    }
    return ref;
}

} // namespace rs::sim
