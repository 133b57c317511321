#pragma once

#include "Codec.h"
#include "VariableTree.h"

#include <QHash>
#include <QHostAddress>
#include <QList>
#include <QObject>
#include <QTimer>
#include <QUdpSocket>

#include <expected>
#include <memory>

namespace neptus::transport {

// How the console meets IMC vehicles over UDP. Everything defaults to
// loopback; a field setup names the boat network's address explicitly.
struct ImcUdpConfig
{
    QHostAddress bindAddress = QHostAddress::LocalHost;
    quint16 port = 6001;                 // 0: any free port (tests)
    // Vehicles known in advance, as host and port; their ids are learned
    // from what they send.
    QList<std::pair<QHostAddress, quint16>> destinations;
    // Listen for vehicles' Announce messages (IMC uses 30100-30104).
    bool discovery = false;
    quint16 discoveryPort = 30100;       // 0: any free port (tests)
    quint16 systemId = 0x4001;           // a CCU id (0x4000-0x5FFF)
    QString systemName = QStringLiteral("neptus-qt");
    int heartbeatMs = 1000;
};

// IMC over UDP, one packet per datagram. The console announces itself (an
// imc+udp:// service, system type CCU) and sends a Heartbeat every second to
// every vehicle it knows, since IMC vehicles only stream to consoles they
// hear from. Vehicles are known from the static destinations and, with
// discovery on, from their Announce. Commands go to the vehicle's own id (IMC
// vehicles ignore 0xFFFF). Our own messages relayed back are dropped.
class ImcUdpTransport : public QObject, public tree::VariableTree::OutputSink
{
    Q_OBJECT

public:
    ImcUdpTransport(std::shared_ptr<const msg::Schema> schema, ImcUdpConfig config, QObject *parent = nullptr);

    // Binds the sockets; an error names the address and port and why.
    std::expected<void, QString> start();
    quint16 port() const { return m_socket.localPort(); }
    quint16 discoveryPort() const { return m_discovery.localPort(); }
    QList<quint16> knownSystems() const { return m_endpoints.keys(); }
    int decodeErrors() const { return m_decodeErrors; }

    // OutputSink: sends `message` to `system`, addressed to it.
    bool publish(quint16 system, const msg::Message &message) override;

    // Sends a Heartbeat (and every fifth time an Announce) to every vehicle now.
    void heartbeat();

signals:
    void received(const neptus::msg::Message &message);
    void systemDiscovered(quint16 system, const QString &name);

private:
    struct Endpoint
    {
        QHostAddress address;
        quint16 port = 0;
    };

    void readDatagrams(QUdpSocket &socket);
    void handle(const QByteArray &datagram, const QHostAddress &from, quint16 fromPort);
    void learnFromAnnounce(const msg::Message &announce);
    void send(const msg::Message &message, const Endpoint &to);
    msg::Message announcement() const;

    msg::Codec m_codec;
    ImcUdpConfig m_config;
    QUdpSocket m_socket;
    QUdpSocket m_discovery;
    QTimer m_timer;
    QHash<quint16, Endpoint> m_endpoints; // known vehicles
    int m_ticks = 0;
    int m_decodeErrors = 0;
    QByteArray m_buffer;
};

} // namespace neptus::transport
