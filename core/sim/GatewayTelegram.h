// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <cstdint>

namespace rs::sim {

// A telegram a ToGateway block sent in a scan (Gateway manual 4.3.4): its
// IO-type (a user block's number 1-99, a standard block's 100-113) and its
// four bytes as the UDINT byte0 | byte1 << 8 | byte2 << 16 | byte3 << 24.
struct GatewayTelegram {
    int ioType = 0;
    std::uint32_t data = 0;

    friend bool operator==(const GatewayTelegram&, const GatewayTelegram&) = default;
};

// "Pluto can only send 4 telegrams every PLC cycle" (Gateway manual 4.3.4).
inline constexpr std::size_t kTelegramsPerScan = 4;

} // namespace rs::sim
