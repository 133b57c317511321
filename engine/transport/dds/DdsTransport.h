#pragma once

#include "core/Clock.h"
#include "messages/SchemaSet.h"
#include "transport/OutputSink.h"

#include <QHash>
#include <QMutex>
#include <QObject>

#include <dds/dds.h>

#include <expected>
#include <functional>
#include <memory>
#include <span>

namespace neptus::transport {

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
    const Clock *clock = &Clock::system(); // stamps what it sends
};

// Cyclone DDS between consoles and vehicles: every message of the schema on
// its own topic ("neptus/<abbrev>"), carried as an IMC packet in a fixed
// envelope (Envelope.idl), reliable, keyed by the sender. Samples arrive on
// Cyclone's threads and are handed to this object's thread as `received`.
// Packets are decoded with the sender's definitions (SchemaSet, by the
// envelope's src) and encoded with the receiver's.
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

    // Sends a message of this node to everyone (vehicles, simulators).
    bool broadcast(const msg::Message &message);
    // Sends several at once (a burst of telemetry, a log replayed): messages
    // of the same kind share datagrams, sent when all are written. False if
    // any could not be sent.
    bool broadcast(std::span<const msg::Message> messages);
    // OutputSink: to one system, in its definitions; an error says why not.
    std::expected<void, QString> publish(quint16 system, const msg::Message &message) override;

signals:
    // A decoded message and the size of its packet.
    void received(const neptus::msg::Message &message, qsizetype bytes);
    // A sample whose packet could not be decoded: the sender's system id (from
    // the envelope), the peer ("DDS"), and why.
    void decodeFailed(quint16 system, const QString &peer, const QString &reason);
    // A peer speaks other message definitions than ours: values it sends may
    // be decoded wrongly. Said once per peer and digest.
    void definitionsDiffer(quint16 system, const QString &name, const QString &theirDigest, const QString &ourDigest);

private:
    static void onData(dds_entity_t reader, void *self);
    static void onParticipant(dds_entity_t reader, void *self);
    dds_entity_t topicFor(const QString &abbrev);
    // The QoS of a message's topic, the same for its readers and writers so they always match.
    dds_qos_t *qosFor(const QString &abbrev) const;
    // The writer of a message's topic, made on first use; 0 if it cannot be.
    dds_entity_t writerFor(const msg::MessageDef &def);
    // Writes `message` with `header` without sending: samples wait in the
    // writer's batch until flushed.
    std::expected<void, QString> write(dds_entity_t writer, const msg::Message &message,
                                       const msg::Message::Header &header);

    std::shared_ptr<msg::SchemaSet> m_schemas;
    DdsConfig m_config;
    dds_entity_t m_participant = 0;
    QMutex m_mutex;
    QHash<QString, dds_entity_t> m_topics;
    QHash<const msg::MessageDef *, dds_entity_t> m_writers;
    dds_entity_t m_participantWriter = 0;
    QHash<quint16, QString> m_peerDigests;
    std::function<void(const msg::Message &, qsizetype)> m_direct;
};

} // namespace neptus::transport
