#include "session/OperationsFeed.h"

#include "geo/Geodesy.h"
#include "log/Recorder.h"
#include "session/Console.h"

#include <cmath>
#include <limits>

using namespace Qt::StringLiterals;

namespace neptus::session {

namespace {

QString enumOf(const msg::Message &m, const QString &field)
{
    const int index = m.def()->fieldIndex.value(field, -1);
    return index < 0 ? QString() : m.enumText(index);
}

} // namespace

OperationsFeed::OperationsFeed(Console &console, db::Writer *writer, const Clock *clock, QObject *parent)
    : QObject(parent)
    , m_console(console)
    , m_writer(writer)
    , m_clock(clock)
{
    connect(&m_timer, &QTimer::timeout, this, [this] {
        noteLog();
        checkAlarms();
        QMutexLocker lock(&m_mutex);
        if (m_runs.waiting())
            planEvents(m_runs.poll(m_clock->now().toMSecsSinceEpoch()));
    });
    m_timer.start(250);
    m_console.setFeed(this);
    if (!writer)
        return;
    alarms::AlarmGraph &graph = console.alarmGraph();
    const auto node = graph.ensure(u"database"_s);
    const auto said = [&graph, node](const db::Status &status) {
        if (status.problem.isEmpty())
            graph.raise(node, alarms::Normal, status.connected ? u"writing"_s : QString());
        else
            graph.raise(node, alarms::Warning, status.spooled > 0 || !status.connected
                                                   ? u"%1 (%2 rows kept on disk until it answers)"_s.arg(status.problem).arg(status.spooled)
                                                   : status.problem);
    };
    writer->setProblemHandler(said);
    said(writer->status());
}

void OperationsFeed::put(db::Row row)
{
    if (m_writer)
        m_writer->write(std::move(row));
}

std::vector<OperationsFeed::LiveSystem> OperationsFeed::live(bool withTracks) const
{
    QMutexLocker lock(&m_mutex);
    std::vector<LiveSystem> systems;
    for (auto it = m_systems.cbegin(); it != m_systems.cend(); ++it) {
        LiveSystem s = it->live; // its `recent` stays empty: the track is kept beside it
        if (withTracks)
            s.recent = it->recent;
        s.id = it.key();
        s.name = nameOf(it.key());
        s.kind = it->kind;
        s.lastMs = it->lastMs;
        systems.push_back(std::move(s));
    }
    std::sort(systems.begin(), systems.end(), [](const auto &a, const auto &b) { return a.name < b.name; });
    return systems;
}

OperationsFeed::~OperationsFeed()
{
    m_console.setFeed(nullptr);
    if (!m_writer)
        return;
    m_writer->setProblemHandler({});
    planEvents(m_runs.poll(std::numeric_limits<qint64>::max())); // ends still waiting for their words
    checkAlarms();
    m_logWrittenMs = 0; // the log's final span, now
    noteLog();
}

void OperationsFeed::setRecorder(const log::Recorder *recorder)
{
    m_recorder = recorder;
}

QString OperationsFeed::nameOf(quint16 id) const
{
    const auto it = m_systems.constFind(id);
    return it != m_systems.cend() && !it->name.isEmpty() ? it->name : u"0x%1"_s.arg(id, 4, 16, QLatin1Char('0'));
}

void OperationsFeed::noteSystem(quint16 id, qint64 now)
{
    SystemState &s = m_systems[id];
    if (s.firstMs == 0)
        s.firstMs = now;
    s.lastMs = now;
    if (!s.name.isEmpty() && now - s.writtenMs >= 5000) {
        s.writtenMs = now;
        put(db::Row{db::Table::System, {int(id), s.name, s.kind, s.firstMs, now}});
    }
}

void OperationsFeed::observe(const msg::Message &m, bool sent)
{
    const msg::MessageDef *def = m.def();
    if (!def)
        return;
    const qint64 now = m_clock->now().toMSecsSinceEpoch();
    QMutexLocker lock(&m_mutex);
    const quint16 source = m.header.src;
    if (!sent && def->abbrev == u"Announce") {
        SystemState &s = m_systems[source];
        const QString name = m.text(u"sys_name"), kind = enumOf(m, u"sys_type"_s);
        if (s.name != name || s.kind != kind)
            s.writtenMs = 0; // say it now
        s.name = name;
        s.kind = kind;
    }
    if (!sent)
        noteSystem(source, now);
    if (!sent && def->abbrev == u"EstimatedState") {
        SystemState &s = m_systems[source];
        const geo::Geodetic p = geo::imcPosition(m.number(u"lat"), m.number(u"lon"), m.number(u"height"), m.number(u"x"),
                                                 m.number(u"y"), m.number(u"z"));
        const double heading = std::fmod(geo::degrees(m.number(u"psi")) + 360.0, 360.0);
        const db::TrackPoint point{now, geo::degrees(p.lat), geo::degrees(p.lon), m.number(u"depth"), m.number(u"alt"), heading,
                                   std::hypot(m.number(u"vx"), m.number(u"vy"))};
        s.live.hasPosition = true;
        s.live.position = point;
        if (s.recent.empty() || now - s.recent.back().ms >= 1000) {
            s.recent.push_back(point);
            if (s.recent.size() > 600)
                s.recent.erase(s.recent.begin(), s.recent.begin() + 60);
        }
        if (now - s.positionMs < m_positionIntervalMs)
            return;
        s.positionMs = now;
        put(db::Row{db::Table::Position, {now, nameOf(source), int(source), point.lat, point.lon, point.depth, point.altitude,
                                          point.heading, point.speed}});
    } else if (!sent && def->abbrev == u"PlanControlState") {
        LiveSystem &live = m_systems[source].live;
        live.planState = enumOf(m, u"state"_s);
        live.plan = m.text(u"plan_id");
        live.maneuver = m.text(u"man_id");
        live.progress = m.number(u"plan_progress");
        planEvents(m_runs.observe(m, now), live.progress);
    } else if (def->abbrev == u"PlanControl") {
        planControl(m, sent, now);
        if (!sent)
            planEvents(m_runs.observe(m, now));
    } else if (!sent && def->abbrev == u"LogBookEntry") {
        put(db::Row{db::Table::LogBook, {now, nameOf(source), enumOf(m, u"type"_s), m.text(u"context"), m.text(u"text")}});
    }
}

void OperationsFeed::relabelRun(quint16 system, const QString &plan)
{
    QMutexLocker lock(&m_mutex);
    m_runs.relabel(system, plan);
}

void OperationsFeed::stopAccepted(quint16 system)
{
    QMutexLocker lock(&m_mutex);
    planEvents(m_runs.stopAnswered(system));
}

void OperationsFeed::planEvents(const std::vector<plans::PlanRuns::Event> &events, double progress)
{
    using Kind = plans::PlanRuns::Event::Kind;
    for (const plans::PlanRuns::Event &e : events) {
        QString what, detail;
        switch (e.kind) {
        case Kind::Started:
            what = u"started"_s;
            detail = e.joined ? u"running when first heard"_s : QString();
            break;
        case Kind::Maneuver:
            what = u"maneuver"_s;
            detail = u"%1 %"_s.arg(progress, 0, 'f', 0);
            break;
        case Kind::Ended:
            what = plans::PlanRuns::outcomeName(e.outcome);
            detail = e.reason;
            break;
        }
        put(db::Row{db::Table::PlanEvent, {e.ms, nameOf(e.system), e.plan, what, e.maneuver, detail}});
    }
}

void OperationsFeed::planControl(const msg::Message &m, bool sent, qint64 now)
{
    const QString op = enumOf(m, u"op"_s).toLower(), type = enumOf(m, u"type"_s).toLower();
    if (sent) { // a request of this console's
        if (type != u"request"_s)
            return;
        put(db::Row{db::Table::PlanEvent, {now, nameOf(m.header.dst), m.text(u"plan_id"),
                                                      op == u"start"_s ? u"sent"_s : op + u" requested"_s, QString(), m.text(u"info")}});
    } else if (type == u"success"_s || type == u"failure"_s) { // a vehicle's answer
        put(db::Row{db::Table::PlanEvent, {now, nameOf(m.header.src), m.text(u"plan_id"), op + u' ' + type, QString(),
                                                      m.text(u"info")}});
    }
}

void OperationsFeed::noteLog()
{
    if (!m_recorder)
        return;
    const qint64 now = m_clock->now().toMSecsSinceEpoch();
    const log::Recorder::Status s = m_recorder->status();
    if (!s.folder.isEmpty() && s.folder != m_logFolder) { // a new part: its own span and counts
        m_logFolder = s.folder;
        m_logBeganMs = now;
        m_logPacketsBefore = s.packets;
        m_logBytesBefore = s.bytes;
        m_logWrittenMs = 0;
    }
    if (!m_logFolder.isEmpty() && now - m_logWrittenMs >= 5000) {
        m_logWrittenMs = now;
        put(db::Row{db::Table::Log, {m_logFolder, m_logBeganMs, now, qint64(s.packets - m_logPacketsBefore),
                                     qint64(s.bytes - m_logBytesBefore)}});
    }
}

void OperationsFeed::checkAlarms()
{
    alarms::AlarmGraph &graph = m_console.alarmGraph();
    const qint64 now = m_clock->now().toMSecsSinceEpoch();
    const quint64 version = graph.version();
    if (version == m_alarmVersion)
        return;
    m_alarmVersion = version;
    QHash<QString, AlarmState> current;
    for (const alarms::AlarmGraph::Alarm &a : graph.activeAlarms()) {
        if (a.origin == u"database"_s) // its own state is the writer's status, not a record
            continue;
        current.insert(a.origin, {a.level, a.message, a.acknowledged});
        const auto before = m_alarms.constFind(a.origin);
        if (before == m_alarms.cend() || before->level != a.level || before->message != a.message)
            put(db::Row{db::Table::Alarm, {now, a.origin, alarms::levelName(a.level),
                                                      a.level == alarms::Info ? u"notice"_s : u"raised"_s, a.message}});
        if (a.acknowledged && (before == m_alarms.cend() || !before->acknowledged))
            put(db::Row{db::Table::Alarm, {now, a.origin, alarms::levelName(a.level), u"acknowledged"_s, a.message}});
    }
    for (auto it = m_alarms.cbegin(); it != m_alarms.cend(); ++it)
        if (!current.contains(it.key()))
            put(db::Row{db::Table::Alarm, {now, it.key(), alarms::levelName(graph.ownLevel(graph.find(it.key()))),
                                                      u"cleared"_s, graph.message(graph.find(it.key()))}});
    m_alarms = std::move(current);
}

} // namespace neptus::session
