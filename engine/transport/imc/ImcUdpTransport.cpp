#include "transport/imc/ImcUdpTransport.h"

#include <QNetworkInterface>
#include <QRegularExpression>
#include <QTimer>

#include <cstring>

#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

namespace neptus::transport {

std::optional<std::pair<QHostAddress, quint16>> hostAndPort(QStringView text)
{
    const qsizetype colon = text.lastIndexOf(u':');
    if (colon <= 0)
        return std::nullopt;
    const QHostAddress host(text.left(colon).toString());
    bool ok = false;
    const uint port = text.mid(colon + 1).toUInt(&ok);
    if (host.isNull() || !ok || port == 0 || port > 65535)
        return std::nullopt;
    return std::pair{host, quint16(port)};
}

namespace {

// IMC's discovery multicast group (DUNE and the Java Neptus use it).
const QHostAddress discoveryGroup(QStringLiteral("224.0.75.69"));

// Hosts remembered per system (an attacker can forge many source addresses).
constexpr int sendersPerSystem = 16;

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
    m_timer.setInterval(m_config.heartbeatMs);
    connect(&m_timer, &QTimer::timeout, this, &ImcUdpTransport::heartbeat);
}

ImcUdpTransport::ImcUdpTransport(std::shared_ptr<const msg::Schema> schema, ImcUdpConfig config, QObject *parent)
    : ImcUdpTransport(std::make_shared<msg::SchemaSet>(std::move(schema)), std::move(config), parent)
{
}

ImcUdpTransport::~ImcUdpTransport()
{
    m_pump.reset(); // stops taking and reading before the sockets close
    for (const int fd : {m_fd, m_discoveryFd}) {
        if (fd >= 0)
            ::close(fd);
    }
}

std::expected<void, QString> ImcUdpTransport::start()
{
    // Qt binds and sets the sockets up (errors, multicast); then they are
    // ours, read by the reader's thread and written with sendto().
    QUdpSocket socket, discovery;
    if (!socket.bind(m_config.bindAddress, m_config.port))
        return std::unexpected(QStringLiteral("IMC/UDP: cannot listen on %1:%2: %3")
                                   .arg(m_config.bindAddress.toString()).arg(m_config.port).arg(socket.errorString()));
    if (auto bound = bindDiscovery(socket, discovery); !bound)
        return bound;
    m_port = socket.localPort();
    m_fd = ::dup(int(socket.socketDescriptor()));
    std::vector<int> fds{m_fd};
    if (discovery.state() == QAbstractSocket::BoundState) {
        m_discoveryPort = discovery.localPort();
        m_discoveryFd = ::dup(int(discovery.socketDescriptor()));
        fds.push_back(m_discoveryFd);
    }
    if (std::find(fds.begin(), fds.end(), -1) != fds.end())
        return std::unexpected(QStringLiteral("IMC/UDP: cannot keep the socket: %1").arg(qt_error_string(errno)));
    DatagramReader::Limits limits;
    limits.datagramsPerSecond = m_config.maxDatagramsPerSecond;
    m_pump = std::make_unique<DatagramPump>(
        fds, limits, [this](const DatagramReader::Datagram &d) { process(d.bytes, d.from, d.port, d.host); },
        [this](const QHash<QString, int> &overRate, const QHash<QString, int> &behind) { dropped(overRate, behind); });
    m_timer.start();
    heartbeat();
    return {};
}

std::expected<void, QString> ImcUdpTransport::bindDiscovery(QUdpSocket &socket, QUdpSocket &discovery)
{
    if (!m_config.discovery)
        return {};
    const bool loopback = m_config.bindAddress.isLoopback();
    if (m_config.discoveryPort == 0) {
        if (!discovery.bind(m_config.bindAddress, 0))
            return std::unexpected(QStringLiteral("IMC/UDP: cannot listen for announcements on %1: %2")
                                       .arg(m_config.bindAddress.toString(), discovery.errorString()));
        return {};
    }
    if (!loopback) {
        // A field network: announcements come by broadcast and multicast, which
        // every program on the port receives, so the port is shared.
        const auto interface = interfaceOf(m_config.bindAddress);
        if (!interface)
            return std::unexpected(QStringLiteral("IMC/UDP: no network interface has the address %1")
                                       .arg(m_config.bindAddress.toString()));
        if (!discovery.bind(QHostAddress::AnyIPv4, m_config.discoveryPort,
                              QUdpSocket::ShareAddress | QUdpSocket::ReuseAddressHint))
            return std::unexpected(QStringLiteral("IMC/UDP: cannot listen for announcements on port %1: %2")
                                       .arg(m_config.discoveryPort).arg(discovery.errorString()));
        discovery.joinMulticastGroup(discoveryGroup, interface->first);
        socket.setMulticastInterface(interface->first);
        return {};
    }
    // Loopback: each program takes the first free port of the range and
    // announces to all of them, as DUNE does.
    QString why;
    for (int i = 0; i < m_config.discoveryPortCount; ++i) {
        const auto port = static_cast<quint16>(m_config.discoveryPort + i);
        if (discovery.bind(m_config.bindAddress, port))
            return {};
        why = discovery.errorString();
        discovery.close();
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

QString ImcUdpTransport::Endpoint::name() const
{
    return peerName(address, port);
}

void ImcUdpTransport::emitAll(Later &later)
{
    for (const auto &emitIt : later)
        emitIt();
    later.clear();
}

void ImcUdpTransport::dropped(const QHash<QString, int> &overRate, const QHash<QString, int> &behind)
{
    Later later;
    {
        std::lock_guard lock(m_mutex);
        const qint64 now = nowMs();
        for (const auto *counts : {&overRate, &behind}) {
            for (auto it = counts->cbegin(); it != counts->cend(); ++it) {
                Budget &budget = m_budgets[it.key()];
                rollBudgetLocked(it.key(), budget, now, later);
                (counts == &overRate ? budget.dropped : budget.behind) += it.value();
                m_dropped += quint64(it.value());
            }
        }
    }
    emitAll(later);
}

void ImcUdpTransport::receive(QByteArrayView datagram, const QHostAddress &from, quint16 fromPort)
{
    const QString host = DatagramReader::hostName(from);
    Later later;
    bool within = false;
    {
        std::lock_guard lock(m_mutex);
        within = withinBudgetLocked(host, later);
    }
    emitAll(later);
    if (within)
        process(datagram, from, fromPort, host);
}

void ImcUdpTransport::process(QByteArrayView datagram, const QHostAddress &from, quint16 fromPort, const QString &host)
{
    ++m_processed;
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
    Later later;
    {
        std::lock_guard lock(m_mutex);
        if (announce) {
            learnFromAnnounceLocked(*message, from, host, later);
        } else if (Sender *sender = senderForLocked(source, host)) {
            sender->lastMs = nowMs();
            if (fromPort != 0)
                sender->data = Endpoint{from, fromPort}; // reachable where it talks from
            resolveLocked(source, later);
        }
    }
    emitAll(later);
    if (m_tap)
        m_tap(datagram);
    emit received(*message, datagram.size());
    if (!announce)
        return;
    // After `received`, so that the system already has its name.
    static const QRegularExpression version(QStringLiteral(R"(imc\+info://[^;]*/version/([^/;]+))"));
    const auto match = version.match(message->text(u"services"));
    if (!match.hasMatch())
        return;
    {
        std::lock_guard lock(m_mutex);
        if (m_versions.value(source) == match.captured(1))
            return;
        m_versions.insert(source, match.captured(1));
    }
    emit versionAnnounced(source, match.captured(1));
}

bool ImcUdpTransport::withinBudgetLocked(const QString &host, Later &later)
{
    if (m_config.maxDatagramsPerSecond <= 0)
        return true;
    Budget &budget = m_budgets[host];
    rollBudgetLocked(host, budget, nowMs(), later);
    if (budget.count < m_config.maxDatagramsPerSecond) {
        ++budget.count;
        return true;
    }
    ++budget.dropped;
    ++m_dropped;
    return false;
}

void ImcUdpTransport::rollBudgetLocked(const QString &host, Budget &budget, qint64 now, Later &later)
{
    if (now - budget.secondStartMs < 1000)
        return;
    const bool was = budget.overloaded;
    budget.overloaded = budget.dropped > 0 || budget.behind > 0;
    const int dropped = budget.dropped, behind = budget.behind;
    budget.secondStartMs = now;
    budget.count = 0;
    budget.dropped = 0;
    budget.behind = 0;
    if (budget.overloaded || was)
        later.push_back([this, host, dropped, behind] { emit overloaded(host, dropped, behind); });
}

ImcUdpTransport::Sender *ImcUdpTransport::senderForLocked(quint16 system, const QString &host)
{
    auto peer = m_peers.find(system);
    if (peer == m_peers.end()) {
        if (m_peers.size() >= m_config.maxSystems)
            return nullptr;
        peer = m_peers.insert(system, {});
    }
    auto sender = peer->senders.find(host);
    if (sender == peer->senders.end()) {
        if (peer->senders.size() >= sendersPerSystem)
            return nullptr;
        sender = peer->senders.insert(host, {});
    }
    return &*sender;
}

void ImcUdpTransport::resolveLocked(quint16 system, Later &later)
{
    const auto it = m_peers.find(system);
    if (it == m_peers.end())
        return;
    Peer &peer = *it;
    const qint64 now = nowMs();
    QStringList recent;
    QString newest;
    qint64 newestMs = std::numeric_limits<qint64>::min();
    for (auto sender = peer.senders.cbegin(); sender != peer.senders.cend(); ++sender) {
        if (now - sender->lastMs <= m_config.conflictWindowMs)
            recent.append(sender.key());
        if (sender->lastMs > newestMs) {
            newestMs = sender->lastMs;
            newest = sender.key();
        }
    }
    recent.sort();
    QString chosen;
    if (!peer.picked.isEmpty() && peer.senders.contains(peer.picked))
        chosen = peer.picked;
    else if (recent.size() == 1)
        chosen = recent.front();
    else if (recent.isEmpty())
        chosen = newest; // all silent: the last one heard
    // else: a conflict, held until one is picked or falls silent
    peer.target.reset();
    if (!chosen.isEmpty()) {
        const Sender &sender = peer.senders[chosen];
        peer.target = sender.announced ? sender.announced : sender.data;
    }
    const QString destination = peer.target ? peer.target->name() : QString();
    if (recent == peer.sources && destination == peer.destination)
        return;
    peer.sources = recent;
    peer.destination = destination;
    later.push_back([this, system, recent, destination] { emit sourcesChanged(system, recent, destination); });
}

QList<quint16> ImcUdpTransport::knownSystems() const
{
    std::lock_guard lock(m_mutex);
    QList<quint16> systems;
    for (auto it = m_peers.cbegin(); it != m_peers.cend(); ++it) {
        if (it->target)
            systems.append(it.key());
    }
    return systems;
}

QStringList ImcUdpTransport::sources(quint16 system) const
{
    std::lock_guard lock(m_mutex);
    return m_peers.value(system).sources;
}

QString ImcUdpTransport::destination(quint16 system) const
{
    std::lock_guard lock(m_mutex);
    return m_peers.value(system).destination;
}

QString ImcUdpTransport::announcedVersion(quint16 system) const
{
    std::lock_guard lock(m_mutex);
    return m_versions.value(system);
}

bool ImcUdpTransport::pick(quint16 system, const QString &host)
{
    Later later;
    {
        std::lock_guard lock(m_mutex);
        const auto it = m_peers.find(system);
        if (it == m_peers.end() || (!host.isEmpty() && !it->senders.contains(host)))
            return false;
        it->picked = host;
        resolveLocked(system, later);
    }
    emitAll(later);
    return true;
}

void ImcUdpTransport::forgetSilent()
{
    Later later;
    {
        std::lock_guard lock(m_mutex);
        const qint64 now = nowMs();
        for (const quint16 system : m_peers.keys()) {
            Peer &peer = m_peers[system];
            peer.senders.removeIf([&](const auto &sender) { return now - sender.value().lastMs > m_config.forgetAfterMs; });
            if (!peer.picked.isEmpty() && !peer.senders.contains(peer.picked))
                peer.picked.clear();
            if (!peer.senders.isEmpty()) {
                resolveLocked(system, later);
                continue;
            }
            const bool reported = !peer.sources.isEmpty() || !peer.destination.isEmpty();
            m_peers.remove(system);
            m_versions.remove(system);
            if (reported)
                later.push_back([this, system] { emit sourcesChanged(system, {}, {}); });
        }
        // Hosts that no longer send keep no budget.
        m_budgets.removeIf([&](const auto &budget) {
            return !budget.value().overloaded && now - budget.value().secondStartMs > 2000;
        });
        for (auto it = m_budgets.begin(); it != m_budgets.end(); ++it)
            rollBudgetLocked(it.key(), it.value(), now, later);
    }
    emitAll(later);
}

void ImcUdpTransport::learnFromAnnounceLocked(const msg::Message &announce, const QHostAddress &from, const QString &host,
                                              Later &later)
{
    const quint16 source = announce.header.src;
    const QString name = announce.text(u"sys_name");
    m_schemas->learnName(source, name);
    // services: "dune://0.0.0.0/uid/...;imc+info://0.0.0.0/version/5.4.31;imc+udp://127.0.0.1:6002/;..."
    // A vehicle lists one imc+udp service per interface: only the one on
    // the host it sent from counts, so that nobody can send a vehicle's
    // commands elsewhere with a forged Announce.
    const QString services = announce.text(u"services");
    static const QRegularExpression service(QStringLiteral(R"(imc\+udp://([^:/;]+):(\d+))"));
    std::optional<Endpoint> chosen;
    bool listsUdp = false;
    for (auto it = service.globalMatch(services); it.hasNext();) {
        const auto match = it.next();
        const Endpoint candidate{QHostAddress(match.captured(1)), static_cast<quint16>(match.captured(2).toUInt())};
        listsUdp = true;
        if (candidate.address.isNull() || candidate.port == 0)
            continue;
        if (candidate.address.isEqual(from, QHostAddress::TolerantConversion)) {
            chosen = candidate;
            break;
        }
    }
    Sender *sender = senderForLocked(source, host);
    if (!sender)
        return;
    const qint64 now = nowMs();
    sender->lastMs = now;
    if (chosen)
        sender->announced = chosen;
    else if (listsUdp)
        later.push_back([this, source, host, services] { emit announceIgnored(source, host, services); });
    Peer &peer = m_peers[source];
    const bool known = peer.target.has_value();
    resolveLocked(source, later);
    // Greeted at each Announce (a vehicle that restarted has forgotten us,
    // and streams only to consoles it knows from their Announce and hears
    // from; DUNE takes a repeated greeting as nothing new), at most one
    // every 2 s: a flood of forged Announces makes no flood of greetings.
    if (!peer.target || (peer.greetedMs > 0 && now - peer.greetedMs < 2000))
        return;
    peer.greetedMs = now;
    greetLocked(source, from, *peer.target);
    if (!known)
        later.push_back([this, source, name] { emit systemDiscovered(source, name); });
}

void ImcUdpTransport::greetLocked(quint16 system, const QHostAddress &host, const Endpoint &target)
{
    const double time = now();
    msg::Message hello = announcement();
    hello.header.timestamp = time; // DUNE's discovery takes one Announce per address and timestamp
    hello.header.src = m_config.systemId;
    hello.header.dst = system;
    if (m_config.discovery && m_config.discoveryPort != 0) {
        for (int i = 0; i < m_config.discoveryPortCount; ++i)
            sendLocked(hello, Endpoint{host, static_cast<quint16>(m_config.discoveryPort + i)});
    }
    sendLocked(hello, target);
    msg::Message beat(m_schemas->defaultSchema().byAbbrev(u"Heartbeat"));
    if (!beat.def())
        return;
    beat.header.timestamp = time;
    beat.header.src = m_config.systemId;
    beat.header.dst = system;
    sendLocked(beat, target);
    // Again a moment later, once its discovery has told its UDP transport of us.
    QMetaObject::invokeMethod(this, [this, beat, target] {
        QTimer::singleShot(250, this, [this, beat, target] {
            std::lock_guard lock(m_mutex);
            sendLocked(beat, target);
        });
    }, Qt::QueuedConnection);
}

std::expected<void, QString> ImcUdpTransport::sendLocked(const msg::Message &message, const Endpoint &to)
{
    if (auto encoded = m_schemas->codecFor(message.header.dst)->encode(message, m_buffer); !encoded)
        return std::unexpected(QStringLiteral("%1 does not encode: %2").arg(message.abbrev(), encoded.error().toString()));
    if (auto sent = sendDatagram(m_fd, m_buffer, to.address, to.port, m_config.bindAddress.protocol() == QAbstractSocket::IPv6Protocol);
        !sent)
        return std::unexpected(QStringLiteral("cannot send to %1: %2").arg(to.name(), sent.error()));
    if (m_tap)
        m_tap(m_buffer);
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
                                                     .arg(m_port)
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
    forgetSilent();
    std::lock_guard lock(m_mutex);
    const double time = now();
    auto stamp = [&](msg::Message &m, quint16 dst) {
        m.header.timestamp = time;
        m.header.src = m_config.systemId;
        m.header.srcEnt = 0xFF;
        m.header.dst = dst;
        m.header.dstEnt = 0xFF;
    };
    QList<std::pair<quint16, Endpoint>> targets;
    for (auto it = m_peers.cbegin(); it != m_peers.cend(); ++it) {
        if (it->target)
            targets.append({it.key(), *it->target});
    }
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
            sendLocked(announce, target);
    }
    for (const auto &[system, endpoint] : targets) {
        if (announceToo) {
            msg::Message announce = announcement();
            stamp(announce, system);
            sendLocked(announce, endpoint);
        }
        msg::Message beat(beatDef);
        stamp(beat, system);
        sendLocked(beat, endpoint);
    }
}

std::expected<void, QString> ImcUdpTransport::publish(quint16 system, const msg::Message &message)
{
    std::lock_guard lock(m_mutex);
    const auto it = m_peers.constFind(system);
    if (it == m_peers.cend())
        return std::unexpected(QStringLiteral("IMC/UDP: %1 was never heard or announced").arg(msg::systemLabel(system)));
    if (!it->target && it->sources.size() > 1)
        return std::unexpected(QStringLiteral("IMC/UDP: %1 hosts send as %2 (%3): commands are held until one is chosen")
                                   .arg(it->sources.size()).arg(msg::systemLabel(system), it->sources.join(QStringLiteral(", "))));
    if (!it->target)
        return std::unexpected(QStringLiteral("IMC/UDP: %1 named no address on the host it is heard from (%2)")
                                   .arg(msg::systemLabel(system), QStringList(it->senders.keys()).join(QStringLiteral(", "))));
    auto addressed = m_schemas->forSystem(system, message);
    if (!addressed)
        return std::unexpected(addressed.error());
    addressed->header.src = m_config.systemId;
    addressed->header.srcEnt = 0xFF;
    addressed->header.dst = system;
    addressed->header.timestamp = now();
    return sendLocked(*addressed, *it->target);
}

} // namespace neptus::transport
