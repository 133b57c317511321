#include "sim/MavlinkPeer.h"

#include <QNetworkDatagram>

namespace neptus::sim {

using namespace Qt::StringLiterals;

MavlinkPeer::MavlinkPeer(std::shared_ptr<const msg::Schema> mavlink, Config config, QObject *parent)
    : QObject(parent)
    , m_codec(mavlink)
    , m_config(std::move(config))
    , m_autopilot(mavlink, m_config.autopilot)
{
    m_signing.key = m_config.signingKey;
    m_signing.linkId = 1; // ArduPilot signs with the channel's number; SERIAL1, a telemetry radio
    m_timer.setInterval(50);
    connect(&m_timer, &QTimer::timeout, this, &MavlinkPeer::tick);
    connect(&m_socket, &QUdpSocket::readyRead, this, &MavlinkPeer::read);
}

std::expected<void, QString> MavlinkPeer::start()
{
    if (m_config.tcp) {
        if (!m_server.listen(m_config.bindAddress, m_config.port))
            return std::unexpected(u"cannot listen on TCP %1:%2: %3"_s.arg(m_config.bindAddress.toString()).arg(m_config.port).arg(m_server.errorString()));
        connect(&m_server, &QTcpServer::newConnection, this, [this] {
            while (QTcpSocket *next = m_server.nextPendingConnection()) {
                if (m_client)
                    m_client->deleteLater();
                m_client = next;
                m_framer = std::make_unique<msg::MavlinkFramer>(m_codec);
                connect(next, &QTcpSocket::readyRead, this, [this, next] {
                    if (next != m_client)
                        return;
                    m_framer->feed(next->readAll());
                    while (const auto frame = m_framer->next())
                        answer(*frame, {}, 0);
                });
                connect(next, &QTcpSocket::disconnected, this, [this, next] {
                    if (next == m_client)
                        m_client = nullptr;
                    next->deleteLater();
                });
            }
        });
        m_clock.start();
        m_timer.start();
        return {};
    }
    if (!m_socket.bind(m_config.bindAddress, m_config.port))
        return std::unexpected(u"cannot listen on %1:%2: %3"_s.arg(m_config.bindAddress.toString()).arg(m_config.port).arg(m_socket.errorString()));
    m_clock.start();
    m_timer.start();
    tick();
    return {};
}

double MavlinkPeer::now() const
{
    return m_clock.elapsed() / 1000.0 * m_config.timeFactor;
}

void MavlinkPeer::send(const std::vector<msg::Message> &messages, const QHostAddress &to, quint16 port)
{
    msg::MavlinkCodec::Options options;
    options.system = m_config.system;
    options.component = 1;
    if (!m_signing.key.isEmpty()) {
        m_signing.timestamp = std::max(m_signing.timestamp, msg::MavlinkSigning::now());
        options.signing = &m_signing;
    }
    for (const msg::Message &m : messages) {
        options.sequence = m_sequence++;
        auto frame = m_codec.encode(m, options);
        if (!frame)
            continue;
        if (m_config.tcp) {
            if (m_client && m_client->state() == QAbstractSocket::ConnectedState)
                m_client->write(*frame);
        } else {
            m_socket.writeDatagram(*frame, to, port);
        }
    }
}

void MavlinkPeer::tick()
{
    send(m_autopilot.step(now()), m_config.groundAddress, m_config.groundPort);
}

bool MavlinkPeer::signedWell(QByteArrayView frame, const msg::MavlinkFrame &header)
{
    if (m_signing.key.isEmpty())
        return true;
    if (!header.isSigned)
        return header.messageId == 109 || header.messageId == 166; // accept_unsigned_callback's list
    if (!msg::MavlinkCodec::signatureValid(frame, m_signing.key))
        return false;
    return m_streams.fresh(header, std::max(m_signing.timestamp, msg::MavlinkSigning::now()));
}

void MavlinkPeer::answer(QByteArrayView frame, const QHostAddress &from, quint16 port)
{
    msg::MavlinkFrame header;
    auto message = m_codec.decode(frame, &header);
    if (!message) {
        ++m_bad;
        return;
    }
    if (!signedWell(frame, header)) {
        ++m_refused; // dropped without a word, as ArduPilot does
        return;
    }
    // Addressed by target_system, or MANUAL_CONTROL's target: another vehicle's is not ours.
    int target = message->def() ? message->def()->indexOf(u"target_system") : -1;
    if (target < 0 && message->def() && message->def()->abbrev == u"MANUAL_CONTROL")
        target = message->def()->indexOf(u"target");
    if (target >= 0 && message->integer(target) != 0 && message->integer(target) != m_config.system)
        return; // for another vehicle
    send(m_autopilot.receive(*message, now()), from, port);
}

void MavlinkPeer::read()
{
    while (m_socket.hasPendingDatagrams()) {
        const QNetworkDatagram datagram = m_socket.receiveDatagram();
        const QByteArray data = datagram.data();
        // A datagram may carry several frames (a radio bridge packs them).
        for (qsizetype at = 0; at < data.size();) {
            const qsizetype length = msg::MavlinkCodec::frameLength(QByteArrayView(data).sliced(at));
            if (length == 0 || at + length > data.size()) {
                ++m_bad;
                break;
            }
            answer(QByteArrayView(data).sliced(at, length), datagram.senderAddress(), quint16(datagram.senderPort()));
            at += length;
        }
    }
}

} // namespace neptus::sim
