// SPDX-License-Identifier: GPL-3.0-or-later
#include "ModbusTcpServer.h"

#include "ModbusFrame.h"

#include <modbus/modbus.h>

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/select.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <vector>

namespace rs::gateway {

namespace {

constexpr int kBacklog = 64;

std::string peerName(int socket) {
    sockaddr_in peer{};
    socklen_t length = sizeof peer;
    if (getpeername(socket, reinterpret_cast<sockaddr*>(&peer), &length) != 0)
        return "a client";
    char text[INET_ADDRSTRLEN] = {};
    inet_ntop(AF_INET, &peer.sin_addr, text, sizeof text);
    return std::string(text) + ":" + std::to_string(ntohs(peer.sin_port));
}

} // namespace

struct ModbusTcpServer::Impl {
    modbus_t* context = nullptr;
    int listener = -1;
    std::vector<int> clients;

    ~Impl() {
        for (int client : clients)
            close(client);
        if (listener >= 0)
            close(listener);
        if (context)
            modbus_free(context);
    }

    void drop(int client, const Log& log, const std::string& why) {
        const std::string peer = peerName(client);
        log({peer, false, "client " + peer + " " + why});
        close(client);
        std::erase(clients, client);
    }
};

ModbusTcpServer::ModbusTcpServer(std::unique_ptr<Impl> impl, int port)
    : m_impl(std::move(impl)), m_port(port) {}

ModbusTcpServer::~ModbusTcpServer() = default;

std::unique_ptr<ModbusTcpServer> ModbusTcpServer::listen(const std::string& host, int port,
                                                         std::string& error) {
    auto impl = std::make_unique<Impl>();
    impl->context = modbus_new_tcp(host.c_str(), port);
    if (!impl->context) {
        error = std::strerror(errno);
        return nullptr;
    }
    // A client stalled in the middle of a frame is given up after a second.
    modbus_set_indication_timeout(impl->context, 1, 0);
    impl->listener = modbus_tcp_listen(impl->context, kBacklog);
    if (impl->listener < 0) {
        error =
            "cannot listen on " + host + ":" + std::to_string(port) + ": " + modbus_strerror(errno);
        return nullptr;
    }
    fcntl(impl->listener, F_SETFL, fcntl(impl->listener, F_GETFL) | O_NONBLOCK);
    sockaddr_in bound{};
    socklen_t length = sizeof bound;
    getsockname(impl->listener, reinterpret_cast<sockaddr*>(&bound), &length);
    return std::unique_ptr<ModbusTcpServer>(
        new ModbusTcpServer(std::move(impl), ntohs(bound.sin_port)));
}

int ModbusTcpServer::clients() const {
    return static_cast<int>(m_impl->clients.size());
}

void ModbusTcpServer::serve(int waitMs, const Answer& answer, const Log& log) {
    Impl& s = *m_impl;
    fd_set ready;
    FD_ZERO(&ready);
    FD_SET(s.listener, &ready);
    int highest = s.listener;
    for (int client : s.clients) {
        FD_SET(client, &ready);
        highest = std::max(highest, client);
    }
    timeval timeout{waitMs / 1000, (waitMs % 1000) * 1000};
    if (select(highest + 1, &ready, nullptr, nullptr, &timeout) <= 0)
        return;
    // Every waiting connection at once (the listener does not block), so that
    // many clients connecting together never overflow the backlog.
    if (FD_ISSET(s.listener, &ready))
        for (int listener = s.listener;;) {
            const int client = modbus_tcp_accept(s.context, &listener);
            if (client < 0)
                break;
            if (client >= FD_SETSIZE) {
                close(client); // select() cannot watch it
                continue;
            }
            s.clients.push_back(client);
            const std::string peer = peerName(client);
            log({peer, true, "client " + peer + " connected"});
        }
    const int header = modbus_get_header_length(s.context);
    const std::vector<int> watched = s.clients;
    for (int client : watched) {
        if (!FD_ISSET(client, &ready))
            continue;
        modbus_set_socket(s.context, client);
        std::uint8_t frame[MODBUS_TCP_MAX_ADU_LENGTH];
        const int length = modbus_receive(s.context, frame);
        if (length <= 0) {
            // libmodbus reports a client's close as ECONNRESET.
            s.drop(client, log,
                   errno == ECONNRESET ? "left"
                                       : std::string("dropped: ") + modbus_strerror(errno));
            continue;
        }
        const std::optional<ModbusRequest> request =
            readModbusFrame(frame, static_cast<std::size_t>(length));
        if (!request || header != static_cast<int>(kMbapHeaderLength)) {
            s.drop(client, log, "dropped: a malformed frame");
            continue;
        }
        const ModbusResponse response = answer(*request);
        int sent = 0;
        if (response.exception != ModbusException::None) {
            sent =
                modbus_reply_exception(s.context, frame, static_cast<unsigned>(response.exception));
        } else {
            modbus_mapping_t* mapping = modbus_mapping_new_start_address(
                0, 0, 0, 0, static_cast<unsigned>(request->address),
                static_cast<unsigned>(std::max<int>(request->count, 1)), 0, 0);
            std::copy(response.registers.begin(), response.registers.end(), mapping->tab_registers);
            sent = modbus_reply(s.context, frame, length, mapping);
            modbus_mapping_free(mapping);
        }
        if (sent < 0)
            s.drop(client, log, "left");
    }
}

} // namespace rs::gateway
