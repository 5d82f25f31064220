// SPDX-License-Identifier: GPL-3.0-or-later
#include "ModbusFrame.h"

namespace rs::gateway {

namespace {

int word(const std::uint8_t* bytes) {
    return bytes[0] << 8 | bytes[1];
}

} // namespace

std::optional<ModbusRequest> readModbusFrame(const std::uint8_t* bytes, std::size_t length) {
    // The length field counts the unit identifier and the PDU.
    if (length < kMbapHeaderLength + 1 ||
        static_cast<std::size_t>(word(bytes + 4)) != length - (kMbapHeaderLength - 1))
        return std::nullopt;
    const std::uint8_t* pdu = bytes + kMbapHeaderLength;
    const std::size_t pduLength = length - kMbapHeaderLength;
    ModbusRequest request;
    request.unit = bytes[kMbapHeaderLength - 1];
    request.function = pdu[0];
    if (pduLength >= 5) {
        request.address = word(pdu + 1);
        request.count = word(pdu + 3);
    }
    if (request.function == 16 && pduLength >= 6) {
        const std::size_t byteCount = pdu[5];
        for (std::size_t i = 0; i + 1 < byteCount && 6 + i + 1 < pduLength; i += 2)
            request.values.push_back(static_cast<std::uint16_t>(word(pdu + 6 + i)));
    }
    return request;
}

} // namespace rs::gateway
