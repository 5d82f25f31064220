// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

// Modbus RTU on a pseudo-terminal, with libmodbus: the simulated PL110's
// serial port. A client opens devicePath() as it would a serial line
// (mbpoll -m rtu DEVICE); baud rate and format mean nothing on a
// pseudo-terminal, so any are accepted.
namespace rs::pl110 {

class ModbusRtuServer {
public:
    // A request's PDU (function and data) in, the answer's PDU out.
    using Answer = std::function<std::vector<std::uint8_t>(std::span<const std::uint8_t>)>;

    // Opens a pseudo-terminal answering as `slave` (1-247); nothing and the
    // reason when it cannot.
    static std::unique_ptr<ModbusRtuServer> open(int slave, std::string& error);
    ~ModbusRtuServer();
    ModbusRtuServer(const ModbusRtuServer&) = delete;
    ModbusRtuServer& operator=(const ModbusRtuServer&) = delete;

    const std::string& devicePath() const { return m_devicePath; }
    // The pseudo-terminal's master side: readable when a client has sent
    // something, for an event loop to wait on instead of a thread.
    int descriptor() const;
    // Waits up to `waitMs` for one frame and answers it: requests to this
    // slave get `answer`'s PDU back, broadcasts (address 0) are carried out
    // without an answer, frames for other slaves and frames with a bad CRC
    // are dropped.
    void serve(int waitMs, const Answer& answer);

private:
    struct Impl;
    ModbusRtuServer(std::unique_ptr<Impl> impl, std::string devicePath);

    std::unique_ptr<Impl> m_impl;
    std::string m_devicePath;
};

} // namespace rs::pl110
