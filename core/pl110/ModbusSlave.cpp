// SPDX-License-Identifier: GPL-3.0-or-later
#include "ModbusSlave.h"

#include "ProgramCheck.h"

#include <optional>

namespace rs::pl110 {

namespace {

enum Function : std::uint8_t {
    ReadCoils = 1,
    ReadDiscreteInputs = 2,
    ReadHoldingRegisters = 3,
    ReadInputRegisters = 4,
    WriteSingleCoil = 5,
    WriteSingleRegister = 6,
    WriteMultipleCoils = 15,
    WriteMultipleRegisters = 16,
};

enum Exception : std::uint8_t { IllegalFunction = 1, IllegalDataAddress = 2, IllegalDataValue = 3 };

// What one Modbus bit address is: a bit of memory, and whether a master may write it.
struct BitPlace {
    Address address;
    bool writable = false;
};

std::optional<BitPlace> bitAt(int modbus) {
    for (const AreaInfo& info : areaTable()) {
        if (info.modbusBit < 0 || modbus < info.modbusBit)
            continue;
        const int offset = modbus - info.modbusBit;
        Address address{info.area, Width::Bit, 0, -1};
        if (info.bitsOfWords) {
            // The datasheet maps bits of SM0-SM129 and of every V word.
            const int words = info.area == Area::SpecialMarker ? 130 : info.last - info.first + 1;
            if (offset >= 16 * words)
                continue;
            address.number = info.first + offset / 16;
            address.bit = offset % 16;
        } else {
            if (offset > info.last - info.first)
                continue;
            address.number = info.first + offset;
        }
        const bool contactOfValue = info.area == Area::Timer || info.area == Area::Counter;
        return BitPlace{address,
                        info.modbusWrites && !contactOfValue && !isReadOnlySpecial(address)};
    }
    return std::nullopt;
}

// What one Modbus word address is: a word of an area, or sixteen packed bits.
struct WordPlace {
    Area area = Area::Input;
    int word = 0;          // index into the area's words, or the packed word
    bool contacts = false; // the packed contacts of T or C
    bool writable = false;
};

std::optional<WordPlace> wordAt(int modbus) {
    for (const AreaInfo& info : areaTable()) {
        if (info.modbusContactWord >= 0 && modbus >= info.modbusContactWord &&
            modbus < info.modbusContactWord + (info.last - info.first + 16) / 16)
            return WordPlace{info.area, modbus - info.modbusContactWord, true, false};
        if (info.modbusWord < 0 || modbus < info.modbusWord ||
            modbus >= info.modbusWord + wordCount(info.area))
            continue;
        WordPlace place{info.area, modbus - info.modbusWord, false, false};
        // Input words are read only, their bits writable (docs/pl110.md, A13).
        place.writable = info.modbusWrites && info.area != Area::Input &&
                         !isReadOnlySpecial({info.area, Width::Word, info.first + place.word, -1});
        return place;
    }
    return std::nullopt;
}

std::uint16_t readWord(const Memory& memory, const WordPlace& place) {
    if (!place.contacts)
        return memory
            .words[static_cast<std::size_t>(place.area)][static_cast<std::size_t>(place.word)];
    std::uint16_t packed = 0;
    for (int bit = 0; bit < 16; ++bit) {
        const int number = 16 * place.word + bit + 1;
        if (number <= areaInfo(place.area).last && memory.bit({place.area, Width::Bit, number, -1}))
            packed = static_cast<std::uint16_t>(packed | (1U << bit));
    }
    return packed;
}

int word16(std::span<const std::uint8_t> data, std::size_t at) {
    return (data[at] << 8) | data[at + 1];
}

std::vector<std::uint8_t> exception(std::uint8_t function, Exception code) {
    return {static_cast<std::uint8_t>(function | 0x80), code};
}

} // namespace

std::vector<std::uint8_t> answerRequest(Memory& memory, std::span<const std::uint8_t> request) {
    if (request.empty())
        return exception(0, IllegalFunction);
    const std::uint8_t function = request[0];
    const auto data = request.subspan(1);
    const auto needs = [&](std::size_t bytes) {
        return data.size() >= bytes;
    };
    switch (function) {
    case ReadCoils:
    case ReadDiscreteInputs: {
        if (!needs(4))
            return exception(function, IllegalDataValue);
        const int first = word16(data, 0);
        const int count = word16(data, 2);
        if (count < 1 || count > kMaxBitsPerRequest)
            return exception(function, IllegalDataValue);
        std::vector<std::uint8_t> answer{function, static_cast<std::uint8_t>((count + 7) / 8)};
        answer.resize(2 + static_cast<std::size_t>((count + 7) / 8), 0);
        for (int i = 0; i < count; ++i) {
            const auto place = bitAt(first + i);
            if (!place)
                return exception(function, IllegalDataAddress);
            if (memory.bit(place->address))
                answer[2 + static_cast<std::size_t>(i / 8)] |=
                    static_cast<std::uint8_t>(1U << (i % 8));
        }
        return answer;
    }
    case ReadHoldingRegisters:
    case ReadInputRegisters: {
        if (!needs(4))
            return exception(function, IllegalDataValue);
        const int first = word16(data, 0);
        const int count = word16(data, 2);
        if (count < 1 || count > kMaxWordsPerRequest)
            return exception(function, IllegalDataValue);
        std::vector<std::uint8_t> answer{function, static_cast<std::uint8_t>(2 * count)};
        for (int i = 0; i < count; ++i) {
            const auto place = wordAt(first + i);
            if (!place)
                return exception(function, IllegalDataAddress);
            const std::uint16_t value = readWord(memory, *place);
            answer.push_back(static_cast<std::uint8_t>(value >> 8));
            answer.push_back(static_cast<std::uint8_t>(value & 0xFF));
        }
        return answer;
    }
    case WriteSingleCoil: {
        if (!needs(4))
            return exception(function, IllegalDataValue);
        const int value = word16(data, 2);
        if (value != 0xFF00 && value != 0)
            return exception(function, IllegalDataValue);
        const auto place = bitAt(word16(data, 0));
        if (!place || !place->writable)
            return exception(function, IllegalDataAddress);
        memory.setBit(place->address, value == 0xFF00);
        return {request.begin(), request.begin() + 5};
    }
    case WriteSingleRegister: {
        if (!needs(4))
            return exception(function, IllegalDataValue);
        const auto place = wordAt(word16(data, 0));
        if (!place || !place->writable)
            return exception(function, IllegalDataAddress);
        memory.words[static_cast<std::size_t>(place->area)][static_cast<std::size_t>(place->word)] =
            static_cast<std::uint16_t>(word16(data, 2));
        return {request.begin(), request.begin() + 5};
    }
    case WriteMultipleCoils:
    case WriteMultipleRegisters: {
        if (!needs(5))
            return exception(function, IllegalDataValue);
        const int first = word16(data, 0);
        const int count = word16(data, 2);
        const std::size_t bytes = data[4];
        const bool coils = function == WriteMultipleCoils;
        const int most = coils ? kMaxBitsPerRequest : kMaxWordsPerRequest;
        const std::size_t expected =
            coils ? static_cast<std::size_t>((count + 7) / 8) : static_cast<std::size_t>(2 * count);
        if (count < 1 || count > most || bytes != expected || !needs(5 + bytes))
            return exception(function, IllegalDataValue);
        // Every address is checked before anything is written: a refused
        // request changes nothing.
        for (int i = 0; i < count; ++i) {
            const bool writable = coils ? bitAt(first + i) && bitAt(first + i)->writable
                                        : wordAt(first + i) && wordAt(first + i)->writable;
            if (!writable)
                return exception(function, IllegalDataAddress);
        }
        for (int i = 0; i < count; ++i) {
            if (coils) {
                const bool on = (data[5 + static_cast<std::size_t>(i / 8)] >> (i % 8)) & 1U;
                memory.setBit(bitAt(first + i)->address, on);
            } else {
                const WordPlace place = *wordAt(first + i);
                memory.words[static_cast<std::size_t>(place.area)]
                            [static_cast<std::size_t>(place.word)] =
                    static_cast<std::uint16_t>(word16(data, 5 + 2 * static_cast<std::size_t>(i)));
            }
        }
        return {request.begin(), request.begin() + 5};
    }
    default:
        return exception(function, IllegalFunction);
    }
}

} // namespace rs::pl110
