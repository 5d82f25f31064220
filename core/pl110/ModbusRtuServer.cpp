// SPDX-License-Identifier: GPL-3.0-or-later
#include "ModbusRtuServer.h"

#include <modbus.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

namespace rs::pl110 {

struct ModbusRtuServer::Impl {
    modbus_t* context = nullptr;
    int master = -1;
    int slaveSide = -1; // held open so the line stays up between clients
    int address = 1;

    ~Impl() {
        if (context)
            modbus_free(context);
        if (slaveSide >= 0)
            ::close(slaveSide);
        if (master >= 0)
            ::close(master);
    }
};

ModbusRtuServer::ModbusRtuServer(std::unique_ptr<Impl> impl, std::string devicePath)
    : m_impl(std::move(impl)), m_devicePath(std::move(devicePath)) {}

ModbusRtuServer::~ModbusRtuServer() = default;

std::unique_ptr<ModbusRtuServer> ModbusRtuServer::open(int slave, std::string& error) {
    if (slave < 1 || slave > 247) {
        error = "the slave address must be 1-247";
        return nullptr;
    }
    auto impl = std::make_unique<Impl>();
    impl->address = slave;
    impl->master = ::posix_openpt(O_RDWR | O_NOCTTY);
    if (impl->master < 0 || ::grantpt(impl->master) != 0 || ::unlockpt(impl->master) != 0) {
        error = std::string("cannot open a pseudo-terminal: ") + std::strerror(errno);
        return nullptr;
    }
    const char* name = ::ptsname(impl->master);
    if (!name) {
        error = std::string("cannot name the pseudo-terminal: ") + std::strerror(errno);
        return nullptr;
    }
    std::string devicePath = name;
    impl->slaveSide = ::open(name, O_RDWR | O_NOCTTY);
    termios raw{};
    if (impl->slaveSide < 0 || ::tcgetattr(impl->slaveSide, &raw) != 0) {
        error = "cannot open " + devicePath + ": " + std::strerror(errno);
        return nullptr;
    }
    // Raw bytes both ways: no echo, no line editing, no character translation.
    ::cfmakeraw(&raw);
    ::tcsetattr(impl->slaveSide, TCSANOW, &raw);
    // libmodbus frames and checks on the master side; the device name is not
    // opened (no modbus_connect), the pseudo-terminal is the socket.
    impl->context = modbus_new_rtu(devicePath.c_str(), 19200, 'N', 8, 1);
    if (!impl->context) {
        error = std::string("cannot start Modbus RTU: ") + modbus_strerror(errno);
        return nullptr;
    }
    modbus_set_socket(impl->context, impl->master);
    modbus_set_slave(impl->context, slave);
    return std::unique_ptr<ModbusRtuServer>(new ModbusRtuServer(std::move(impl), devicePath));
}

int ModbusRtuServer::descriptor() const {
    return m_impl->master;
}

void ModbusRtuServer::serve(int waitMs, const Answer& answer) {
    modbus_t* context = m_impl->context;
    modbus_set_indication_timeout(context, static_cast<std::uint32_t>(waitMs / 1000),
                                  static_cast<std::uint32_t>(waitMs % 1000) * 1000);
    std::uint8_t frame[MODBUS_RTU_MAX_ADU_LENGTH];
    const int length = modbus_receive(context, frame);
    if (length <= 0) {
        // A timeout, another slave's frame, or a broken one: drop what came.
        if (length < 0 && errno != ETIMEDOUT)
            modbus_flush(context);
        return;
    }
    // The frame is address, PDU, CRC.
    const std::span<const std::uint8_t> pdu(frame + 1, static_cast<std::size_t>(length) - 3);
    const std::vector<std::uint8_t> response = answer(pdu);
    if (frame[0] == MODBUS_BROADCAST_ADDRESS)
        return;
    std::vector<std::uint8_t> raw;
    raw.reserve(response.size() + 1);
    raw.push_back(static_cast<std::uint8_t>(m_impl->address));
    raw.insert(raw.end(), response.begin(), response.end());
    modbus_send_raw_request(context, raw.data(), static_cast<int>(raw.size()));
}

} // namespace rs::pl110
