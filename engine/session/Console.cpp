#include "session/Console.h"
#include "session/OperationsFeed.h"

#include "core/DataFiles.h"

namespace neptus::session {

namespace {

// Decode errors older than this no longer keep a system's link alarm up.
constexpr qint64 decodeErrorAlarmMs = 10000;
// Nor an ignored Announce its sources alarm.
constexpr qint64 ignoredAnnounceAlarmMs = 30000;

} // namespace

Console::Console(std::shared_ptr<const msg::Schema> schema, const Clock *clock, QObject *parent)
    : QObject(parent)
    , m_clock(clock)
    , m_schema(schema)
    , m_schemas(std::make_shared<msg::SchemaSet>(schema))
    , m_tree(clock)
    , m_graph(clock)
    , m_health(m_graph, m_tree, clock)
    , m_naming(m_tree, schema, [this](quint16 system, msg::Message m) { return send(system, std::move(m)); }, clock)
    , m_linkStatistics(clock)
{
    m_checkTimer.setInterval(250);
    connect(&m_checkTimer, &QTimer::timeout, this, &Console::check);
    m_checkTimer.start();
    m_tickTimer.setInterval(1000);
    connect(&m_tickTimer, &QTimer::timeout, this, &Console::tick);
    m_tickTimer.start();
}

Console::~Console()
{
    // The links stop first: nothing may arrive while the rest goes.
    m_dds.reset();
    m_imc.reset();
    m_mavlink.clear();
}

scripting::ScriptHost *Console::scripts()
{
    if (!m_scripts)
        m_scripts = std::make_unique<scripting::ScriptHost>(m_tree, m_graph);
    return m_scripts.get();
}

std::expected<void, QString> Console::setDefinitionsFor(const QString &system, const QString &file)
{
    auto schema = msg::Schema::load({file});
    if (!schema)
        return std::unexpected(QStringLiteral("definitions for %1: %2").arg(system, schema.error().toString()));
    m_schemas->setFor(system, *schema);
    return {};
}

std::expected<void, QString> Console::startImc(transport::ImcUdpConfig config)
{
    config.clock = m_clock;
    auto imc = std::make_unique<transport::ImcUdpTransport>(m_schemas, config);
    // Wired before it starts: a vehicle answers the first Heartbeat at once, and its Announce must not be lost.
    wireImc(*imc);
    if (auto started = imc->start(); !started)
        return started;
    keepImc(std::move(imc));
    return {};
}

transport::ImcUdpTransport *Console::attachImc(std::unique_ptr<transport::ImcUdpTransport> imc)
{
    wireImc(*imc);
    return keepImc(std::move(imc));
}

transport::ImcUdpTransport *Console::keepImc(std::unique_ptr<transport::ImcUdpTransport> imc)
{
    m_imc = std::move(imc);
    addLink(QStringLiteral("IMC/UDP"), m_imc.get());
    return m_imc.get();
}

void Console::wireImc(transport::ImcUdpTransport &transport)
{
    auto *imc = &transport;
    const QString link = QStringLiteral("IMC/UDP");
    imc->setPacketTap([this](QByteArrayView packet) { tap(packet); });
    // Straight into the session from the link's decoding thread, as from DDS's: the GUI thread
    // being busy delays nothing and loses nothing (the tree, alarms and statistics are thread-safe).
    connect(imc, &transport::ImcUdpTransport::received, this,
            [this, link](const msg::Message &m, qsizetype bytes) { ingest(m, link, bytes); }, Qt::DirectConnection);
    connect(imc, &transport::ImcUdpTransport::decodeFailed, this,
            [this, link](quint16 system, const QString &peer, const QString &reason) {
                decodeFailed(system, link, peer, reason);
            });
    connect(imc, &transport::ImcUdpTransport::versionAnnounced, this,
            [this](quint16 system, const QString &version) {
                m_announcedVersions.insert(system, version);
                updateDefinitionsAlarm(system, m_linkStatistics.system(system));
            });
    connect(imc, &transport::ImcUdpTransport::sourcesChanged, this, &Console::sourcesChanged);
    connect(imc, &transport::ImcUdpTransport::announceIgnored, this,
            [this](quint16 system, const QString &from, const QString &services) {
                Sources &sources = m_sources[system];
                sources.ignoredAnnounce = tr("an Announce from %1 names addresses on other hosts only (%2): "
                                             "commands do not go there")
                                              .arg(from, services.left(200));
                sources.ignoredMs = m_clock->now().toMSecsSinceEpoch();
                updateSourcesAlarm(system);
            });
    connect(imc, &transport::ImcUdpTransport::overloaded, this,
            [this, maximum = imc->maxDatagramsPerSecond()](const QString &host, int overRate, int behind) {
                overloaded(host, overRate, behind, maximum);
            });
}

// Said as it is: a host that sends too much, or this console falling behind (not the vehicle's doing).
void Console::overloaded(const QString &host, int overRate, int behind, int maximum)
{
    const auto node = m_graph.ensure(QStringLiteral("links/%1").arg(host));
    QStringList why;
    if (overRate > 0)
        why << tr("input overload: %1 sent over %2 datagrams a second; %3 dropped unread").arg(host).arg(maximum).arg(overRate);
    if (behind > 0)
        why << tr("this console fell behind what %1 sends: %2 datagrams dropped unread").arg(host).arg(behind);
    m_graph.raise(node, why.isEmpty() ? alarms::Normal : alarms::Warning, why.join(QStringLiteral("; ")));
}

std::shared_ptr<const msg::Schema> Console::mavlinkSchema()
{
    if (!m_mavlinkSchema) {
        const QString file = m_mavlinkDialect.isEmpty() ? dataPath(QStringLiteral("msgdefs/mavlink")) + QStringLiteral("/ardupilotmega.xml")
                                                        : m_mavlinkDialect;
        if (auto loaded = msg::Schema::load({file}); loaded && (*loaded)->protocol() == msg::Schema::Protocol::Mavlink)
            m_mavlinkSchema = *loaded;
    }
    return m_mavlinkSchema;
}

std::expected<void, QString> Console::setMavlinkDialect(const QString &file)
{
    auto loaded = msg::Schema::load({file});
    if (!loaded)
        return std::unexpected(tr("MAVLink dialect: %1").arg(loaded.error().toString()));
    if ((*loaded)->protocol() != msg::Schema::Protocol::Mavlink)
        return std::unexpected(tr("MAVLink dialect: %1 is not a MAVLink definition (<mavlink>)").arg(file));
    m_mavlinkDialect = file;
    m_mavlinkSchema = *loaded;
    return {};
}

std::expected<void, QString> Console::startMavlink(transport::MavlinkConfig config)
{
    const auto schema = mavlinkSchema();
    if (!schema)
        return std::unexpected(tr("%1: the MAVLink dialects in %2 do not load").arg(config.linkName(), dataPath(QStringLiteral("msgdefs/mavlink"))));
    config.clock = m_clock;
    config.idBase = quint16(0xEA00 + 0x100 * m_mavlink.size());
    auto link = std::make_unique<transport::MavlinkTransport>(schema, m_schema, config);
    wireMavlink(*link); // before it starts, as IMC's
    if (auto started = link->start(); !started)
        return started;
    keepMavlink(std::move(link));
    return {};
}

transport::MavlinkTransport *Console::attachMavlink(std::unique_ptr<transport::MavlinkTransport> link)
{
    wireMavlink(*link);
    return keepMavlink(std::move(link));
}

transport::MavlinkTransport *Console::keepMavlink(std::unique_ptr<transport::MavlinkTransport> link)
{
    const QString name = link->linkName();
    m_mavlink.push_back(std::move(link));
    addLink(name, m_mavlink.back().get());
    return m_mavlink.back().get();
}

void Console::wireMavlink(transport::MavlinkTransport &transport)
{
    auto *link = &transport;
    const QString name = link->linkName();
    link->setPacketTap([this](QByteArrayView packet) { tap(packet); }); // what it means, in Data.lsf
    link->setFrameTap([this](QByteArrayView frame) { // what was said, in mavlink.tlog
        if (log::Recorder *recorder = m_recorder.load(std::memory_order_relaxed))
            recorder->recordMavlink(frame);
    });
    // Straight into the session from the link's reading thread, as IMC's.
    connect(link, &transport::MavlinkTransport::received, this,
            [this, name](const msg::Message &m, qsizetype bytes) { ingest(m, name, bytes); }, Qt::DirectConnection);
    connect(link, &transport::MavlinkTransport::derived, this,
            [this](const msg::Message &m) { ingestDerived(m); }, Qt::DirectConnection);
    connect(link, &transport::MavlinkTransport::decodeFailed, this,
            [this, name](quint16 system, const QString &peer, const QString &reason) { decodeFailed(system, name, peer, reason); });
    connect(link, &transport::MavlinkTransport::sourcesChanged, this, &Console::sourcesChanged);
    connect(link, &transport::MavlinkTransport::refused, this,
            [this](quint16 system, const QString &peer, const QString &reason) {
                Sources &sources = m_sources[system];
                sources.ignoredAnnounce = tr("frames from %1 refused: %2").arg(peer, reason);
                sources.ignoredMs = m_clock->now().toMSecsSinceEpoch();
                updateSourcesAlarm(system);
            });
    connect(link, &transport::MavlinkTransport::statusText, this, &Console::statusText);
    connect(link, &transport::MavlinkTransport::overloaded, this,
            [this, maximum = link->maxDatagramsPerSecond()](const QString &host, int overRate, int behind) {
                overloaded(host, overRate, behind, maximum);
            });
}

void Console::labelMission(quint16 system, const QString &planId, const QStringList &maneuverOfItem)
{
    for (const auto &link : m_mavlink)
        link->setMission(system, planId, maneuverOfItem);
}

QString Console::mavlinkStopMode(quint16 system) const
{
    for (const auto &link : m_mavlink)
        if (const QString mode = link->stopMode(system); !mode.isEmpty())
            return mode;
    return {};
}

void Console::statusText(quint16 system, int severity, const QString &text)
{
    // MAV_SEVERITY: EMERGENCY 0, ALERT 1, CRITICAL 2 ("Arm: …", "PreArm: …"), ERROR 3, WARNING 4; NOTICE and below are only logged.
    if (severity > 4)
        return;
    const alarms::Level level = severity <= 1 ? alarms::Error : alarms::Warning;
    const auto node = m_graph.ensure(QStringLiteral("systems/%1/statustext").arg(m_tree.systemName(system)));
    m_graph.raise(node, level, text);
    m_statusTexts.insert(system, Said{level, m_clock->now().toMSecsSinceEpoch()});
}

std::expected<void, QString> Console::startDds(transport::DdsConfig config)
{
    config.clock = m_clock;
    auto dds = std::make_unique<transport::DdsTransport>(m_schemas, config);
    const QString link = QStringLiteral("DDS");
    // Straight into the session from Cyclone's threads: the tree, alarms and statistics are thread-safe.
    dds->setDirectReceiver([this, link](const msg::Message &m, qsizetype bytes) { ingest(m, link, bytes); });
    dds->setPacketTap([this](QByteArrayView packet) { tap(packet); });
    if (auto started = dds->start(); !started)
        return started;
    connect(dds.get(), &transport::DdsTransport::decodeFailed, this,
            [this, link](quint16 system, const QString &peer, const QString &reason) {
                decodeFailed(system, link, peer, reason);
            });
    connect(dds.get(), &transport::DdsTransport::definitionsDiffer, this,
            [this](quint16 system, const QString &, const QString &theirs, const QString &ours) {
                definitionsDiffer(system, theirs, ours);
            });
    connect(dds.get(), &transport::DdsTransport::sourcesChanged, this, &Console::sourcesChanged);
    connect(dds.get(), &transport::DdsTransport::ourIdInUse, this, [this, id = config.systemId](const QString &participant) {
        m_graph.raise(m_graph.ensure(QStringLiteral("links/DDS")), alarms::Warning,
                      tr("another console, %1, uses this console's system id 0x%2 on DDS: what it sends is ignored; "
                         "give one of them another id (--system-id)")
                          .arg(participant, QStringLiteral("%1").arg(id, 4, 16, QLatin1Char('0'))));
    });
    connect(dds.get(), &transport::DdsTransport::participantJoined, this, [this, id = config.systemId](quint16 system) {
        if (system != id)
            emit participantJoined(system);
    });
    connect(dds.get(), &transport::DdsTransport::participantLeft, this, [this, id = config.systemId](quint16 system) {
        if (system == id)
            m_graph.clear(m_graph.ensure(QStringLiteral("links/DDS"))); // the other console with our id left
        else
            emit participantLeft(system);
    });
    m_dds = std::move(dds);
    addLink(link, m_dds.get());
    return {};
}

void Console::setRecorder(log::Recorder *recorder)
{
    disconnect(m_recorderProblems);
    m_recorder = recorder;
    if (!recorder)
        return;
    const auto node = m_graph.ensure(QStringLiteral("recording"));
    const auto said = [this, node](const QString &problem) {
        m_graph.raise(node, problem.isEmpty() ? alarms::Normal : alarms::Warning, problem);
    };
    m_recorderProblems = connect(recorder, &log::Recorder::problemChanged, this, said);
    said(recorder->status().problem);
}

void Console::tap(QByteArrayView packet)
{
    if (log::Recorder *recorder = m_recorder.load(std::memory_order_relaxed))
        recorder->record(packet);
}

std::expected<void, QString> Console::send(quint16 system, msg::Message message)
{
    if (m_replaying)
        return std::unexpected(tr("this console replays a log: nothing is sent to vehicles"));
    if (auto sent = m_router.publish(system, message); !sent)
        return sent;
    if (OperationsFeed *feed = m_feed.load(std::memory_order_relaxed)) {
        msg::Message addressed = message;
        addressed.header.dst = system;
        feed->observe(addressed, true);
    }
    m_tree.recordSent(system, std::move(message));
    return {};
}

std::expected<void, QString> Console::send(const QString &system, msg::Message message)
{
    const auto id = m_tree.systemId(system);
    if (!id)
        return std::unexpected(tr("no system is called '%1'").arg(system));
    return send(*id, std::move(message));
}

void Console::addLink(const QString &name, transport::OutputSink *sink)
{
    m_router.addLink(name, sink);
}

void Console::definitionsDiffer(quint16 system, const QString &theirDigest, const QString &ourDigest)
{
    m_digestNotes.insert(system, tr("speaks other message definitions (digest %1, ours %2): its values may be misread")
                                     .arg(theirDigest.left(8), ourDigest.left(8)));
    updateDefinitionsAlarm(system, m_linkStatistics.system(system));
}

void Console::ingest(const msg::Message &message, const QString &link, qsizetype bytes)
{
    const quint16 source = message.header.src;
    if (!link.isEmpty())
        heardOn(source, link);
    take(message);
    m_linkStatistics.received(source, link, message.id(), message.abbrev(), !message.isOpaque(), bytes, message.isMavlink());
}

void Console::ingestDerived(const msg::Message &message)
{
    take(message);
}

namespace {

// What the plan desk follows: IMC's plan database and control, and a MAVLink
// vehicle's mission protocol, command answers, words and heartbeat.
bool forPlans(const msg::MessageDef &def)
{
    if (def.mavlink)
        return def.abbrev.startsWith(u"MISSION_") || def.abbrev == u"COMMAND_ACK" || def.abbrev == u"STATUSTEXT"
               || def.abbrev == u"HEARTBEAT";
    return def.abbrev == u"PlanDB" || def.abbrev == u"PlanControl" || def.abbrev == u"PlanControlState";
}

} // namespace

void Console::take(const msg::Message &message)
{
    const quint16 source = message.header.src;
    const msg::MessageDef *def = message.def();
    if (def && !def->mavlink && def->id == 151 && def->abbrev == u"Announce")
        m_schemas->learnName(source, message.text(u"sys_name"));
    m_tree.ingest(message);
    if (OperationsFeed *feed = m_feed.load(std::memory_order_relaxed))
        feed->observe(message, false);
    m_health.observe(message);
    m_naming.observe(message);
    if (def && forPlans(*def))
        emit planMessageReceived(message);
    else if (def && !def->mavlink && def->abbrev == u"MissionChange")
        emit sharedMissionReceived(message);
}

std::expected<void, QString> Console::broadcast(const msg::Message &message)
{
    if (m_replaying)
        return std::unexpected(tr("this console replays a log: nothing is sent"));
    if (!m_dds)
        return std::unexpected(QStringLiteral("no DDS link (consoles share missions over DDS)"));
    return m_dds->publish(0xFFFF, message);
}

void Console::heardOn(quint16 system, const QString &link)
{
    if (m_router.linkOf(system) == link)
        return;
    m_router.heard(system, link);
    m_tree.setSystemLink(system, link);
}

void Console::decodeFailed(quint16 system, const QString &link, const QString &peer, const QString &reason)
{
    m_linkStatistics.decodeFailed(system, link, peer, reason);
}

bool Console::chooseSource(quint16 system, const QString &host)
{
    const bool imc = m_imc && m_imc->pick(system, host);
    const bool dds = m_dds && m_dds->pick(system, host);
    return imc || dds;
}

void Console::sourcesChanged(quint16 system, const QStringList &senders, const QString &destination)
{
    Sources &sources = m_sources[system];
    sources.hosts = senders;
    sources.destination = destination;
    m_linkStatistics.setSources(system, senders, destination);
    updateSourcesAlarm(system);
}

void Console::updateSourcesAlarm(quint16 id)
{
    Sources &sources = m_sources[id];
    const qint64 now = m_clock->now().toMSecsSinceEpoch();
    QString text;
    if (sources.hosts.size() > 1 && sources.destination.isEmpty())
        text = tr("%1 sources send as this system (%2): commands to it are held until one is chosen in Links")
                   .arg(sources.hosts.size())
                   .arg(sources.hosts.join(QStringLiteral(", ")));
    else if (sources.hosts.size() > 1)
        text = tr("%1 sources send as this system (%2); commands go to %3, as chosen")
                   .arg(sources.hosts.size())
                   .arg(sources.hosts.join(QStringLiteral(", ")), sources.destination);
    else if (!sources.ignoredAnnounce.isEmpty() && now - sources.ignoredMs < ignoredAnnounceAlarmMs)
        text = sources.ignoredAnnounce;
    if (text == sources.alarmText)
        return;
    sources.alarmText = text;
    const auto node = m_graph.ensure(QStringLiteral("systems/%1/sources").arg(m_tree.systemName(id)));
    m_graph.raise(node, text.isEmpty() ? alarms::Normal : alarms::Warning, text);
}

void Console::check()
{
    for (const quint16 system : m_health.check())
        forget(system);
    m_naming.check();
}

void Console::forget(quint16 system)
{
    m_health.forget(system); // its alarm node, and everything under it (link, sources, entities), to Unknown
    m_tree.forget(system);
    m_naming.forget(system);
    m_linkStatistics.forget(system);
    m_router.forget(system);
    m_linkAlarmText.remove(system);
    m_definitionsAlarmText.remove(system);
    m_announcedVersions.remove(system);
    m_digestNotes.remove(system);
    m_sources.remove(system);
    m_statusTexts.remove(system);
}

void Console::tick()
{
    m_linkStatistics.tick();
    const qint64 now = m_clock->now().toMSecsSinceEpoch();
    for (auto it = m_statusTexts.begin(); it != m_statusTexts.end();) {
        if (now - it->ms < 60000) {
            ++it;
            continue;
        }
        m_graph.clear(m_graph.ensure(QStringLiteral("systems/%1/statustext").arg(m_tree.systemName(it.key()))));
        it = m_statusTexts.erase(it);
    }
    updateLinkAlarms();
    for (const quint16 system : m_sources.keys()) {
        if (!m_sources.value(system).alarmText.isEmpty())
            updateSourcesAlarm(system); // an ignored Announce ages out
    }
}

void Console::updateLinkAlarms()
{
    const qint64 now = m_tree.clock().now().toMSecsSinceEpoch();
    for (const transport::LinkStatistics::System &system : m_linkStatistics.systems()) {
        const bool known = system.id != transport::LinkStatistics::unknownSystem;
        const QString name = known ? m_tree.systemName(system.id) : QString();

        // Packets that did not decode, while they keep coming.
        QString link;
        if (system.decodeErrors > 0 && now - system.lastErrorMs < decodeErrorAlarmMs)
            link = tr("%n packet(s) could not be decoded; the last, from %1: %2", nullptr,
                      static_cast<int>(std::min<quint64>(system.decodeErrors, INT_MAX)))
                       .arg(system.peer, system.lastError);
        if (link != m_linkAlarmText.value(system.id)) {
            m_linkAlarmText.insert(system.id, link);
            const auto node = m_graph.ensure(known ? QStringLiteral("systems/%1/link").arg(name)
                                                   : QStringLiteral("links/unknown senders"));
            m_graph.raise(node, link.isEmpty() ? alarms::Normal : alarms::Warning, link);
        }
        if (!known)
            continue;

        updateDefinitionsAlarm(system.id, system);
    }
}

void Console::updateDefinitionsAlarm(quint16 id, const transport::LinkStatistics::System &system)
{
    // Definitions that may not be the vehicle's: another digest or IMC version, types we lack.
    QStringList notes;
    if (m_digestNotes.contains(id))
        notes << m_digestNotes.value(id);
    const QString version = m_announcedVersions.value(id);
    if (!version.isEmpty() && version != m_schema->version() && !m_schemas->hasOwn(id))
        notes << tr("announces IMC %1, ours is %2").arg(version, m_schema->version());
    QStringList unknown;
    for (const auto &type : system.types) {
        if (!type.known)
            unknown << QString::number(type.id);
    }
    if (!unknown.isEmpty())
        notes << tr("sends %n message type(s) our definitions lack (id %1)", nullptr, static_cast<int>(unknown.size()))
                     .arg(unknown.join(QStringLiteral(", ")));
    QString text;
    if (!notes.isEmpty())
        text = notes.join(QStringLiteral("; ")) + tr(" (decode it with --defs-for %1 FILE)").arg(msg::systemLabel(id));
    if (text == m_definitionsAlarmText.value(id))
        return;
    m_definitionsAlarmText.insert(id, text);
    const auto node = m_graph.ensure(QStringLiteral("systems/%1/definitions").arg(m_tree.systemName(id)));
    m_graph.raise(node, text.isEmpty() ? alarms::Normal : alarms::Warning, text);
}

QString Console::dumpTree() const
{
    QString out;
    std::vector<tree::NodeId> stack{m_tree.root()};
    while (!stack.empty()) {
        const tree::NodeId node = stack.back();
        stack.pop_back();
        if (node != m_tree.root()) {
            const auto snapshot = m_tree.snapshot(node);
            out += m_tree.path(node) + u'\t' + snapshot.text + u'\t' + snapshot.unit + u'\n';
        }
        for (int row = m_tree.childCount(node) - 1; row >= 0; --row)
            stack.push_back(m_tree.child(node, row));
    }
    return out;
}

} // namespace neptus::session
