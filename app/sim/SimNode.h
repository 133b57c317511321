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
    void handle(const QNetworkDatagram &datagram);
    void sendTo(const neptus::msg::Message &message, const QHostAddress &address, quint16 port);
    void tick();
    static double wallTime();

    struct Peer
    {
        QHostAddress address;
        quint16 port = 0;
        qint64 heardMs = -1;
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
    // Like DUNE: systems that announced an imc+udp service, heard in the last 30 s.
    QHash<quint16, Peer> m_peers;
    QSet<quint16> m_ignored;
};
