#include "SimNode.h"

#include <QDateTime>
#include <QRegularExpression>

#include <cstdio>

using namespace neptus;

namespace {

// IMC's discovery ports on loopback.
QList<std::pair<QHostAddress, quint16>> imcDiscoveryPorts()
{
    QList<std::pair<QHostAddress, quint16>> ports;
    for (quint16 port = 30100; port <= 30104; ++port)
        ports.append({QHostAddress::LocalHost, port});
    return ports;
}

} // namespace

SimNode::SimNode(std::shared_ptr<const msg::Schema> schema, Options options, QObject *parent)
    : QObject(parent)
    , m_schema(schema)
    , m_options(std::move(options))
    , m_codec(schema)
    , m_vehicle(schema, [this] {
        // It announces where its socket is.
        sim::SimulatedVehicle::Config config = m_options.vehicle.config;
        config.services = QStringLiteral("imc+udp://%1:%2/").arg(m_options.vehicle.host).arg(m_options.vehicle.port);
        return config;
    }())
{
    for (const auto &f : m_options.vehicle.faults)
        m_vehicle.scheduleFault(f);
    m_vehicle.setTimeFactor(m_options.timeFactor);
    if (m_options.vehicle.firstTransitionOnly)
        m_vehicle.plans().setTransitions(sim::PlanEngine::Transitions::FirstOnly);
}

double SimNode::wallTime()
{
    return QDateTime::currentMSecsSinceEpoch() / 1000.0;
}

std::expected<void, QString> SimNode::start()
{
    const sim::ScenarioVehicle &v = m_options.vehicle;
    const QHostAddress address(v.host);
    if (!m_socket.bind(address, v.port))
        return std::unexpected(QStringLiteral("cannot listen on %1:%2: %3").arg(v.host).arg(v.port).arg(m_socket.errorString()));
    // Like DUNE: listen for announcements on the first free IMC discovery
    // port and announce to all of them.
    if (v.likeDune) {
        for (const auto &[discoveryAddress, to] : imcDiscoveryPorts()) {
            if (m_discovery.bind(discoveryAddress, to))
                break;
            m_discovery.close();
        }
        if (m_discovery.state() != QAbstractSocket::BoundState)
            return std::unexpected(QStringLiteral("no IMC discovery port (30100-30104) is free on 127.0.0.1"));
        m_options.announceTo = imcDiscoveryPorts();
    }
    connect(&m_socket, &QUdpSocket::readyRead, this, [this] {
        while (m_socket.hasPendingDatagrams())
            handle(m_socket.receiveDatagram(), false);
    });
    connect(&m_discovery, &QUdpSocket::readyRead, this, [this] {
        while (m_discovery.hasPendingDatagrams())
            handle(m_discovery.receiveDatagram(), true);
    });
    // Over DDS there is no heartbeat handshake: publish to whoever subscribes.
    if (v.dds) {
        transport::DdsConfig config{static_cast<dds_domainid_t>(m_options.ddsDomain), {}, v.config.id};
        config.security = {m_options.ddsKeys, m_options.ddsIdentity};
        m_dds = std::make_unique<transport::DdsTransport>(m_schema, config);
        if (auto started = m_dds->start(); !started)
            return std::unexpected(started.error());
        connect(m_dds.get(), &transport::DdsTransport::received, this, [this](const msg::Message &m) {
            if (m.header.dst == m_options.vehicle.config.id) {
                std::printf("neptus-sim: %s received %s from 0x%04x over DDS\n", qPrintable(m_options.vehicle.config.name),
                            qPrintable(m.abbrev()), m.header.src);
                std::fflush(stdout);
            }
            for (const msg::Message &reply : m_vehicle.answer(m, wallTime()))
                m_dds->publish(m.header.src, reply);
        });
    }
    std::printf("neptus-sim: %s (id 0x%04x) on %s:%u\n", qPrintable(v.config.name), v.config.id, qPrintable(v.host), v.port);
    std::fflush(stdout);
    m_clock.start();
    connect(&m_timer, &QTimer::timeout, this, &SimNode::tick);
    m_timer.start(20);
    return {};
}

void SimNode::sendTo(const msg::Message &message, const QHostAddress &address, quint16 port)
{
    QByteArray packet;
    if (m_codec.encode(message, packet))
        m_socket.writeDatagram(packet, address, port);
}

void SimNode::handle(const QNetworkDatagram &datagram, bool discovery)
{
    auto message = m_codec.decode(datagram.data());
    if (!message)
        return;
    const quint16 self = m_options.vehicle.config.id;
    const quint16 from = message->header.src;
    if (from == self)
        return; // our own Announce on the discovery ports
    if (m_options.vehicle.likeDune) {
        if (discovery) {
            // Transports.Discovery: Announces only, once per address and timestamp;
            // Transports.UDP keeps the first imc+udp address a system names.
            if (message->abbrev() != u"Announce")
                return;
            const QString sender = datagram.senderAddress().toString();
            if (m_announceStamps.value(sender, -1) == message->header.timestamp)
                return;
            m_announceStamps.insert(sender, message->header.timestamp);
            m_vehicle.answer(*message, wallTime()); // who it is, for the words of an abort
            static const QRegularExpression service(QStringLiteral(R"(imc\+udp://([^:/;]+):(\d+))"));
            const auto match = service.match(message->text(u"services"));
            if (match.hasMatch() && !m_peers.contains(from))
            {
                Peer peer;
                peer.address = QHostAddress(match.captured(1));
                peer.port = static_cast<quint16>(match.captured(2).toUInt());
                m_peers.insert(from, peer);
            }
            return;
        }
        if (!m_peers.contains(from)) {
            if (!m_ignored.contains(from)) {
                m_ignored.insert(from);
                std::printf("neptus-sim: ignoring 0x%04x: it has not announced itself\n", from);
                std::fflush(stdout);
            }
            return;
        }
        Peer &peer = m_peers[from];
        peer.heardMs = m_clock.elapsed();
        peer.heardFrom = datagram.senderAddress();
    } else if (message->abbrev() == u"Heartbeat") {
        const QPair<QString, quint16> console{datagram.senderAddress().toString(), static_cast<quint16>(datagram.senderPort())};
        if (!m_consoles.contains(console)) { // a new console: say who we are at once
            for (const msg::Message &m : m_vehicle.introduction(wallTime()))
                sendTo(m, datagram.senderAddress(), static_cast<quint16>(datagram.senderPort()));
        }
        m_consoles[console] = m_clock.elapsed();
    }
    if (message->header.dst == self && message->abbrev() != u"Announce" && message->abbrev() != u"Heartbeat") {
        std::printf("neptus-sim: received %s from 0x%04x\n", qPrintable(message->abbrev()), from);
        std::fflush(stdout);
    }
    for (const msg::Message &reply : m_vehicle.answer(*message, wallTime())) {
        if (!m_options.vehicle.likeDune) {
            sendTo(reply, datagram.senderAddress(), static_cast<quint16>(datagram.senderPort()));
            continue;
        }
        // DUNE's UDP transport sends everything to every active node, whatever its destination.
        for (const Peer &peer : std::as_const(m_peers))
            if (peer.active)
                sendTo(reply, peer.address, peer.port);
    }
}

void SimNode::refreshContacts()
{
    const qint64 now = m_clock.elapsed();
    for (auto it = m_peers.begin(); it != m_peers.end(); ++it) {
        Peer &peer = *it;
        const bool heard = peer.heardMs >= 0 && now - peer.heardMs < 30000;
        const bool active = heard && peer.heardFrom.isEqual(peer.address, QHostAddress::TolerantConversion);
        if (active && !peer.active) {
            std::printf("neptus-sim: activating transmission to node 0x%04x\n", it.key());
            std::fflush(stdout);
        }
        peer.active = active;
    }
}

void SimNode::tick()
{
    const double t = m_clock.elapsed() / 1000.0;
    // DUNE refreshes its contacts every 5 s (Transports.UDP, Contact Refresh Periodicity).
    if (m_options.vehicle.likeDune && m_clock.elapsed() - m_refreshedMs >= 5000) {
        m_refreshedMs += 5000;
        refreshContacts();
    }
    const auto messages = m_vehicle.step(m_previous, t, wallTime());
    m_previous = t;
    if (m_dds)
        m_dds->broadcast(messages);
    for (const msg::Message &m : messages) {
        if (!m_codec.encode(m, m_buffer))
            continue;
        for (auto it = m_consoles.cbegin(); it != m_consoles.cend(); ++it) {
            if (m_clock.elapsed() - it.value() < 5000)
                m_socket.writeDatagram(m_buffer, QHostAddress(it.key().first), it.key().second);
        }
        // DUNE's UDP transport does not carry Announce (etc/common/transports.ini): only its discovery does.
        for (const Peer &peer : std::as_const(m_peers)) {
            if (peer.active && m.abbrev() != u"Announce")
                m_socket.writeDatagram(m_buffer, peer.address, peer.port);
        }
        if (m.abbrev() == u"Announce") {
            for (const auto &[address, to] : std::as_const(m_options.announceTo))
                m_socket.writeDatagram(m_buffer, address, to);
        }
    }
}
