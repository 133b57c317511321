#pragma once

#include "core/Clock.h"
#include "messages/SchemaSet.h"
#include "transport/OutputSink.h"

#include <QHash>
#include <QSet>
#include <QMutex>
#include <QObject>

#include <dds/dds.h>

#include <expected>
#include <functional>
#include <memory>
#include <span>

namespace neptus::transport {

// DDS Security (authentication, access control, encryption) from a key set
// made by tools/dds-keys (docs/dds-security.md): `keys` holds the two CA
// certificates and governance.p7s, `keys`/`identity` this system's cert.pem,
// key.pem and permissions.p7s. Without keys a participant is not secured,
// and secured participants neither hear it nor are heard by it.
struct DdsSecurity
{
    QString keys;     // a folder; empty: no security
    QString identity; // the name the keys were made for
};

struct DdsConfig
{
    dds_domainid_t domain = 0;
    QString configFile;           // Cyclone XML; the project's dds/loopback.xml by default
    quint16 systemId = 0x4001;
    QString systemName = QStringLiteral("neptus-qt");
    QString systemType = QStringLiteral("CCU");
    // Commands and plans: reliable, with a history deep enough for a burst.
    // Every other message is telemetry: best-effort, the latest per sender.
    QStringList reliable{QStringLiteral("Abort"), QStringLiteral("PlanControl"), QStringLiteral("PlanDB"),
                         QStringLiteral("PlanSpecification"), QStringLiteral("SetEntityParameters"),
                         QStringLiteral("LogBookEntry")};
    // Who a participant is: kept for late joiners (transient-local, the
    // latest per sender), so a console started later still learns names.
    QStringList lasting{QStringLiteral("Announce"), QStringLiteral("EntityList"), QStringLiteral("EntityInfo")};
    // Every sample matters, in order (a shared mission's objects: a console
    // joining gets them all at once): reliable, keep-all.
    QStringList complete{QStringLiteral("MissionChange")};
    const Clock *clock = &Clock::system(); // stamps what it sends
    // How long two participants sending as one system id must be apart to be one.
    int conflictWindowMs = 10000;
    DdsSecurity security = {};
};

// Cyclone DDS between consoles and vehicles: every message of the schema on
// its own topic ("neptus/<abbrev>"), carried as an IMC packet in a fixed
// envelope (Envelope.idl), reliable, keyed by the sender. Samples arrive on
// Cyclone's threads and are handed to this object's thread as `received`.
// Packets are decoded with the sender's definitions (SchemaSet, by the
// envelope's src) and encoded with the receiver's.
//
// Against impostors: each sample's writer tells which participant sent it
// ("dds:" and its GUID prefix). Two participants sending as one system id
// within conflictWindowMs are a conflict: commands to it are held until the
// operator picks one (pick()), and from then on the other's samples for that
// system are dropped, so its position cannot jump between two places. (DDS
// delivers to every reader: only DDS Security keeps others from reading
// commands or writing as a vehicle.)
class DdsTransport : public QObject, public OutputSink
{
    Q_OBJECT

public:
    DdsTransport(std::shared_ptr<msg::SchemaSet> schemas, DdsConfig config, QObject *parent = nullptr);
    DdsTransport(std::shared_ptr<const msg::Schema> schema, DdsConfig config, QObject *parent = nullptr);
    ~DdsTransport() override;

    std::expected<void, QString> start();

    // Hands received messages straight to `receiver` on Cyclone's own
    // threads instead of `received` on this object's thread: for thread-safe
    // consumers (the variable tree, the console session), it saves the hop
    // through the event loop. Set before start().
    void setDirectReceiver(std::function<void(const msg::Message &, qsizetype bytes)> receiver)
    {
        m_direct = std::move(receiver);
    }

    void setPacketTap(PacketTap tap) { m_tap = std::move(tap); }

    // Sends a message of this node to everyone (vehicles, simulators).
    bool broadcast(const msg::Message &message);
    // Sends several at once (a burst of telemetry, a log replayed): messages
    // of the same kind share datagrams, sent when all are written. False if
    // any could not be sent.
    bool broadcast(std::span<const msg::Message> messages);
    // OutputSink: to one system, in its definitions; an error says why not.
    std::expected<void, QString> publish(quint16 system, const msg::Message &message) override;

    // This transport's own participant as others see it ("dds:<GUID prefix>"); empty before start().
    QString participantName() const;
    // The participants that sent as `system` within the conflict window.
    QStringList sources(quint16 system) const;
    // The operator trusts `participant` as `system`: commands flow again and
    // only its samples for `system` are taken; "" goes back to automatic.
    // False if `system` was not heard from that participant.
    bool pick(quint16 system, const QString &participant);

signals:
    // A decoded message and the size of its packet.
    void received(const neptus::msg::Message &message, qsizetype bytes);
    // A sample whose packet could not be decoded: the sender's system id (from
    // the envelope), the peer ("DDS"), and why.
    void decodeFailed(quint16 system, const QString &peer, const QString &reason);
    // A peer speaks other message definitions than ours: values it sends may
    // be decoded wrongly. Said once per peer and digest.
    void definitionsDiffer(quint16 system, const QString &name, const QString &theirDigest, const QString &ourDigest);
    // Who sends as `system` changed: its recent participants, and the one
    // trusted ("" while two claim it and none was picked).
    void sourcesChanged(quint16 system, const QStringList &senders, const QString &destination);
    // Another participant (named) announces itself as this console's own
    // system id (two consoles given the same id): what it sends is ignored.
    // Said again, naming another, when the one named leaves and others remain.
    void ourIdInUse(const QString &participant);
    // A participant announced itself as `system` (again, after it left: a
    // link back after an outage longer than the lease).
    void participantJoined(quint16 system);
    // Every participant that announced itself as `system` left or went
    // silent past its lease (this console's own id: the others using it left).
    void participantLeft(quint16 system);

private:
    // The participant QoS that turns DDS Security on (null without keys).
    static std::expected<dds_qos_t *, QString> securityQos(const DdsSecurity &security);
    static void onData(dds_entity_t reader, void *self);
    static void onParticipant(dds_entity_t reader, void *self);
    // DCPSParticipant: a participant that left (or whose lease ran out) no
    // longer counts as a sender, so a vehicle restarted is not its own impostor.
    static void onPresence(dds_entity_t reader, void *self);
    dds_entity_t topicFor(const QString &abbrev);
    // The QoS of a message's topic, the same for its readers and writers so they always match.
    dds_qos_t *qosFor(const QString &abbrev) const;
    // The writer of a message's topic, made on first use; 0 before start(),
    // negative (a DDS_RETCODE) if it cannot be made.
    dds_entity_t writerFor(const msg::MessageDef &def);
    // Writes `message` with `header` without sending: samples wait in the
    // writer's batch until flushed.
    std::expected<void, QString> write(dds_entity_t writer, const msg::Message &message,
                                       const msg::Message::Header &header);
    // Notes that the participant that wrote `publication` sent as `system`
    // at `nowMs`; false when its samples are to be dropped (the operator
    // trusts another).
    bool heard(quint16 system, dds_entity_t reader, dds_instance_handle_t publication, qint64 nowMs);

    // The participants that send as one system (by their names,
    // "dds:<GUID prefix>"), and the one trusted.
    struct Peer
    {
        QHash<QString, qint64> senders; // last heard, ms
        QString picked;
        QStringList sources;            // as last reported
        QString destination;            // as last reported ("" while held)
        QString last;                   // the sender of the last sample
        qint64 resolvedMs = 0;
    };
    void resolveLocked(quint16 system, Peer &peer, qint64 nowMs);

    std::shared_ptr<msg::SchemaSet> m_schemas;
    DdsConfig m_config;
    dds_entity_t m_participant = 0;
    mutable QMutex m_mutex;
    QHash<QString, dds_entity_t> m_topics;
    QHash<const msg::MessageDef *, dds_entity_t> m_writers;
    dds_entity_t m_participantWriter = 0;
    QHash<quint16, QString> m_peerDigests;
    struct Announcer
    {
        int system = -1;
        QString name;
    };
    QHash<QString, Announcer> m_announcers; // the system each participant announced itself as, and its name (by participantLabel)
    QSet<QString> m_left; // participants seen leaving: a late announcement of theirs is not counted
    QString m_ourIdNamed; // the participant announcing our system id that ourIdInUse named last
    QHash<dds_instance_handle_t, QString> m_participantOfWriter; // by publication handle
    QHash<quint16, Peer> m_peers;
    std::function<void(const msg::Message &, qsizetype)> m_direct;
    PacketTap m_tap;
};

} // namespace neptus::transport
