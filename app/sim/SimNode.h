#pragma once

#include "messages/Codec.h"
#include "sim/Scenario.h"
#include "sim/SimulatedVehicle.h"
#include "transport/dds/DdsTransport.h"

#include <QElapsedTimer>
#include <QHash>
#include <QHostAddress>
#include <QNetworkDatagram>
#include <QObject>
#include <QSet>
#include <QTimer>
#include <QUdpSocket>

#include <expected>
#include <memory>

// One simulated vehicle on the air: its IMC/UDP socket (and the IMC discovery
// ports when like DUNE), optionally a DDS participant, and the 20 ms timer
// that steps it and sends what it says to the consoles that talk to it.
//
// Like DUNE (--like-dune), as its Transports.Discovery and Transports.UDP
// tasks do (src/Transports/UDP/Task.cpp, Listener.hpp, NodeTable.hpp): a
// console becomes a node only by an Announce on the discovery port (not on
// the vehicle's own port; the first imc+udp address it names is kept, and an
// Announce repeating a timestamp from the same address is ignored); its
// packets on the vehicle's port make it a contact, which is activated — the
// vehicle streams to it — only at the next contact refresh, every 5 s from
// start, and only if it sends from the address it announced; 30 s without a
// packet and it is dropped at the next refresh. Everything the vehicle says,
// replies included, goes to every active node.
class SimNode : public QObject
{
    Q_OBJECT

public:
    struct Options
    {
        neptus::sim::ScenarioVehicle vehicle;
        QList<std::pair<QHostAddress, quint16>> announceTo; // consoles or discovery ports to announce to
        int ddsDomain = 0;
        QString ddsKeys, ddsIdentity;
        double timeFactor = 1;
    };

    SimNode(std::shared_ptr<const neptus::msg::Schema> schema, Options options, QObject *parent = nullptr);

    // Opens its sockets and links and starts; an error says why not.
    std::expected<void, QString> start();

private:
    void handle(const QNetworkDatagram &datagram, bool discovery);
    // Like DUNE: contacts heard within 30 s from their announced address become active, others not.
    void refreshContacts();
    void sendTo(const neptus::msg::Message &message, const QHostAddress &address, quint16 port);
    void tick();
    static double wallTime();

    struct Peer
    {
        QHostAddress address; // its announced imc+udp address
        quint16 port = 0;
        qint64 heardMs = -1;  // a packet on the vehicle's port
        QHostAddress heardFrom;
        bool active = false;  // streamed to (since a refresh)
    };

    std::shared_ptr<const neptus::msg::Schema> m_schema;
    Options m_options;
    neptus::msg::Codec m_codec;
    neptus::sim::SimulatedVehicle m_vehicle;
    QUdpSocket m_socket;
    QUdpSocket m_discovery;
    std::unique_ptr<neptus::transport::DdsTransport> m_dds;
    QElapsedTimer m_clock;
    QTimer m_timer;
    double m_previous = -1;
    QByteArray m_buffer;
    // Plain: consoles heard from, and when (it streams to them for 5 s after each Heartbeat).
    QHash<QPair<QString, quint16>, qint64> m_consoles;
    // Like DUNE: systems that announced an imc+udp service on the discovery port.
    QHash<quint16, Peer> m_peers;
    QSet<quint16> m_ignored;
    QHash<QString, double> m_announceStamps; // the last Announce timestamp per address
    qint64 m_refreshedMs = 0;
};
