#include "core/DataFiles.h"
#include "transport/dds/DdsTransport.h"

#include "Envelope.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QMetaObject>
#include <QMutexLocker>
#include <QVarLengthArray>

#include <array>
#include <tuple>

#include <dlfcn.h>

namespace neptus::transport {

namespace {

// Where Cyclone's security plugins are: beside libddsc, or in Debian's
// private folder there (libddsc0debian); else the bare names for the loader.
QString securityPlugin(const char *name)
{
    Dl_info info{};
    if (dladdr(reinterpret_cast<void *>(&dds_create_participant), &info) != 0 && info.dli_fname) {
        const QString dir = QFileInfo(QString::fromLocal8Bit(info.dli_fname)).absolutePath();
        for (const QString &candidate : {dir + QStringLiteral("/libddsc0debian/lib%1.so"), dir + QStringLiteral("/lib%1.so")}) {
            const QString path = candidate.arg(QLatin1String(name));
            if (QFileInfo::exists(path))
                return path;
        }
    }
    return QLatin1String(name);
}

// How a participant is named to the operator: "dds:" and its GUID prefix.
QString participantLabel(const dds_guid_t &guid)
{
    return QStringLiteral("dds:") + QByteArray(reinterpret_cast<const char *>(guid.v), 12).toHex();
}

// Takes every sample `reader` has, on loan, 8 at a time: fn(sample, info).
template<typename Sample, typename Fn>
void forEachTaken(dds_entity_t reader, Fn fn)
{
    void *samples[8] = {};
    dds_sample_info_t infos[8];
    for (;;) {
        const dds_return_t n = dds_take(reader, samples, infos, 8, 8);
        if (n <= 0)
            return;
        for (int i = 0; i < n; ++i)
            fn(*static_cast<const Sample *>(samples[i]), infos[i]);
        dds_return_loan(reader, samples, n);
    }
}

} // namespace

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
    auto qos = securityQos(m_config.security);
    if (!qos)
        return std::unexpected(qos.error());
    m_participant = dds_create_participant(m_config.domain, *qos, nullptr);
    dds_delete_qos(*qos);
    if (m_participant < 0 && !m_config.security.keys.isEmpty())
        return std::unexpected(QStringLiteral("DDS Security: cannot join domain %1 as %2 with the keys in %3: %4 "
                                              "(expired or mismatched certificates, a permissions document for "
                                              "another name or domain, or unsigned documents)")
                                   .arg(m_config.domain)
                                   .arg(m_config.security.identity, m_config.security.keys,
                                        QString::fromUtf8(dds_strretcode(m_participant))));
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
    dds_listener_t *presence = dds_create_listener(this);
    dds_lset_data_available(presence, &DdsTransport::onPresence);
    const dds_entity_t presenceReader = dds_create_reader(m_participant, DDS_BUILTIN_TOPIC_DCPSPARTICIPANT, nullptr, presence);
    dds_delete_listener(presence);
    m_participantWriter = dds_create_writer(m_participant, topic, lasting, nullptr);
    dds_delete_qos(lasting);
    if (topic < 0 || peerReader < 0 || presenceReader < 0 || m_participantWriter < 0)
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

std::expected<dds_qos_t *, QString> DdsTransport::securityQos(const DdsSecurity &security)
{
    if (security.keys.isEmpty())
        return nullptr;
    const QDir keys(security.keys);
    const QString identity = security.identity;
    if (identity.isEmpty() || identity.contains(u'/'))
        return std::unexpected(QStringLiteral("DDS Security: name the identity (a folder of %1) to use").arg(keys.path()));
    const std::pair<const char *, QString> files[] = {
        {"dds.sec.auth.identity_ca", QStringLiteral("identity_ca.pem")},
        {"dds.sec.auth.identity_certificate", identity + QStringLiteral("/cert.pem")},
        {"dds.sec.auth.private_key", identity + QStringLiteral("/key.pem")},
        {"dds.sec.access.permissions_ca", QStringLiteral("permissions_ca.pem")},
        {"dds.sec.access.governance", QStringLiteral("governance.p7s")},
        {"dds.sec.access.permissions", identity + QStringLiteral("/permissions.p7s")},
    };
    for (const auto &[property, file] : files) {
        if (!QFileInfo(keys.filePath(file)).isReadable())
            return std::unexpected(QStringLiteral("DDS Security: %1 is missing or unreadable (make keys with tools/dds-keys)")
                                       .arg(keys.filePath(file)));
    }
    dds_qos_t *qos = dds_create_qos();
    for (const auto &[property, file] : files)
        dds_qset_prop(qos, property, (QStringLiteral("file:") + keys.absoluteFilePath(file)).toUtf8().constData());
    const std::tuple<const char *, const char *, const char *, const char *> plugins[] = {
        {"auth", "dds_security_auth", "init_authentication", "finalize_authentication"},
        {"crypto", "dds_security_crypto", "init_crypto", "finalize_crypto"},
        {"access", "dds_security_ac", "init_access_control", "finalize_access_control"},
    };
    for (const auto &[kind, library, init, finalize] : plugins) {
        const QByteArray prefix = QByteArray("dds.sec.") + kind + ".library.";
        dds_qset_prop(qos, (prefix + "path").constData(), securityPlugin(library).toUtf8().constData());
        dds_qset_prop(qos, (prefix + "init").constData(), init);
        dds_qset_prop(qos, (prefix + "finalize").constData(), finalize);
    }
    return qos;
}

void DdsTransport::onParticipant(dds_entity_t reader, void *self)
{
    auto *transport = static_cast<DdsTransport *>(self);
    forEachTaken<neptus_Participant>(reader, [transport, reader](const neptus_Participant &peer, const dds_sample_info_t &info) {
        if (!info.valid_data)
            return; // who left is told by the participants' own presence (onPresence), one by one
        const quint16 system = peer.system;
        // The participant that announced it: several may share a system id, and
        // the id is free again only when the last of them has left.
        // (One whose writer DDS no longer knows, or that has already left, is not counted: nothing
        // would ever say it left.)
        QString participant;
        if (dds_builtintopic_endpoint_t *writer = dds_get_matched_publication_data(reader, info.publication_handle)) {
            participant = participantLabel(writer->participant_key);
            dds_builtintopic_free_endpoint(writer);
        }
        const QString name = QString::fromUtf8(peer.name);
        if (!participant.isEmpty()) {
            QMutexLocker lock(&transport->m_mutex);
            if (!transport->m_left.contains(participant)) {
                const bool joined = transport->m_announcers.value(participant).system != system;
                transport->m_announcers.insert(participant, Announcer{system, name});
                if (joined)
                    QMetaObject::invokeMethod(transport, [transport, system] { emit transport->participantJoined(system); },
                                              Qt::QueuedConnection);
            }
            if (system == transport->m_config.systemId)
                transport->m_ourIdNamed = participant;
        }
        if (system == transport->m_config.systemId) {
            // Another participant as this system (ignorelocal: not us).
            QMetaObject::invokeMethod(transport, [transport, name] { emit transport->ourIdInUse(name); }, Qt::QueuedConnection);
            return;
        }
        const QString theirs = QString::fromUtf8(peer.digest);
        const QString ours = QString::fromLatin1(transport->m_schemas->defaultSchema().digest());
        QMutexLocker lock(&transport->m_mutex);
        if (theirs == ours || transport->m_peerDigests.value(peer.system) == theirs)
            return;
        transport->m_peerDigests.insert(peer.system, theirs);
        QMetaObject::invokeMethod(transport, [transport, system, name, theirs, ours] {
            emit transport->definitionsDiffer(system, name, theirs, ours);
        }, Qt::QueuedConnection);
    });
}

void DdsTransport::onPresence(dds_entity_t reader, void *self)
{
    auto *transport = static_cast<DdsTransport *>(self);
    QStringList gone;
    forEachTaken<dds_builtintopic_participant_t>(reader, [&](const dds_builtintopic_participant_t &participant,
                                                             const dds_sample_info_t &info) {
        if (info.instance_state != DDS_IST_ALIVE)
            gone << participantLabel(participant.key);
    });
    if (gone.isEmpty())
        return;
    const qint64 now = monotonicMs();
    QMutexLocker lock(&transport->m_mutex);
    transport->m_participantOfWriter.removeIf([&](const auto &it) { return gone.contains(it.value()); });
    for (const QString &name : gone)
        transport->m_left.insert(name); // (a participant's key is never used again)
    // The systems whose last announcer left.
    const auto announcerOf = [transport](int system) {
        return std::ranges::find_if(transport->m_announcers, [system](const Announcer &a) { return a.system == system; });
    };
    for (const QString &name : gone) {
        const int system = transport->m_announcers.value(name).system;
        if (system < 0)
            continue;
        transport->m_announcers.remove(name);
        if (announcerOf(system) != transport->m_announcers.end())
            continue;
        transport->m_peerDigests.remove(quint16(system));
        QMetaObject::invokeMethod(transport, [transport, system] { emit transport->participantLeft(quint16(system)); },
                                  Qt::QueuedConnection);
    }
    // The other console named as using our id left while others still do: name one of them.
    if (const auto still = announcerOf(transport->m_config.systemId);
        gone.contains(transport->m_ourIdNamed) && still != transport->m_announcers.end()) {
        transport->m_ourIdNamed = still.key();
        QMetaObject::invokeMethod(transport, [transport, name = still->name] { emit transport->ourIdInUse(name); },
                                  Qt::QueuedConnection);
    }
    for (auto peer = transport->m_peers.begin(); peer != transport->m_peers.end(); ++peer) {
        bool changed = false;
        for (const QString &name : gone) {
            changed = peer->senders.remove(name) || changed;
            if (peer->picked == name)
                peer->picked.clear();
            if (peer->last == name)
                peer->last.clear();
        }
        if (changed)
            transport->resolveLocked(peer.key(), *peer, now);
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
    } else if (m_config.complete.contains(abbrev)) {
        dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
        dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
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
        const qint64 now = monotonicMs();
        for (int i = 0; i < n; ++i) {
            const neptus_Envelope &envelope = buffers.envelopes[i];
            // (Our own samples never come here, ignorelocal: one sent as our
            // id is another participant's, said by onParticipant.)
            if (!buffers.infos[i].valid_data || envelope.src == transport->m_config.systemId)
                continue; // a disposal, or sent as us
            if (!transport->heard(envelope.src, reader, buffers.infos[i].publication_handle, now))
                continue; // the operator trusts another participant as this system
            const auto bytes = static_cast<qsizetype>(envelope.packet._length);
            auto message = transport->m_schemas->codecFor(envelope.src)->decode(QByteArrayView(envelope.packet._buffer, bytes));
            if (!message) {
                const quint16 system = envelope.src;
                QMetaObject::invokeMethod(transport, [transport, system, why = message.error().toString()] {
                    emit transport->decodeFailed(system, QStringLiteral("DDS"), why);
                }, Qt::QueuedConnection);
                continue;
            }
            if (transport->m_tap)
                transport->m_tap(QByteArrayView(envelope.packet._buffer, bytes));
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

bool DdsTransport::heard(quint16 system, dds_entity_t reader, dds_instance_handle_t publication, qint64 nowMs)
{
    constexpr int sendersPerSystem = 16;
    QMutexLocker lock(&m_mutex);
    auto name = m_participantOfWriter.constFind(publication);
    if (name == m_participantOfWriter.cend()) {
        // The writer's participant names it.
        QString participant = QStringLiteral("dds:unknown");
        lock.unlock();
        if (dds_builtintopic_endpoint_t *writer = dds_get_matched_publication_data(reader, publication)) {
            participant = participantLabel(writer->participant_key);
            dds_builtintopic_free_endpoint(writer);
        }
        lock.relock();
        if (m_participantOfWriter.size() >= 4096) // writers come and go: forget them all now and then
            m_participantOfWriter.clear();
        name = m_participantOfWriter.insert(publication, participant);
    }
    const QString &participant = *name;
    Peer &peer = m_peers[system];
    // The usual case: the one sender of this system again.
    if (peer.senders.size() == 1 && peer.last == participant) {
        qint64 &last = *peer.senders.begin();
        const bool wasSilent = nowMs - last > m_config.conflictWindowMs;
        last = nowMs;
        if (wasSilent)
            resolveLocked(system, peer, nowMs);
        return peer.picked.isEmpty() || peer.picked == participant;
    }
    auto sender = peer.senders.find(participant);
    const bool arrived = sender == peer.senders.end() || nowMs - *sender > m_config.conflictWindowMs;
    if (sender == peer.senders.end()) {
        if (peer.senders.size() >= sendersPerSystem)
            return false;
        sender = peer.senders.insert(participant, nowMs);
    }
    *sender = nowMs;
    peer.last = participant;
    // Several senders: who is recent changes slowly, look a few times a second.
    if (arrived || nowMs - peer.resolvedMs >= 250)
        resolveLocked(system, peer, nowMs);
    return peer.picked.isEmpty() || peer.picked == participant;
}

void DdsTransport::resolveLocked(quint16 system, Peer &peer, qint64 nowMs)
{
    peer.resolvedMs = nowMs;
    QStringList recent;
    QString newest;
    qint64 newestMs = std::numeric_limits<qint64>::min();
    for (auto it = peer.senders.cbegin(); it != peer.senders.cend(); ++it) {
        if (nowMs - *it <= m_config.conflictWindowMs)
            recent.append(it.key());
        if (*it > newestMs) {
            newestMs = *it;
            newest = it.key();
        }
    }
    recent.sort();
    QString chosen;
    if (!peer.picked.isEmpty())
        chosen = peer.picked;
    else if (recent.size() == 1)
        chosen = recent.front();
    else if (recent.isEmpty())
        chosen = newest;
    if (recent == peer.sources && chosen == peer.destination)
        return;
    peer.sources = recent;
    peer.destination = chosen;
    QMetaObject::invokeMethod(this, [this, system, recent, chosen] { emit sourcesChanged(system, recent, chosen); },
                              Qt::QueuedConnection);
}

QString DdsTransport::participantName() const
{
    dds_guid_t guid{};
    if (m_participant <= 0 || dds_get_guid(m_participant, &guid) != DDS_RETCODE_OK)
        return {};
    return participantLabel(guid);
}

QStringList DdsTransport::sources(quint16 system) const
{
    QMutexLocker lock(&m_mutex);
    return m_peers.value(system).sources;
}

bool DdsTransport::pick(quint16 system, const QString &participant)
{
    QMutexLocker lock(&m_mutex);
    const auto it = m_peers.find(system);
    if (it == m_peers.end() || (!participant.isEmpty() && !it->senders.contains(participant)))
        return false;
    it->picked = participant;
    resolveLocked(system, *it, monotonicMs());
    return true;
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
            return writer; // the reason, e.g. DDS_RETCODE_NOT_ALLOWED_BY_SECURITY
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
    if (m_tap)
        m_tap(packet);
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
    {
        QMutexLocker lock(&m_mutex);
        const auto peer = m_peers.constFind(system);
        if (peer != m_peers.cend() && peer->destination.isEmpty() && peer->sources.size() > 1)
            return std::unexpected(QStringLiteral("DDS: %1 participants send as %2 (%3): commands are held until one is chosen")
                                       .arg(peer->sources.size())
                                       .arg(msg::systemLabel(system), peer->sources.join(QStringLiteral(", "))));
    }
    const auto addressed = m_schemas->forSystem(system, message);
    if (!addressed)
        return std::unexpected(addressed.error());
    const dds_entity_t writer = addressed->def() ? writerFor(*addressed->def()) : 0;
    if (writer == DDS_RETCODE_NOT_ALLOWED_BY_SECURITY)
        return std::unexpected(QStringLiteral("DDS Security: the permissions of %1 do not allow publishing neptus/%2")
                                   .arg(m_config.security.identity, addressed->abbrev()));
    if (writer == 0)
        return std::unexpected(QStringLiteral("DDS: no writer for %1 (not started)").arg(addressed->abbrev()));
    if (writer < 0)
        return std::unexpected(QStringLiteral("DDS: no writer for %1: %2").arg(addressed->abbrev(), QString::fromUtf8(dds_strretcode(writer))));
    msg::Message::Header header = addressed->header;
    header.src = m_config.systemId;
    header.dst = system;
    header.timestamp = m_config.clock->now().toMSecsSinceEpoch() / 1000.0;
    auto sent = write(writer, *addressed, header);
    dds_write_flush(writer);
    return sent;
}

} // namespace neptus::transport
