// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Holds core types by value; Qt 6.4's moc cannot parse the C++20 headers
// they bring in and needs only the names.
#ifndef Q_MOC_RUN
#include "gateway/ModbusMap.h"
#endif

#include <QObject>
#include <QStringList>

#include <atomic>
#include <functional>
#include <memory>
#include <thread>

namespace rs::gateway {
class ModbusTcpServer;
}

namespace rs::ui {

// Modbus TCP served while simulating (docs/gateway.md): a server on a thread
// of its own, so that no client ever holds up the scans or the window, which
// hands each request to `answer` (called on that thread) and tells the window
// which clients are connected.
class ModbusService : public QObject {
    Q_OBJECT
public:
    using Answer = std::function<gateway::ModbusResponse(const gateway::ModbusRequest&)>;

    explicit ModbusService(Answer answer, QObject* parent = nullptr);
    ~ModbusService() override;

    // Listens on host:port; why it cannot, empty when it serves.
    QString start(const QString& host, int port);
    void stop();
    bool isServing() const { return m_server != nullptr; }
    QString address() const { return m_address; } // "127.0.0.1:1502"
    QStringList clients() const { return m_clients; }

signals:
    void servingChanged();
    void clientsChanged();
    void message(const QString& text);

private:
    Answer m_answer;
    std::unique_ptr<gateway::ModbusTcpServer> m_server;
    std::thread m_thread;
    std::atomic<bool> m_stop{false};
    QString m_address;
    QStringList m_clients;
};

} // namespace rs::ui
