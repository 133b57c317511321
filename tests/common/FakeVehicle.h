#pragma once

// A vehicle that behaves like a DUNE vehicle on loopback: it streams only to
// consoles it has heard a Heartbeat from, and keeps the commands addressed
// to its own id. Bound to 127.0.0.1 (or another loopback address, to play a
// second host), on an ephemeral port.
#include "messages/Codec.h"

#include "Schemas.h"

#include <QNetworkDatagram>
#include <QUdpSocket>

#include <vector>

namespace neptus::test {

class FakeVehicle : public QObject
{
public:
    explicit FakeVehicle(quint16 id, const QHostAddress &host = QHostAddress::LocalHost)
        : m_codec(shippedSchema())
        , m_id(id)
    {
        m_socket.bind(host, 0);
        connect(&m_socket, &QUdpSocket::readyRead, this, [this] {
            while (m_socket.hasPendingDatagrams()) {
                const QNetworkDatagram datagram = m_socket.receiveDatagram();
                auto message = m_codec.decode(datagram.data());
                if (!message)
                    continue;
                if (message->abbrev() == u"Heartbeat") {
                    m_console = {datagram.senderAddress(), static_cast<quint16>(datagram.senderPort())};
                    ++heartbeats;
                } else if (message->header.dst == m_id) {
                    commands.push_back(*message);
                }
            }
        });
    }

    quint16 port() const { return m_socket.localPort(); }
    bool streaming() const { return heartbeats > 0; }

    void send(msg::Message message, quint16 toPort)
    {
        message.header.src = m_id;
        m_socket.writeDatagram(*m_codec.encode(message), QHostAddress::LocalHost, toPort);
    }
    // A DUNE vehicle streams to the consoles it heard from, and only to them.
    void streamState(double depth)
    {
        if (!streaming())
            return;
        msg::Message state(shippedSchema()->byAbbrev(u"EstimatedState"));
        state.setNumber(state.def()->indexOf(u"depth"), depth);
        send(state, m_console.second);
    }
    void announceTo(quint16 port)
    {
        msg::Message announce(shippedSchema()->byAbbrev(u"Announce"));
        announce.setBytes(announce.def()->indexOf(u"sys_name"), "lauv-sim-1");
        announce.setInteger(announce.def()->indexOf(u"sys_type"), 2);
        announce.setBytes(announce.def()->indexOf(u"services"),
                          QStringLiteral("dune://0.0.0.0/uid/1/;imc+udp://%1:%2/")
                              .arg(m_socket.localAddress().toString())
                              .arg(this->port())
                              .toUtf8());
        send(announce, port);
    }

    int heartbeats = 0;
    std::vector<msg::Message> commands;

private:
    msg::Codec m_codec;
    quint16 m_id;
    QUdpSocket m_socket;
    std::pair<QHostAddress, quint16> m_console;
};

} // namespace neptus::test
