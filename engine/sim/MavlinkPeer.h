#pragma once

#include "messages/MavlinkCodec.h"
#include "sim/MavlinkAutopilot.h"

#include <QElapsedTimer>
#include <QHostAddress>
#include <QObject>
#include <QTimer>
#include <QTcpServer>
#include <QTcpSocket>
#include <QUdpSocket>

#include <memory>

namespace neptus::sim {

// A MavlinkAutopilot on UDP, as ArduPilot's SITL or a telemetry radio's
// bridge presents a vehicle: it sends to the ground station's address
// (14550 by default) from its own port and answers whoever talks to it; or
// on TCP, as SITL's first serial port (5760): it listens, and talks to the
// ground station that connects (one at a time, the last one in).
// MAVLink 2, system `system`, component 1 (the autopilot).
// With a signing key it is a telemetry channel of an ArduPilot whose key is
// set (GCS_Signing.cpp): it signs what it sends and silently drops unsigned
// frames (but a radio's RADIO_STATUS and RADIO), frames whose signature does
// not verify, and replays (a stream's timestamp not newer than its last, or
// a new stream's more than a minute old).
class MavlinkPeer : public QObject
{
    Q_OBJECT

public:
    struct Config
    {
        MavlinkAutopilot::Config autopilot;
        quint8 system = 1;
        QHostAddress bindAddress = QHostAddress::LocalHost;
        quint16 port = 0; // its own; 0: any free one
        QHostAddress groundAddress = QHostAddress::LocalHost;
        quint16 groundPort = 14550;
        double timeFactor = 1.0; // simulated seconds a second
        bool tcp = false;        // listen on `port` for a ground station instead of UDP
        QByteArray signingKey;   // 32 bytes: sign, and take only frames signed with it
    };

    MavlinkPeer(std::shared_ptr<const msg::Schema> mavlink, Config config, QObject *parent = nullptr);
    // Binds and starts talking; an error says why not.
    std::expected<void, QString> start();
    quint16 port() const { return m_config.tcp ? m_server.serverPort() : m_socket.localPort(); }
    MavlinkAutopilot &autopilot() { return m_autopilot; }
    // Frames it received that did not decode.
    int badFrames() const { return m_bad; }
    // Frames it dropped for their signing (unsigned, wrongly signed, replayed).
    int refusedFrames() const { return m_refused; }

private:
    void tick();
    void read();
    void send(const std::vector<msg::Message> &messages, const QHostAddress &to, quint16 port);
    void answer(QByteArrayView frame, const QHostAddress &from, quint16 port);
    double now() const;
    bool signedWell(QByteArrayView frame, const msg::MavlinkFrame &header);

    msg::MavlinkCodec m_codec;
    Config m_config;
    MavlinkAutopilot m_autopilot;
    QUdpSocket m_socket;
    QTcpServer m_server;
    QTcpSocket *m_client = nullptr; // the ground station connected over TCP
    std::unique_ptr<msg::MavlinkFramer> m_framer;
    QTimer m_timer;
    QElapsedTimer m_clock;
    quint8 m_sequence = 0;
    int m_bad = 0;
    int m_refused = 0;
    msg::MavlinkSigning m_signing;
    msg::MavlinkSigningStreams m_streams;
};

} // namespace neptus::sim
