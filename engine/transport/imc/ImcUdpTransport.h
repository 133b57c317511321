#pragma once

#include "core/Clock.h"
#include "messages/SchemaSet.h"
#include "transport/OutputSink.h"
#include "transport/DatagramPump.h"

#include <QHash>
#include <QHostAddress>
#include <QList>
#include <QObject>
#include <QTimer>
#include <QUdpSocket>

#include <atomic>
#include <expected>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>

namespace neptus::transport {

// "127.0.0.1:6002": an IP address and a port 1-65535, or nothing (a host
// name, a missing or bad port). For --imc-peer and the like.
std::optional<std::pair<QHostAddress, quint16>> hostAndPort(QStringView text);

// How the console meets IMC vehicles over UDP. Everything defaults to
// loopback; a field setup names the boat network's address explicitly.
struct ImcUdpConfig
{
    QHostAddress bindAddress = QHostAddress::LocalHost;
    quint16 port = 6001;                 // 0: any free port (tests)
    // Vehicles known in advance, as host and port; their ids are learned
    // from what they send.
    QList<std::pair<QHostAddress, quint16>> destinations;
    // IMC discovery: listen on the first free port of discoveryPort ..
    // discoveryPort + discoveryPortCount - 1 (IMC: 30100-30104), and send our
    // Announce to all of them, so that vehicles (which only talk to consoles
    // they know) learn of us, and we of them.
    bool discovery = true;
    quint16 discoveryPort = 30100;       // 0: listen on any free port and announce to none (tests)
    int discoveryPortCount = 5;
    quint16 systemId = 0x4001;           // a CCU id (0x4000-0x5FFF)
    QString systemName = QStringLiteral("neptus-qt");
    int heartbeatMs = 1000;
    int announceEvery = 5;               // heartbeats between two Announces
    const Clock *clock = &Clock::system(); // stamps what it sends
    // What a peer may cost: datagrams a second from one address (the excess is
    // dropped before decoding and reported), systems it keeps addresses of,
    // how long an address it no longer hears from is kept (and heartbeated),
    // and how long two senders of one system id must be apart to be one.
    int maxDatagramsPerSecond = 5000;
    int maxSystems = 256;
    int forgetAfterMs = 60000;
    int conflictWindowMs = 10000;
};

// IMC over UDP, one packet per datagram. The console announces itself (an
// imc+udp:// service, system type CCU) to the IMC discovery ports and to
// every vehicle it knows, and sends a Heartbeat every second to those
// vehicles, since IMC vehicles only stream to consoles they know and hear
// from. Vehicles are known from the static destinations, from their Announce
// (on the discovery port or ours), and from what they send. Packets are
// decoded with each sender's own definitions (SchemaSet). Commands go to the
// vehicle's own id (IMC vehicles ignore 0xFFFF). Our own messages relayed
// back are dropped; packets that do not decode are reported, never passed on.
//
// On a field interface (bindAddress not loopback) discovery also sends to the
// interface's broadcast address and IMC's multicast group 224.0.75.69, and
// listens there; on loopback it stays on 127.0.0.1.
//
// Against impostors and floods: commands go to a host a system's messages
// come from, at the address its Announce names on that host (else where its
// messages come from); an Announce that names addresses on other hosts
// redirects nothing. Two hosts sending as one system id are a conflict:
// commands to it are held until the operator picks one (pick()) or one
// falls silent for conflictWindowMs. Hosts not heard from for forgetAfterMs
// are forgotten (no more heartbeats to them), at most maxSystems systems are
// kept, and each host may deliver at most maxDatagramsPerSecond (0: no limit,
// for replaying logs); the excess is dropped before it is decoded.
//
// The sockets are read and the datagrams decoded off the GUI thread
// (DatagramPump: a bounded queue per sending host, taken in turns) and
// handed on (`received`, the packet tap): a flooding host delays and drops
// only its own datagrams, and a busy GUI thread none at all — a receiver
// connected directly gets them on the pump's thread (the console's session
// is thread-safe), others through their event loop. What is known
// of peers is guarded for both threads; signals other than `received` are
// emitted with nothing locked, from whichever thread found the change.
//
// Greeting: DUNE makes a console a node only from an Announce on its
// discovery port (Transports.Discovery), and streams to it from its next
// contact refresh (Transports.UDP, every 5 s) once the console's packets
// come to its own port. So a vehicle heard announcing (met first, or
// restarted and forgetful) is greeted at once: our Announce to the IMC
// discovery ports of its host, a Heartbeat to its port, and another a
// quarter of a second later (the node and the contact are made by two of
// its threads), then the heartbeat every second.
class ImcUdpTransport : public QObject, public OutputSink
{
    Q_OBJECT

public:
    ImcUdpTransport(std::shared_ptr<msg::SchemaSet> schemas, ImcUdpConfig config, QObject *parent = nullptr);
    ImcUdpTransport(std::shared_ptr<const msg::Schema> schema, ImcUdpConfig config, QObject *parent = nullptr);
    ~ImcUdpTransport() override;

    // Binds the sockets; an error names the address and port and why.
    std::expected<void, QString> start();
    quint16 port() const { return m_port; }
    quint16 discoveryPort() const { return m_discoveryPort; }
    // Systems with an address commands can go to.
    QList<quint16> knownSystems() const;
    int decodeErrors() const { return m_decodeErrors; }
    int maxDatagramsPerSecond() const { return m_config.maxDatagramsPerSecond; }
    // Datagrams dropped unread over their host's budget or queue, since the start.
    quint64 droppedDatagrams() const { return m_dropped; }
    // Datagrams taken and handed on since the start (any thread).
    quint64 processedDatagrams() const { return m_processed; }
    const msg::SchemaSet &schemas() const { return *m_schemas; }
    void setPacketTap(PacketTap tap) { m_tap = std::move(tap); }

    // One datagram as it arrived from `from`:`fromPort`, within its host's
    // budget, on the caller's thread (tests and the fuzz target call it
    // without any socket).
    void receive(QByteArrayView datagram, const QHostAddress &from, quint16 fromPort);

    // OutputSink: sends `message` to `system`, addressed to it, in its
    // definitions; an error says why not (never heard of, not in its
    // definitions, the socket's reason).
    std::expected<void, QString> publish(quint16 system, const msg::Message &message) override;

    // Sends a Heartbeat to every vehicle now, and an Announce to them and to
    // the discovery ports every `announceEvery`-th time.
    void heartbeat();

    // The IMC version a system announces ("5.4.31"), empty until known.
    QString announcedVersion(quint16 system) const;

    // The hosts a system was heard from within the conflict window
    // ("127.0.0.2"), and where commands to it go ("127.0.0.2:6002"; "" while
    // held or unknown).
    QStringList sources(quint16 system) const;
    QString destination(quint16 system) const;
    // The operator trusts this host as `system`: commands go there while it
    // is remembered; "" goes back to automatic. False if `system` was not
    // heard from that host.
    bool pick(quint16 system, const QString &host);
    // Forgets systems not heard from for forgetAfterMs (the heartbeat does it too).
    void forgetSilent();

signals:
    // A decoded message and the size of its packet.
    void received(const neptus::msg::Message &message, qsizetype bytes);
    void systemDiscovered(quint16 system, const QString &name);
    // A packet that could not be decoded: the sender's id when the header
    // gave one (else 0xFFFF), the address it came from, and why.
    void decodeFailed(quint16 system, const QString &peer, const QString &reason);
    // A system's Announce names the IMC version it was built with (its
    // "imc+info://…/version/X" service), the first time and when it changes.
    void versionAnnounced(quint16 system, const QString &version);
    // Who sends as `system` changed: its recent senders, where commands go
    // ("" while two claim it and none was picked).
    void sourcesChanged(quint16 system, const QStringList &senders, const QString &destination);
    // An Announce for `system` from host `from` named no imc+udp address on
    // that host: no command will go to the addresses it names.
    void announceIgnored(quint16 system, const QString &from, const QString &services);
    // Datagrams from `host` dropped in the last second: `overRate` past its
    // budget (the host sends too much), `behind` because its queue was full
    // (this console fell behind); both 0 once a second goes by without any.
    void overloaded(const QString &host, int overRate, int behind);

private:
    struct Endpoint
    {
        QHostAddress address;
        quint16 port = 0;
        QString name() const;
    };
    // A host that sends as some system: where its messages come from, the
    // address it announces on that host, and when it was last heard.
    struct Sender
    {
        std::optional<Endpoint> data;
        std::optional<Endpoint> announced;
        qint64 lastMs = 0;
    };
    // A system: the hosts it was heard from, and where commands go.
    struct Peer
    {
        QHash<QString, Sender> senders; // by host address
        QString picked;                 // the host the operator trusts
        QStringList sources;            // as last reported by sourcesChanged
        QString destination;            // as last reported ("" while held)
        std::optional<Endpoint> target; // where commands and heartbeats go
        qint64 greetedMs = 0;           // when it was last greeted
    };
    // Datagrams from one host in the current second.
    struct Budget
    {
        qint64 secondStartMs = 0;
        int count = 0;
        int dropped = 0; // over its rate
        int behind = 0;  // its queue was full
        bool overloaded = false; // the last second dropped some
    };
    // Signals found with the state locked, emitted once it is not.
    using Later = std::vector<std::function<void()>>;
    static void emitAll(Later &later);

    qint64 nowMs() const { return m_config.clock->now().toMSecsSinceEpoch(); }
    // With m_mutex held (…Locked), changes to report go to `later`.
    // The sender record of `host` for `system`; null when maxSystems are kept already.
    Sender *senderForLocked(quint16 system, const QString &host);
    // Works out where commands to `system` go, and reports a change.
    void resolveLocked(quint16 system, Later &later);
    bool withinBudgetLocked(const QString &host, Later &later);
    void rollBudgetLocked(const QString &host, Budget &budget, qint64 now, Later &later);
    void learnFromAnnounceLocked(const msg::Message &announce, const QHostAddress &from, const QString &host, Later &later);
    std::expected<void, QString> sendLocked(const msg::Message &message, const Endpoint &to);
    // Our Announce to the discovery ports of `host`, a Heartbeat to `target` now and again shortly.
    void greetLocked(quint16 system, const QHostAddress &host, const Endpoint &target);

    // The pump's: datagrams dropped unread (over a host's rate, or its queue full).
    void dropped(const QHash<QString, int> &overRate, const QHash<QString, int> &behind);
    // A datagram within its host's budget, from `host` (DatagramReader::hostName(from)), on any thread.
    void process(QByteArrayView datagram, const QHostAddress &from, quint16 fromPort, const QString &host);
    double now() const { return m_config.clock->now().toMSecsSinceEpoch() / 1000.0; }
    msg::Message announcement() const;
    std::expected<void, QString> bindDiscovery(QUdpSocket &socket, QUdpSocket &discovery);
    // Where our Announce goes besides the vehicles we know: the discovery ports.
    QList<Endpoint> discoveryTargets() const;

    std::shared_ptr<msg::SchemaSet> m_schemas;
    PacketTap m_tap;
    ImcUdpConfig m_config;
    mutable std::mutex m_mutex; // guards the peers, budgets, versions, m_buffer and the sending socket
    int m_fd = -1;          // bound by start(); sends go from it
    int m_discoveryFd = -1;
    quint16 m_port = 0;
    quint16 m_discoveryPort = 0;
    QTimer m_timer;
    QHash<quint16, Peer> m_peers; // known systems
    QHash<QString, Budget> m_budgets; // by sending host
    QHash<quint16, QString> m_versions;
    int m_ticks = 0;
    std::atomic<int> m_decodeErrors = 0;
    std::atomic<quint64> m_dropped = 0;
    std::atomic<quint64> m_processed = 0;
    QByteArray m_buffer;
    std::unique_ptr<DatagramPump> m_pump; // stops before the rest goes
};

} // namespace neptus::transport
