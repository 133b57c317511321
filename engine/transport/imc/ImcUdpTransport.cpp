#include "transport/imc/ImcUdpTransport.h"

#include <QNetworkDatagram>
#include <QNetworkInterface>
#include <QRegularExpression>

namespace neptus::transport {

namespace {

// IMC's discovery multicast group (DUNE and the Java Neptus use it).
const QHostAddress discoveryGroup(QStringLiteral("224.0.75.69"));

QString peerName(const QHostAddress &address, quint16 port)
{
    return QStringLiteral("%1:%2").arg(address.toString()).arg(port);
}

// The interface that holds `address`, if any.
std::optional<std::pair<QNetworkInterface, QNetworkAddressEntry>> interfaceOf(const QHostAddress &address)
{
    for (const QNetworkInterface &interface : QNetworkInterface::allInterfaces()) {
        for (const QNetworkAddressEntry &entry : interface.addressEntries()) {
            if (entry.ip() == address)
                return std::pair{interface, entry};
        }
    }
    return std::nullopt;
}

} // namespace

ImcUdpTransport::ImcUdpTransport(std::shared_ptr<msg::SchemaSet> schemas, ImcUdpConfig config, QObject *parent)
    : QObject(parent)
    , m_schemas(std::move(schemas))
    , m_config(std::move(config))
{
    connect(&m_socket, &QUdpSocket::readyRead, this, [this] { readDatagrams(m_socket); });
    connect(&m_discovery, &QUdpSocket::readyRead, this, [this] { readDatagrams(m_discovery); });
    m_timer.setInterval(m_config.heartbeatMs);
    connect(&m_timer, &QTimer::timeout, this, &ImcUdpTransport::heartbeat);
}

ImcUdpTransport::ImcUdpTransport(std::shared_ptr<const msg::Schema> schema, ImcUdpConfig config, QObject *parent)
    : ImcUdpTransport(std::make_shared<msg::SchemaSet>(std::move(schema)), std::move(config), parent)
{
}

std::expected<void, QString> ImcUdpTransport::start()
{
    if (!m_socket.bind(m_config.bindAddress, m_config.port))
        return std::unexpected(QStringLiteral("IMC/UDP: cannot listen on %1:%2: %3")
                                   .arg(m_config.bindAddress.toString()).arg(m_config.port).arg(m_socket.errorString()));
    if (auto bound = bindDiscovery(); !bound)
        return bound;
    m_timer.start();
    heartbeat();
    return {};
}

std::expected<void, QString> ImcUdpTransport::bindDiscovery()
{
    if (!m_config.discovery)
        return {};
    const bool loopback = m_config.bindAddress.isLoopback();
    if (m_config.discoveryPort == 0) {
        if (!m_discovery.bind(m_config.bindAddress, 0))
            return std::unexpected(QStringLiteral("IMC/UDP: cannot listen for announcements on %1: %2")
                                       .arg(m_config.bindAddress.toString(), m_discovery.errorString()));
        return {};
    }
    if (!loopback) {
        // A field network: announcements come by broadcast and multicast, which
        // every program on the port receives, so the port is shared.
        const auto interface = interfaceOf(m_config.bindAddress);
        if (!interface)
            return std::unexpected(QStringLiteral("IMC/UDP: no network interface has the address %1")
                                       .arg(m_config.bindAddress.toString()));
        if (!m_discovery.bind(QHostAddress::AnyIPv4, m_config.discoveryPort,
                              QUdpSocket::ShareAddress | QUdpSocket::ReuseAddressHint))
            return std::unexpected(QStringLiteral("IMC/UDP: cannot listen for announcements on port %1: %2")
                                       .arg(m_config.discoveryPort).arg(m_discovery.errorString()));
        m_discovery.joinMulticastGroup(discoveryGroup, interface->first);
        m_socket.setMulticastInterface(interface->first);
        return {};
    }
    // Loopback: each program takes the first free port of the range and
    // announces to all of them, as DUNE does.
    QString why;
    for (int i = 0; i < m_config.discoveryPortCount; ++i) {
        const auto port = static_cast<quint16>(m_config.discoveryPort + i);
        if (m_discovery.bind(m_config.bindAddress, port))
            return {};
        why = m_discovery.errorString();
        m_discovery.close();
    }
    return std::unexpected(QStringLiteral("IMC/UDP: cannot listen for announcements on %1, ports %2-%3: %4")
                               .arg(m_config.bindAddress.toString())
                               .arg(m_config.discoveryPort)
                               .arg(m_config.discoveryPort + m_config.discoveryPortCount - 1)
                               .arg(why));
}

QList<ImcUdpTransport::Endpoint> ImcUdpTransport::discoveryTargets() const
{
    QList<Endpoint> targets;
    if (!m_config.discovery || m_config.discoveryPort == 0)
        return targets;
    QList<QHostAddress> addresses;
    if (m_config.bindAddress.isLoopback()) {
        addresses.append(m_config.bindAddress);
    } else if (const auto interface = interfaceOf(m_config.bindAddress)) {
        if (!interface->second.broadcast().isNull())
            addresses.append(interface->second.broadcast());
        addresses.append(discoveryGroup);
    }
    for (const QHostAddress &address : addresses) {
        for (int i = 0; i < m_config.discoveryPortCount; ++i)
            targets.append({address, static_cast<quint16>(m_config.discoveryPort + i)});
    }
    return targets;
}

void ImcUdpTransport::readDatagrams(QUdpSocket &socket)
{
    while (socket.hasPendingDatagrams()) {
        const QNetworkDatagram datagram = socket.receiveDatagram();
        receive(datagram.data(), datagram.senderAddress(), static_cast<quint16>(datagram.senderPort()));
    }
}

void ImcUdpTransport::receive(QByteArrayView datagram, const QHostAddress &from, quint16 fromPort)
{
    auto message = m_schemas->decode(datagram);
    if (!message) {
        ++m_decodeErrors;
        const auto sender = m_schemas->senderOf(datagram);
        emit decodeFailed(sender ? *sender : quint16(0xFFFF), peerName(from, fromPort), message.error().toString());
        return;
    }
    const quint16 source = message->header.src;
    if (source == m_config.systemId)
        return; // our own, relayed back (or our own Announce on the discovery ports)
    const bool announce = message->def() && message->def()->abbrev == u"Announce";
    if (announce) {
        learnFromAnnounce(*message, from);
    } else if (!m_endpoints.contains(source) && fromPort != 0) {
        // A vehicle that talks to us is reachable where it talks from.
        m_endpoints.insert(source, {from, fromPort});
    }
    emit received(*message, datagram.size());
    if (!announce)
        return;
    // After `received`, so that the system already has its name.
    static const QRegularExpression version(QStringLiteral(R"(imc\+info://[^;]*/version/([^/;]+))"));
    const auto match = version.match(message->text(u"services"));
    if (match.hasMatch() && m_versions.value(source) != match.captured(1)) {
        m_versions.insert(source, match.captured(1));
        emit versionAnnounced(source, match.captured(1));
    }
}

void ImcUdpTransport::learnFromAnnounce(const msg::Message &announce, const QHostAddress &from)
{
    const quint16 source = announce.header.src;
    const QString name = announce.text(u"sys_name");
    m_schemas->learnName(source, name);
    // services: "dune://0.0.0.0/uid/...;imc+info://0.0.0.0/version/5.4.31;imc+udp://127.0.0.1:6002/;..."
    const QString services = announce.text(u"services");
    // A vehicle lists one imc+udp service per interface: take the one it
    // sent from, else one on loopback when we are there, else the first.
    static const QRegularExpression service(QStringLiteral(R"(imc\+udp://([^:/;]+):(\d+))"));
    std::optional<Endpoint> chosen;
    for (auto it = service.globalMatch(services); it.hasNext();) {
        const auto match = it.next();
        const Endpoint candidate{QHostAddress(match.captured(1)), static_cast<quint16>(match.captured(2).toUInt())};
        if (candidate.address.isNull() || candidate.port == 0)
            continue;
        if (candidate.address.isEqual(from, QHostAddress::TolerantConversion)) {
            chosen = candidate;
            break;
        }
        if (!chosen || (m_config.bindAddress.isLoopback() && candidate.address.isLoopback()
                        && !chosen->address.isLoopback()))
            chosen = candidate;
    }
    if (!chosen)
        return;
    const bool known = m_endpoints.contains(source);
    m_endpoints.insert(source, *chosen);
    if (known)
        return;
    // Say hello at once: a vehicle streams only once it hears from us, and
    // knows us only from our Announce.
    for (msg::Message hello : {announcement(), msg::Message(m_schemas->defaultSchema().byAbbrev(u"Heartbeat"))}) {
        if (!hello.def())
            continue;
        hello.header.timestamp = now();
        hello.header.src = m_config.systemId;
        hello.header.dst = source;
        send(hello, *chosen);
    }
    emit systemDiscovered(source, name);
}

std::expected<void, QString> ImcUdpTransport::send(const msg::Message &message, const Endpoint &to)
{
    if (auto encoded = m_schemas->codecFor(message.header.dst)->encode(message, m_buffer); !encoded)
        return std::unexpected(QStringLiteral("%1 does not encode: %2").arg(message.abbrev(), encoded.error().toString()));
    if (m_socket.writeDatagram(m_buffer, to.address, to.port) != m_buffer.size())
        return std::unexpected(QStringLiteral("cannot send to %1: %2").arg(peerName(to.address, to.port), m_socket.errorString()));
    return {};
}

msg::Message ImcUdpTransport::announcement() const
{
    const msg::Schema &schema = m_schemas->defaultSchema();
    const msg::MessageDef *def = schema.byAbbrev(u"Announce");
    msg::Message announce(def);
    announce.setBytes(def->indexOf(u"sys_name"), m_config.systemName.toUtf8());
    announce.setInteger(def->indexOf(u"sys_type"), 0); // CCU
    announce.setInteger(def->indexOf(u"owner"), 0xFFFF);
    announce.setBytes(def->indexOf(u"services"), QStringLiteral("imc+info://0.0.0.0/version/%1;imc+udp://%2:%3/")
                                                     .arg(schema.version(), m_config.bindAddress.toString())
                                                     .arg(port())
                                                     .toUtf8());
    return announce;
}

void ImcUdpTransport::heartbeat()
{
    const msg::Schema &schema = m_schemas->defaultSchema();
    const msg::MessageDef *beatDef = schema.byAbbrev(u"Heartbeat");
    const bool canAnnounce = schema.byAbbrev(u"Announce") != nullptr;
    if (!beatDef)
        return;
    const bool announceToo = canAnnounce && m_ticks++ % std::max(1, m_config.announceEvery) == 0;
    const double time = now();
    auto stamp = [&](msg::Message &m, quint16 dst) {
        m.header.timestamp = time;
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
    // Announce first: a vehicle takes a heartbeat only from a system it knows.
    if (announceToo) {
        msg::Message announce = announcement();
        stamp(announce, 0xFFFF);
        for (const Endpoint &target : discoveryTargets())
            send(announce, target);
    }
    for (const auto &[system, endpoint] : targets) {
        if (announceToo) {
            msg::Message announce = announcement();
            stamp(announce, system);
            send(announce, endpoint);
        }
        msg::Message beat(beatDef);
        stamp(beat, system);
        send(beat, endpoint);
    }
}

std::expected<void, QString> ImcUdpTransport::publish(quint16 system, const msg::Message &message)
{
    const auto it = m_endpoints.constFind(system);
    if (it == m_endpoints.cend())
        return std::unexpected(QStringLiteral("IMC/UDP: 0x%1 was never heard or announced").arg(system, 4, 16, QLatin1Char('0')));
    auto addressed = m_schemas->forSystem(system, message);
    if (!addressed)
        return std::unexpected(addressed.error());
    addressed->header.src = m_config.systemId;
    addressed->header.srcEnt = 0xFF;
    addressed->header.dst = system;
    addressed->header.timestamp = now();
    return send(*addressed, *it);
}

} // namespace neptus::transport
