#pragma once

#include "messages/MavlinkCodec.h"
#include "sim/MavlinkAutopilot.h"

#include <QElapsedTimer>
#include <QHostAddress>
#include <QObject>
#include <QTimer>
#include <QUdpSocket>

namespace neptus::sim {

// A MavlinkAutopilot on UDP, as ArduPilot's SITL or a telemetry radio's
// bridge presents a vehicle: it sends to the ground station's address
// (14550 by default) from its own port and answers whoever talks to it.
// MAVLink 2, system `system`, component 1 (the autopilot).
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
    };

    MavlinkPeer(std::shared_ptr<const msg::Schema> mavlink, Config config, QObject *parent = nullptr);
    // Binds and starts talking; an error says why not.
    std::expected<void, QString> start();
    quint16 port() const { return m_socket.localPort(); }
    MavlinkAutopilot &autopilot() { return m_autopilot; }
    // Frames it received that did not decode, and those it answered.
    int badFrames() const { return m_bad; }

private:
    void tick();
    void read();
    void send(const std::vector<msg::Message> &messages, const QHostAddress &to, quint16 port);
    double now() const;

    msg::MavlinkCodec m_codec;
    Config m_config;
    MavlinkAutopilot m_autopilot;
    QUdpSocket m_socket;
    QTimer m_timer;
    QElapsedTimer m_clock;
    quint8 m_sequence = 0;
    int m_bad = 0;
};

} // namespace neptus::sim
