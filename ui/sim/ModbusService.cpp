// SPDX-License-Identifier: GPL-3.0-or-later
#include "sim/ModbusService.h"

#include "gateway/ModbusTcpServer.h"

#include <QMetaObject>

namespace rs::ui {

ModbusService::ModbusService(Answer answer, QObject* parent)
    : QObject(parent), m_answer(std::move(answer)) {}

ModbusService::~ModbusService() {
    stop();
}

QString ModbusService::start(const QString& host, int port) {
    stop();
    std::string error;
    m_server = gateway::ModbusTcpServer::listen(host.toStdString(), port, error);
    if (!m_server)
        return QString::fromStdString(error);
    m_address = QStringLiteral("%1:%2").arg(host).arg(m_server->port());
    m_stop = false;
    m_thread = std::thread([this, server = m_server.get()] {
        while (!m_stop)
            server->serve(100, m_answer,
                          [this](const gateway::ModbusTcpServer::ClientEvent& event) {
                              const QString peer = QString::fromStdString(event.peer);
                              const QString text = QString::fromStdString(event.text);
                              const bool connected = event.connected;
                              QMetaObject::invokeMethod(
                                  this,
                                  [this, peer, text, connected] {
                                      if (connected)
                                          m_clients << peer;
                                      else
                                          m_clients.removeOne(peer);
                                      emit clientsChanged();
                                      emit message(text);
                                  },
                                  Qt::QueuedConnection);
                          });
    });
    emit servingChanged();
    return {};
}

void ModbusService::stop() {
    if (!m_server)
        return;
    m_stop = true;
    m_thread.join();
    m_server.reset(); // closes every client
    m_clients.clear();
    m_address.clear();
    emit clientsChanged();
    emit servingChanged();
}

} // namespace rs::ui
