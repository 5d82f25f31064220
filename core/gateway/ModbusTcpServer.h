// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ModbusMap.h"

#include <functional>
#include <memory>
#include <string>

// Modbus TCP on a socket, with libmodbus: several clients at once, each
// request handed to `answer` by unit identifier, so one port serves every
// table of the gateway's map (libmodbus' TCP side does not filter by unit).
namespace rs::gateway {

class ModbusTcpServer {
public:
    using Answer = std::function<ModbusResponse(const ModbusRequest&)>;
    // A client came or went: its address and port, and a line that says so.
    struct ClientEvent {
        std::string peer;
        bool connected = false;
        std::string text;
    };
    using Log = std::function<void(const ClientEvent&)>;

    // Listens on host:port (port 0: one the system picks); nothing and the
    // reason when it cannot.
    static std::unique_ptr<ModbusTcpServer> listen(const std::string& host, int port,
                                                   std::string& error);
    ~ModbusTcpServer();
    ModbusTcpServer(const ModbusTcpServer&) = delete;
    ModbusTcpServer& operator=(const ModbusTcpServer&) = delete;

    int port() const { return m_port; }
    // Accepts clients and answers their requests for up to `waitMs`. A client
    // that closes, sends a malformed frame or stalls mid-frame for longer
    // than a second is disconnected; the others are not affected.
    void serve(int waitMs, const Answer& answer, const Log& log);
    int clients() const;

private:
    struct Impl;
    explicit ModbusTcpServer(std::unique_ptr<Impl> impl, int port);

    std::unique_ptr<Impl> m_impl;
    int m_port = 0;
};

} // namespace rs::gateway
