#include "ImcUdpTransport.h"

#include <QDateTime>
#include <QNetworkDatagram>
#include <QRegularExpression>

namespace neptus::transport {

ImcUdpTransport::ImcUdpTransport(std::shared_ptr<const msg::Schema> schema, ImcUdpConfig config, QObject *parent)
    : QObject(parent)
    , m_codec(std::move(schema))
    , m_config(std::move(config))
{
    connect(&m_socket, &QUdpSocket::readyRead, this, [this] { readDatagrams(m_socket); });
    connect(&m_discovery, &QUdpSocket::readyRead, this, [this] { readDatagrams(m_discovery); });
    m_timer.setInterval(m_config.heartbeatMs);
    connect(&m_timer, &QTimer::timeout, this, &ImcUdpTransport::heartbeat);
}

std::expected<void, QString> ImcUdpTransport::start()
{
    if (!m_socket.bind(m_config.bindAddress, m_config.port))
        return std::unexpected(QStringLiteral("IMC/UDP: cannot listen on %1:%2: %3")
                                   .arg(m_config.bindAddress.toString()).arg(m_config.port).arg(m_socket.errorString()));
    if (m_config.discovery && !m_discovery.bind(m_config.bindAddress, m_config.discoveryPort))
        return std::unexpected(QStringLiteral("IMC/UDP: cannot listen for announcements on %1:%2: %3")
                                   .arg(m_config.bindAddress.toString()).arg(m_config.discoveryPort)
                                   .arg(m_discovery.errorString()));
    m_timer.start();
    heartbeat();
    return {};
}

void ImcUdpTransport::readDatagrams(QUdpSocket &socket)
{
    while (socket.hasPendingDatagrams()) {
        const QNetworkDatagram datagram = socket.receiveDatagram();
        handle(datagram.data(), datagram.senderAddress(), static_cast<quint16>(datagram.senderPort()));
    }
}

void ImcUdpTransport::handle(const QByteArray &datagram, const QHostAddress &from, quint16 fromPort)
{
    auto message = m_codec.decode(datagram);
    if (!message) {
        ++m_decodeErrors;
        return;
    }
    const quint16 source = message->header.src;
    if (source == m_config.systemId)
        return; // our own, relayed back
    if (message->def() && message->def()->abbrev == u"Announce") {
        learnFromAnnounce(*message);
    } else if (!m_endpoints.contains(source) && fromPort != 0) {
        // A vehicle that talks to us is reachable where it talks from.
        m_endpoints.insert(source, {from, fromPort});
    }
    emit received(*message);
}

void ImcUdpTransport::learnFromAnnounce(const msg::Message &announce)
{
    // services: "dune://0.0.0.0/uid/...;imc+udp://127.0.0.1:6002/;..."
    static const QRegularExpression service(QStringLiteral(R"(imc\+udp://([^:/;]+):(\d+))"));
    const QString services = announce.text(u"services");
    auto match = service.match(services);
    if (!match.hasMatch())
        return;
    const QHostAddress address(match.captured(1));
    const quint16 port = static_cast<quint16>(match.captured(2).toUInt());
    const quint16 source = announce.header.src;
    const bool known = m_endpoints.contains(source);
    m_endpoints.insert(source, {address, port});
    if (!known)
        emit systemDiscovered(source, announce.text(u"sys_name"));
}

void ImcUdpTransport::send(const msg::Message &message, const Endpoint &to)
{
    if (!m_codec.encode(message, m_buffer))
        return;
    m_socket.writeDatagram(m_buffer, to.address, to.port);
}

msg::Message ImcUdpTransport::announcement() const
{
    const msg::MessageDef *def = m_codec.schema().byAbbrev(u"Announce");
    msg::Message announce(def);
    announce.setBytes(def->indexOf(u"sys_name"), m_config.systemName.toUtf8());
    announce.setInteger(def->indexOf(u"sys_type"), 0); // CCU
    announce.setInteger(def->indexOf(u"owner"), 0xFFFF);
    announce.setBytes(def->indexOf(u"services"), QStringLiteral("imc+udp://%1:%2/")
                                                     .arg(m_config.bindAddress.toString()).arg(port()).toUtf8());
    return announce;
}

void ImcUdpTransport::heartbeat()
{
    const msg::MessageDef *beatDef = m_codec.schema().byAbbrev(u"Heartbeat");
    if (!beatDef)
        return;
    const bool announceToo = m_ticks++ % 5 == 0;
    const double now = QDateTime::currentMSecsSinceEpoch() / 1000.0;
    auto stamp = [&](msg::Message &m, quint16 dst) {
        m.header.timestamp = now;
        m.header.src = m_config.systemId;
        m.header.srcEnt = 0xFF;
        m.header.dst = dst;
        m.header.dstEnt = 0xFF;
    };
    QList<std::pair<quint16, Endpoint>> targets;
    for (auto it = m_endpoints.cbegin(); it != m_endpoints.cend(); ++it)
        targets.append({it.key(), it.value()});
    for (const auto &[address, port] : m_config.destinations) {
        const bool covered = std::any_of(targets.begin(), targets.end(), [&](const auto &t) {
            return t.second.address == address && t.second.port == port;
        });
        if (!covered)
            targets.append({quint16(0xFFFF), Endpoint{address, port}});
    }
    for (const auto &[system, endpoint] : targets) {
        msg::Message beat(beatDef);
        stamp(beat, system);
        send(beat, endpoint);
        if (announceToo && m_codec.schema().byAbbrev(u"Announce")) {
            msg::Message announce = announcement();
            stamp(announce, system);
            send(announce, endpoint);
        }
    }
}

bool ImcUdpTransport::publish(quint16 system, const msg::Message &message)
{
    const auto it = m_endpoints.constFind(system);
    if (it == m_endpoints.cend())
        return false;
    msg::Message addressed = message;
    addressed.header.src = m_config.systemId;
    addressed.header.srcEnt = 0xFF;
    addressed.header.dst = system;
    addressed.header.timestamp = QDateTime::currentMSecsSinceEpoch() / 1000.0;
    send(addressed, *it);
    return true;
}

} // namespace neptus::transport
