#include "core/DataFiles.h"
#include "transport/dds/DdsTransport.h"

#include "Envelope.h"

#include <QFile>
#include <QMetaObject>
#include <QMutexLocker>
#include <QVarLengthArray>

#include <array>

namespace neptus::transport {

DdsTransport::DdsTransport(std::shared_ptr<msg::SchemaSet> schemas, DdsConfig config, QObject *parent)
    : QObject(parent)
    , m_schemas(std::move(schemas))
    , m_config(std::move(config))
{
}

DdsTransport::DdsTransport(std::shared_ptr<const msg::Schema> schema, DdsConfig config, QObject *parent)
    : DdsTransport(std::make_shared<msg::SchemaSet>(std::move(schema)), std::move(config), parent)
{
}

DdsTransport::~DdsTransport()
{
    if (m_participant > 0)
        dds_delete(m_participant); // also deletes its readers, writers and topics, and waits for listeners
}

std::expected<void, QString> DdsTransport::start()
{
    QString file = m_config.configFile.isEmpty() ? dataPath(QStringLiteral("dds/loopback.xml")) : m_config.configFile;
    QFile xml(file);
    if (!xml.open(QIODevice::ReadOnly))
        return std::unexpected(QStringLiteral("DDS: cannot read the configuration %1: %2").arg(file, xml.errorString()));
    const QByteArray config = xml.readAll();
    const dds_entity_t domain = dds_create_domain(m_config.domain, config.constData());
    // A second transport in the same process shares the domain already made.
    if (domain < 0 && domain != DDS_RETCODE_PRECONDITION_NOT_MET)
        return std::unexpected(QStringLiteral("DDS: cannot create domain %1 from %2: %3")
                                   .arg(m_config.domain).arg(file, QString::fromUtf8(dds_strretcode(domain))));
    m_participant = dds_create_participant(m_config.domain, nullptr, nullptr);
    if (m_participant < 0)
        return std::unexpected(QStringLiteral("DDS: cannot join domain %1: %2")
                                   .arg(m_config.domain).arg(QString::fromUtf8(dds_strretcode(m_participant))));
    dds_listener_t *listener = dds_create_listener(this);
    dds_lset_data_available(listener, &DdsTransport::onData);
    for (const auto &def : m_schemas->defaultSchema().messages()) {
        const dds_entity_t topic = topicFor(def->abbrev);
        if (topic < 0)
            continue;
        dds_qos_t *qos = qosFor(def->abbrev);
        const dds_entity_t reader = dds_create_reader(m_participant, topic, qos, listener);
        dds_delete_qos(qos);
        if (reader < 0) {
            dds_delete_listener(listener);
            return std::unexpected(QStringLiteral("DDS: cannot read topic neptus/%1: %2")
                                       .arg(def->abbrev, QString::fromUtf8(dds_strretcode(reader))));
        }
    }
    dds_delete_listener(listener);

    // Say who we are, for as long as we live, and listen to who the others are.
    dds_qos_t *lasting = dds_create_qos();
    dds_qset_reliability(lasting, DDS_RELIABILITY_RELIABLE, DDS_MSECS(100));
    dds_qset_durability(lasting, DDS_DURABILITY_TRANSIENT_LOCAL);
    dds_qset_history(lasting, DDS_HISTORY_KEEP_LAST, 1);
    dds_qset_ignorelocal(lasting, DDS_IGNORELOCAL_PARTICIPANT);
    const dds_entity_t topic = dds_create_topic(m_participant, &neptus_Participant_desc, "neptus/participant", nullptr, nullptr);
    dds_listener_t *peers = dds_create_listener(this);
    dds_lset_data_available(peers, &DdsTransport::onParticipant);
    const dds_entity_t peerReader = dds_create_reader(m_participant, topic, lasting, peers);
    dds_delete_listener(peers);
    m_participantWriter = dds_create_writer(m_participant, topic, lasting, nullptr);
    dds_delete_qos(lasting);
    if (topic < 0 || peerReader < 0 || m_participantWriter < 0)
        return std::unexpected(QStringLiteral("DDS: cannot set up the participant topic"));
    QByteArray name = m_config.systemName.toUtf8(), type = m_config.systemType.toUtf8();
    QByteArray digest = m_schemas->defaultSchema().digest();
    neptus_Participant self{};
    self.system = m_config.systemId;
    self.name = name.data();
    self.type = type.data();
    self.digest = digest.data();
    dds_write(m_participantWriter, &self);
    return {};
}

void DdsTransport::onParticipant(dds_entity_t reader, void *self)
{
    auto *transport = static_cast<DdsTransport *>(self);
    void *samples[8] = {};
    dds_sample_info_t infos[8];
    for (;;) {
        const dds_return_t n = dds_take(reader, samples, infos, 8, 8);
        if (n <= 0)
            break;
        for (int i = 0; i < n; ++i) {
            const auto *peer = static_cast<const neptus_Participant *>(samples[i]);
            if (!infos[i].valid_data || peer->system == transport->m_config.systemId)
                continue;
            const QString theirs = QString::fromUtf8(peer->digest);
            const QString ours = QString::fromLatin1(transport->m_schemas->defaultSchema().digest());
            QMutexLocker lock(&transport->m_mutex);
            if (theirs == ours || transport->m_peerDigests.value(peer->system) == theirs)
                continue;
            transport->m_peerDigests.insert(peer->system, theirs);
            const quint16 system = peer->system;
            const QString name = QString::fromUtf8(peer->name);
            QMetaObject::invokeMethod(transport, [transport, system, name, theirs, ours] {
                emit transport->definitionsDiffer(system, name, theirs, ours);
            }, Qt::QueuedConnection);
        }
        dds_return_loan(reader, samples, n);
    }
}

dds_qos_t *DdsTransport::qosFor(const QString &abbrev) const
{
    dds_qos_t *qos = dds_create_qos();
    // Our own samples never come back to us (no copy, no listener call).
    dds_qset_ignorelocal(qos, DDS_IGNORELOCAL_PARTICIPANT);
    if (m_config.lasting.contains(abbrev)) {
        dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_MSECS(100));
        dds_qset_durability(qos, DDS_DURABILITY_TRANSIENT_LOCAL);
        dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 1);
    } else if (m_config.reliable.contains(abbrev)) {
        dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_MSECS(100));
        dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 32);
    } else {
        dds_qset_reliability(qos, DDS_RELIABILITY_BEST_EFFORT, 0);
        dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 1);
    }
    return qos;
}

dds_entity_t DdsTransport::topicFor(const QString &abbrev)
{
    QMutexLocker lock(&m_mutex);
    const auto it = m_topics.constFind(abbrev);
    if (it != m_topics.cend())
        return *it;
    const QByteArray name = "neptus/" + abbrev.toUtf8();
    const dds_entity_t topic = dds_create_topic(m_participant, &neptus_Envelope_desc, name.constData(), nullptr, nullptr);
    m_topics.insert(abbrev, topic);
    return topic;
}

namespace {

// Samples are taken into envelopes each Cyclone thread keeps, not into loans:
// a packet's bytes land in the buffer the previous sample grew, so taking a
// sample allocates nothing (a loan is freed and allocated again each time).
struct TakeBuffers
{
    static constexpr int count = 16;
    std::array<neptus_Envelope, count> envelopes{};
    std::array<void *, count> samples{};
    std::array<dds_sample_info_t, count> infos{};
    TakeBuffers()
    {
        for (int i = 0; i < count; ++i)
            samples[i] = &envelopes[i];
    }
    ~TakeBuffers()
    {
        for (auto &envelope : envelopes)
            dds_sample_free(&envelope, &neptus_Envelope_desc, DDS_FREE_CONTENTS);
    }
};

} // namespace

void DdsTransport::onData(dds_entity_t reader, void *self)
{
    auto *transport = static_cast<DdsTransport *>(self);
    thread_local TakeBuffers buffers;
    for (;;) {
        const dds_return_t n = dds_take(reader, buffers.samples.data(), buffers.infos.data(), TakeBuffers::count,
                                        TakeBuffers::count);
        if (n <= 0)
            break;
        for (int i = 0; i < n; ++i) {
            const neptus_Envelope &envelope = buffers.envelopes[i];
            if (!buffers.infos[i].valid_data || envelope.src == transport->m_config.systemId)
                continue; // a disposal, or our own
            const auto bytes = static_cast<qsizetype>(envelope.packet._length);
            auto message = transport->m_schemas->codecFor(envelope.src)->decode(QByteArrayView(envelope.packet._buffer, bytes));
            if (!message) {
                const quint16 system = envelope.src;
                QMetaObject::invokeMethod(transport, [transport, system, why = message.error().toString()] {
                    emit transport->decodeFailed(system, QStringLiteral("DDS"), why);
                }, Qt::QueuedConnection);
                continue;
            }
            if (transport->m_direct) {
                transport->m_direct(*message, bytes);
                continue;
            }
            QMetaObject::invokeMethod(transport, [transport, bytes, m = std::move(*message)] {
                emit transport->received(m, bytes);
            }, Qt::QueuedConnection);
        }
    }
}

dds_entity_t DdsTransport::writerFor(const msg::MessageDef &def)
{
    if (m_participant <= 0)
        return 0;
    {
        QMutexLocker lock(&m_mutex);
        if (const dds_entity_t writer = m_writers.value(&def, 0))
            return writer;
    }
    const dds_entity_t topic = topicFor(def.abbrev);
    QMutexLocker lock(&m_mutex);
    dds_entity_t writer = m_writers.value(&def, 0);
    if (writer == 0) {
        dds_qos_t *qos = qosFor(def.abbrev);
        // Samples of a burst share datagrams; every send ends with a flush.
        dds_qset_writer_batching(qos, true);
        writer = dds_create_writer(m_participant, topic, qos, nullptr);
        dds_delete_qos(qos);
        if (writer < 0)
            return 0;
        m_writers.insert(&def, writer);
    }
    return writer;
}

std::expected<void, QString> DdsTransport::write(dds_entity_t writer, const msg::Message &message,
                                                 const msg::Message::Header &header)
{
    // Encoded into a buffer each thread keeps: sending allocates nothing.
    thread_local QByteArray packet;
    if (auto encoded = m_schemas->codecFor(header.dst)->encode(message, header, packet); !encoded)
        return std::unexpected(QStringLiteral("%1 does not encode: %2").arg(message.abbrev(), encoded.error().toString()));
    neptus_Envelope envelope{};
    envelope.src = header.src;
    envelope.src_ent = header.srcEnt;
    envelope.dst = header.dst;
    envelope.dst_ent = header.dstEnt;
    envelope.timestamp = header.timestamp;
    envelope.mgid = message.id();
    envelope.packet._buffer = reinterpret_cast<uint8_t *>(packet.data());
    envelope.packet._length = static_cast<uint32_t>(packet.size());
    envelope.packet._maximum = static_cast<uint32_t>(packet.size());
    envelope.packet._release = false;
    if (const dds_return_t written = dds_write(writer, &envelope); written != DDS_RETCODE_OK)
        return std::unexpected(QStringLiteral("DDS: cannot write %1: %2")
                                   .arg(message.abbrev(), QString::fromUtf8(dds_strretcode(written))));
    return {};
}

bool DdsTransport::broadcast(const msg::Message &message)
{
    return broadcast(std::span(&message, 1));
}

bool DdsTransport::broadcast(std::span<const msg::Message> messages)
{
    const double now = m_config.clock->now().toMSecsSinceEpoch() / 1000.0;
    bool sent = true;
    QVarLengthArray<dds_entity_t, 8> used;
    const msg::MessageDef *def = nullptr;
    dds_entity_t writer = 0;
    for (const msg::Message &message : messages) {
        if (message.def() != def) { // a burst is mostly of one kind: look its writer up once
            def = message.def();
            writer = def ? writerFor(*def) : 0;
            if (writer > 0 && !used.contains(writer))
                used.append(writer);
        }
        msg::Message::Header header = message.header;
        header.src = m_config.systemId;
        if (header.timestamp == 0)
            header.timestamp = now;
        sent = writer > 0 && write(writer, message, header).has_value() && sent;
    }
    for (dds_entity_t w : used)
        dds_write_flush(w);
    return sent;
}

std::expected<void, QString> DdsTransport::publish(quint16 system, const msg::Message &message)
{
    const auto addressed = m_schemas->forSystem(system, message);
    if (!addressed)
        return std::unexpected(addressed.error());
    const dds_entity_t writer = addressed->def() ? writerFor(*addressed->def()) : 0;
    if (writer <= 0)
        return std::unexpected(QStringLiteral("DDS: no writer for %1 (not started?)").arg(addressed->abbrev()));
    msg::Message::Header header = addressed->header;
    header.src = m_config.systemId;
    header.dst = system;
    header.timestamp = m_config.clock->now().toMSecsSinceEpoch() / 1000.0;
    auto sent = write(writer, *addressed, header);
    dds_write_flush(writer);
    return sent;
}

} // namespace neptus::transport
