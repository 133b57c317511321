#include "log/LogExport.h"

#include "geo/Geodesy.h"
#include "messages/MessageJson.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <QTimeZone>
#include <QXmlStreamWriter>

#include <algorithm>
#include <cmath>
#include <map>

namespace neptus::log {

namespace {

// Calls `progress` about a hundred times over `count` steps.
class Ticker
{
public:
    Ticker(const Progress &progress, qsizetype count)
        : m_progress(progress)
        , m_every(std::max<qsizetype>(1, count / 100))
        , m_count(std::max<qsizetype>(1, count))
    {
    }
    // False when the caller asked to stop.
    bool at(qsizetype step)
    {
        if (!m_progress || step % m_every != 0)
            return true;
        return m_progress(double(step) / double(m_count));
    }
    bool done() { return !m_progress || m_progress(1.0); }

private:
    const Progress &m_progress;
    qsizetype m_every, m_count;
};

QString isoTime(double t)
{
    return QDateTime::fromMSecsSinceEpoch(qint64(std::llround(t * 1000)), QTimeZone::UTC).toString(Qt::ISODateWithMs);
}

QString csvText(QString text)
{
    if (text.contains(u',') || text.contains(u'"') || text.contains(u'\n') || text.contains(u'\r')) {
        text.replace(QStringLiteral("\""), QStringLiteral("\"\""));
        return u'"' + text + u'"';
    }
    return text;
}

QString csvValue(const msg::Message &m, int i)
{
    const msg::FieldDef &field = m.field(i);
    switch (field.type) {
    case msg::FieldType::PlainText:
        return csvText(m.text(i));
    case msg::FieldType::RawData:
        return QString::fromLatin1(m.bytes(i).toHex());
    case msg::FieldType::Message: {
        const msg::Message *inner = m.inlineMessage(i);
        return inner ? csvText(QString::fromUtf8(QJsonDocument(msg::toJson(*inner)).toJson(QJsonDocument::Compact)))
                     : QString();
    }
    case msg::FieldType::MessageList: {
        QJsonArray list;
        for (const msg::Message &inner : m.messages(i))
            list.append(msg::toJson(inner));
        return csvText(QString::fromUtf8(QJsonDocument(list).toJson(QJsonDocument::Compact)));
    }
    case msg::FieldType::Fp32:
    case msg::FieldType::Fp64:
        return QString::number(m.number(i), 'g', 17);
    default:
        return QString::number(m.integer(i));
    }
}

std::expected<std::map<quint16, std::vector<TrackPoint>>, QString> tracksOf(const LogSet &logs, const Progress &progress)
{
    std::map<quint16, std::vector<TrackPoint>> byId;
    Ticker ticker(progress, logs.count());
    for (qsizetype k = 0; k < logs.count(); ++k) {
        if (!ticker.at(k))
            return std::unexpected(QStringLiteral("stopped"));
        const LogFile &log = logs.logOf(k);
        const qsizetype i = logs.indexInLog(k);
        const msg::MessageDef *def = log.schemas().codecFor(log.source(i))->schema().byId(log.messageId(i));
        if (!def || def->abbrev != u"EstimatedState")
            continue;
        const auto m = logs.decode(k);
        if (!m)
            continue;
        const geo::Geodetic p = geo::imcPosition(m->number(u"lat"), m->number(u"lon"), m->number(u"height"),
                                                 m->number(u"x"), m->number(u"y"), m->number(u"z"));
        const double lat = p.lat * 180 / M_PI, lon = p.lon * 180 / M_PI;
        if (!std::isfinite(lat) || !std::isfinite(lon) || (lat == 0 && lon == 0))
            continue; // no position yet
        byId[m->header.src].push_back({m->header.timestamp, lat, lon, m->number(u"depth"), m->number(u"alt")});
    }
    return byId;
}

} // namespace

std::map<quint16, std::vector<TrackPoint>> tracks(const LogSet &logs)
{
    return *tracksOf(logs, {});
}

std::vector<plans::PlanRuns::Event> planEvents(const LogSet &logs)
{
    std::vector<plans::PlanRuns::Event> events;
    if (logs.logs().empty())
        return events;
    const msg::Schema &schema = logs.logs().front()->schemas().defaultSchema();
    const msg::MessageDef *state = schema.byAbbrev(u"PlanControlState"), *control = schema.byAbbrev(u"PlanControl");
    if (!state || !control)
        return events;
    const auto ms = [](double t) { return qint64(std::llround(t * 1000)); };
    plans::PlanRuns runs;
    const auto add = [&events](std::vector<plans::PlanRuns::Event> more) {
        std::move(more.begin(), more.end(), std::back_inserter(events));
    };
    for (qsizetype k = 0; k < logs.count(); ++k) {
        const LogFile &log = logs.logOf(k);
        const quint16 id = log.messageId(logs.indexInLog(k));
        if (id != state->id && id != control->id)
            continue;
        if (const auto m = logs.decode(k); m && m->def()) {
            add(runs.poll(ms(logs.time(k))));
            add(runs.observe(*m, ms(logs.time(k))));
        }
    }
    add(runs.finish(ms(logs.end())));
    // An end told after its reason came keeps its own moment.
    std::stable_sort(events.begin(), events.end(), [](const auto &a, const auto &b) { return a.ms < b.ms; });
    return events;
}

std::vector<PlanRun> planRuns(const LogSet &logs, const std::vector<plans::PlanRuns::Event> &plans,
                              const std::map<quint16, std::vector<TrackPoint>> &all)
{
    std::vector<PlanRun> runs;
    QHash<quint16, size_t> open; // system → its run in `runs`
    for (const plans::PlanRuns::Event &e : plans) {
        const double t = e.ms / 1000.0;
        if (e.kind == plans::PlanRuns::Event::Kind::Started) {
            runs.push_back({e.system, logs.systemName(e.system), e.plan, {}, {}, t, t, 0, 0});
            open.insert(e.system, runs.size() - 1);
        } else if (e.kind == plans::PlanRuns::Event::Kind::Ended && open.contains(e.system)) {
            PlanRun &run = runs[open.take(e.system)];
            run.end = t;
            run.outcome = plans::PlanRuns::outcomeName(e.outcome);
            run.reason = e.reason;
        }
    }
    // What the tracks say of each run.
    for (PlanRun &run : runs) {
        const auto track = all.find(run.system);
        if (track == all.end())
            continue;
        const TrackPoint *previous = nullptr;
        for (const TrackPoint &p : track->second) {
            if (p.time < run.begin || p.time > run.end)
                continue;
            run.maxDepth = std::max(run.maxDepth, p.depth);
            if (previous) {
                const Eigen::Vector3d step = geo::toNed({p.lat * M_PI / 180, p.lon * M_PI / 180, 0},
                                                        {previous->lat * M_PI / 180, previous->lon * M_PI / 180, 0});
                run.distance += std::hypot(step.x(), step.y(), p.depth - previous->depth);
            }
            previous = &p;
        }
    }
    return runs;
}

std::expected<std::vector<std::pair<double, double>>, QString> fieldSeries(const LogSet &logs, const QString &path)
{
    const QStringList parts = path.split(u'/');
    if (parts.size() != 3 || parts.contains(QString()))
        return std::unexpected(QStringLiteral("'%1' is not system/Message/field").arg(path));
    if (logs.logs().empty())
        return std::unexpected(QStringLiteral("no logs"));
    std::optional<quint16> system;
    const QHash<quint16, QString> &names = logs.systemNames();
    for (auto it = names.cbegin(); it != names.cend(); ++it) {
        if (it.value() == parts[0])
            system = it.key();
    }
    bool isId = false;
    if (const uint id = parts[0].toUInt(&isId, 0); !system && isId && id < 0xFFFF)
        system = quint16(id);
    if (!system)
        return std::unexpected(QStringLiteral("no system called '%1' in the log").arg(parts[0]));
    const QString message = parts[1].section(u'@', 0, 0);
    const QString entity = parts[1].contains(u'@') ? parts[1].section(u'@', 1) : QString();
    const msg::Schema &schema = logs.logs().front()->schemas().codecFor(*system)->schema();
    const msg::MessageDef *def = schema.byAbbrev(message);
    if (!def)
        return std::unexpected(QStringLiteral("no message '%1' in the log's definitions").arg(message));
    const int field = def->fieldIndex.value(parts[2], -1);
    if (field < 0 || !(msg::isInteger(def->fields[size_t(field)].type) || msg::isFloat(def->fields[size_t(field)].type)))
        return std::unexpected(QStringLiteral("%1 has no number field '%2'").arg(message, parts[2]));
    // An entity by number, or by the label the system gave it (EntityInfo, EntityList).
    std::optional<int> entityId;
    if (!entity.isEmpty()) {
        bool isNumber = false;
        const int n = entity.toInt(&isNumber);
        if (isNumber)
            entityId = n;
        const msg::MessageDef *info = schema.byAbbrev(u"EntityInfo");
        const msg::MessageDef *list = schema.byAbbrev(u"EntityList");
        for (qsizetype k = 0; k < logs.count() && !entityId; ++k) {
            const LogFile &log = logs.logOf(k);
            const qsizetype i = logs.indexInLog(k);
            if (log.source(i) != *system || !((info && log.messageId(i) == info->id) || (list && log.messageId(i) == list->id)))
                continue;
            const auto m = logs.decode(k);
            if (!m)
                continue;
            if (m->def() == info && m->text(u"label") == entity)
                entityId = int(m->integer(u"id"));
            if (m->def() == list) {
                for (const QString &pair : m->text(u"list").split(u';')) {
                    if (pair.section(u'=', 0, 0) == entity)
                        entityId = pair.section(u'=', 1).toInt();
                }
            }
        }
        if (!entityId)
            return std::unexpected(QStringLiteral("%1 has no entity '%2' in the log").arg(parts[0], entity));
    }
    std::vector<std::pair<double, double>> points;
    for (qsizetype k = 0; k < logs.count(); ++k) {
        const LogFile &log = logs.logOf(k);
        const qsizetype i = logs.indexInLog(k);
        if (log.messageId(i) != def->id || log.source(i) != *system || (entityId && log.sourceEntity(i) != *entityId))
            continue;
        if (const auto m = logs.decode(k); m && m->def())
            points.emplace_back(m->header.timestamp, m->number(field));
    }
    return points;
}

std::vector<std::pair<quint16, msg::Message>> planSpecifications(const LogSet &logs)
{
    std::vector<std::pair<quint16, msg::Message>> specifications;
    if (logs.logs().empty())
        return specifications;
    const msg::Schema &schema = logs.logs().front()->schemas().defaultSchema();
    const msg::MessageDef *spec = schema.byAbbrev(u"PlanSpecification");
    const msg::MessageDef *db = schema.byAbbrev(u"PlanDB");
    const msg::MessageDef *control = schema.byAbbrev(u"PlanControl");
    if (!spec)
        return specifications;
    for (qsizetype k = 0; k < logs.count(); ++k) {
        const LogFile &log = logs.logOf(k);
        const qsizetype i = logs.indexInLog(k);
        const quint16 id = log.messageId(i);
        if (id != spec->id && !(db && id == db->id) && !(control && id == control->id))
            continue;
        const auto m = logs.decode(k);
        if (!m || !m->def())
            continue;
        if (m->def() == spec) {
            specifications.emplace_back(m->header.dst != 0xFFFF ? m->header.dst : m->header.src, *m);
            continue;
        }
        // A request (type 0) goes to the vehicle; a reply comes from it.
        const quint16 vehicle = m->integer(u"type") == 0 ? m->header.dst : m->header.src;
        const int arg = m->def()->indexOf(u"arg");
        if (const msg::Message *inner = arg >= 0 ? m->inlineMessage(arg) : nullptr; inner && inner->def() == spec)
            specifications.emplace_back(vehicle, *inner);
    }
    return specifications;
}

std::vector<LogMarker> markersOf(const LogSet &logs, const std::vector<plans::PlanRuns::Event> &plans)
{
    std::vector<LogMarker> markers;
    if (logs.logs().empty())
        return markers;
    const msg::Schema &schema = logs.logs().front()->schemas().defaultSchema();
    const auto idOf = [&](QStringView abbrev) {
        const msg::MessageDef *def = schema.byAbbrev(abbrev);
        return def ? def->id : msg::Schema::noMessage;
    };
    const quint16 logBook = idOf(u"LogBookEntry"), entityState = idOf(u"EntityState");
    QHash<quint32, qint64> entityLevels; // (system, entity) → last state
    for (qsizetype k = 0; k < logs.count(); ++k) {
        const LogFile &log = logs.logOf(k);
        const qsizetype i = logs.indexInLog(k);
        const quint16 id = log.messageId(i);
        if (id != logBook && id != entityState)
            continue;
        const auto m = logs.decode(k);
        if (!m || !m->def())
            continue;
        const QString who = logs.systemName(m->header.src);
        const double t = logs.time(k);
        if (id == logBook) {
            const qint64 type = m->integer(u"type"); // INFO, WARNING, ERROR, CRITICAL, DEBUG
            if (type == 4)
                continue;
            markers.push_back({t, type >= 2 ? LogMarker::Alarm : LogMarker::Note,
                               QStringLiteral("%1 %2: %3").arg(who, m->text(u"context"), m->text(u"text"))});
        } else {
            const quint32 key = (quint32(m->header.src) << 8) | m->header.srcEnt;
            const qint64 state = m->integer(u"state"); // BOOT, NORMAL, FAULT, ERROR, FAILURE
            const qint64 before = entityLevels.value(key, 1);
            entityLevels.insert(key, state);
            if (state >= 2 && state != before)
                markers.push_back({t, LogMarker::Alarm, QStringLiteral("%1 entity %2: %3 %4")
                                                            .arg(who).arg(m->header.srcEnt)
                                                            .arg(m->enumText(m->def()->fieldIndex.value(QStringLiteral("state"))),
                                                                 m->text(u"description"))});
        }
    }
    using Run = plans::PlanRuns;
    for (const Run::Event &e : plans) {
        const QString who = logs.systemName(e.system);
        const double t = e.ms / 1000.0;
        switch (e.kind) {
        case Run::Event::Kind::Started:
            markers.push_back({t, LogMarker::PlanStart, e.joined ? QStringLiteral("%1: plan %2 running as the log begins").arg(who, e.plan)
                                                                 : QStringLiteral("%1: plan %2 started").arg(who, e.plan)});
            break;
        case Run::Event::Kind::Maneuver:
            break;
        case Run::Event::Kind::Ended: {
            QString text = QStringLiteral("%1: plan %2 %3").arg(who, e.plan, Run::outcomeName(e.outcome));
            if (e.outcome == Run::Outcome::Replaced)
                text += QStringLiteral(": %1 started in its place").arg(e.reason);
            else if (e.outcome == Run::Outcome::StillRunning)
                text = QStringLiteral("%1: plan %2 running when the log ends%3")
                           .arg(who, e.plan, e.reason.isEmpty() ? QString() : QStringLiteral(" (last said: %1)").arg(e.reason));
            else if (!e.reason.isEmpty())
                text += QStringLiteral(": ") + e.reason;
            markers.push_back({t, e.outcome == Run::Outcome::Failed ? LogMarker::Alarm : LogMarker::PlanEnd, text});
            break;
        }
        }
    }
    std::stable_sort(markers.begin(), markers.end(), [](const LogMarker &a, const LogMarker &b) { return a.time < b.time; });
    return markers;
}

LogSummary summarize(const LogSet &logs)
{
    LogSummary summary;
    summary.begin = logs.begin();
    summary.end = logs.end();
    summary.packets = logs.count();
    std::map<quint16, qint64> bySystem;
    QHash<QString, qint64> byType;
    for (qsizetype k = 0; k < logs.count(); ++k) {
        const LogFile &log = logs.logOf(k);
        const qsizetype i = logs.indexInLog(k);
        ++bySystem[log.source(i)];
        const msg::MessageDef *def = log.schemas().codecFor(log.source(i))->schema().byId(log.messageId(i));
        ++byType[def ? def->abbrev : QStringLiteral("unknown id %1").arg(log.messageId(i))];
    }
    for (const auto &[id, count] : bySystem)
        summary.systems.append({id, logs.systemName(id), count});
    for (auto it = byType.cbegin(); it != byType.cend(); ++it)
        summary.types.append({it.key(), it.value()});
    std::sort(summary.types.begin(), summary.types.end(),
              [](const auto &a, const auto &b) { return a.second != b.second ? a.second > b.second : a.first < b.first; });
    for (const auto &log : logs.logs()) {
        if (!log->damage().isEmpty())
            summary.damage.append(log->damage());
    }
    return summary;
}

std::expected<QStringList, QString> exportCsv(const LogSet &logs, const QString &folder, const Progress &progress)
{
    if (!QDir().mkpath(folder))
        return std::unexpected(QStringLiteral("%1: cannot make the folder").arg(folder));
    struct Out
    {
        std::unique_ptr<QSaveFile> file;
        QByteArray buffer;
    };
    std::map<QString, Out> files;
    Ticker ticker(progress, logs.count());
    for (qsizetype k = 0; k < logs.count(); ++k) {
        if (!ticker.at(k))
            return std::unexpected(QStringLiteral("stopped"));
        const auto m = logs.decode(k);
        if (!m || !m->def())
            continue;
        auto [it, made] = files.try_emplace(m->def()->abbrev);
        Out &out = it->second;
        if (made) {
            out.file = std::make_unique<QSaveFile>(QDir(folder).filePath(m->def()->abbrev + QStringLiteral(".csv")));
            if (!out.file->open(QIODevice::WriteOnly))
                return std::unexpected(QStringLiteral("%1: %2").arg(out.file->fileName(), out.file->errorString()));
            QStringList header{QStringLiteral("time"), QStringLiteral("system"), QStringLiteral("entity")};
            for (int i = 0; i < m->fieldCount(); ++i)
                header.append(m->field(i).unit.isEmpty() || m->field(i).unit == u"Enumerated" || m->field(i).unit == u"Bitfield"
                                  ? m->field(i).abbrev
                                  : QStringLiteral("%1 (%2)").arg(m->field(i).abbrev, m->field(i).unit));
            out.buffer = header.join(u',').toUtf8() + '\n';
        }
        QString line = QString::number(m->header.timestamp, 'f', 6) + u',' + csvText(logs.systemName(m->header.src)) + u','
                       + QString::number(m->header.srcEnt);
        for (int i = 0; i < m->fieldCount(); ++i)
            line += u',' + csvValue(*m, i);
        out.buffer += line.toUtf8() + '\n';
        if (out.buffer.size() > (1 << 20)) {
            out.file->write(out.buffer);
            out.buffer.clear();
        }
    }
    QStringList written;
    for (auto &[abbrev, out] : files) {
        out.file->write(out.buffer);
        if (!out.file->commit())
            return std::unexpected(QStringLiteral("%1: %2").arg(out.file->fileName(), out.file->errorString()));
        written.append(out.file->fileName());
    }
    ticker.done();
    return written;
}

std::optional<TrackFormat> trackFormat(const QString &name)
{
    if (name == u"kml")
        return TrackFormat::Kml;
    if (name == u"geojson")
        return TrackFormat::GeoJson;
    if (name == u"gpx")
        return TrackFormat::Gpx;
    return std::nullopt;
}

std::expected<void, QString> exportTracks(const LogSet &logs, TrackFormat format, const QString &file,
                                          const Progress &progress)
{
    auto positions = tracksOf(logs, progress);
    if (!positions)
        return std::unexpected(positions.error());
    if (positions->empty())
        return std::unexpected(QStringLiteral("no positions in the log (no EstimatedState with a position)"));
    QSaveFile out(file);
    if (!out.open(QIODevice::WriteOnly))
        return std::unexpected(QStringLiteral("%1: %2").arg(file, out.errorString()));
    const QString title = QFileInfo(logs.logs().front()->folder()).fileName();
    if (format == TrackFormat::GeoJson) {
        // RFC 7946: one LineString per system, [lon, lat, -depth]; the times alongside.
        QJsonArray features;
        for (const auto &[id, points] : *positions) {
            QJsonArray coordinates, times;
            for (const TrackPoint &p : points) {
                coordinates.append(QJsonArray{p.lon, p.lat, -p.depth});
                times.append(isoTime(p.time));
            }
            features.append(QJsonObject{
                {QStringLiteral("type"), QStringLiteral("Feature")},
                {QStringLiteral("geometry"), QJsonObject{{QStringLiteral("type"), QStringLiteral("LineString")},
                                                         {QStringLiteral("coordinates"), coordinates}}},
                {QStringLiteral("properties"), QJsonObject{{QStringLiteral("system"), logs.systemName(id)},
                                                           {QStringLiteral("imc_id"), int(id)},
                                                           {QStringLiteral("times"), times}}},
            });
        }
        out.write(QJsonDocument(QJsonObject{{QStringLiteral("type"), QStringLiteral("FeatureCollection")},
                                            {QStringLiteral("features"), features}})
                      .toJson(QJsonDocument::Compact));
    } else {
        QXmlStreamWriter xml(&out);
        xml.setAutoFormatting(true);
        xml.writeStartDocument();
        if (format == TrackFormat::Kml) {
            // KML 2.2 (OGC): a Placemark per system with its path and time span.
            xml.writeDefaultNamespace(QStringLiteral("http://www.opengis.net/kml/2.2"));
            xml.writeStartElement(QStringLiteral("kml"));
            xml.writeStartElement(QStringLiteral("Document"));
            xml.writeTextElement(QStringLiteral("name"), title);
            for (const auto &[id, points] : *positions) {
                xml.writeStartElement(QStringLiteral("Placemark"));
                xml.writeTextElement(QStringLiteral("name"), logs.systemName(id));
                xml.writeStartElement(QStringLiteral("TimeSpan"));
                xml.writeTextElement(QStringLiteral("begin"), isoTime(points.front().time));
                xml.writeTextElement(QStringLiteral("end"), isoTime(points.back().time));
                xml.writeEndElement();
                xml.writeStartElement(QStringLiteral("LineString"));
                xml.writeTextElement(QStringLiteral("tessellate"), QStringLiteral("1"));
                QString coordinates;
                for (const TrackPoint &p : points)
                    coordinates += QStringLiteral("%1,%2,%3 ").arg(p.lon, 0, 'f', 8).arg(p.lat, 0, 'f', 8).arg(-p.depth, 0, 'f', 2);
                xml.writeTextElement(QStringLiteral("coordinates"), coordinates.trimmed());
                xml.writeEndElement();
                xml.writeEndElement();
            }
            xml.writeEndElement();
            xml.writeEndElement();
        } else {
            // GPX 1.1: a track per system; elevation is minus the depth.
            xml.writeDefaultNamespace(QStringLiteral("http://www.topografix.com/GPX/1/1"));
            xml.writeStartElement(QStringLiteral("gpx"));
            xml.writeAttribute(QStringLiteral("version"), QStringLiteral("1.1"));
            xml.writeAttribute(QStringLiteral("creator"), QStringLiteral("Neptus-Qt neptus-log"));
            xml.writeStartElement(QStringLiteral("metadata"));
            xml.writeTextElement(QStringLiteral("name"), title);
            xml.writeTextElement(QStringLiteral("time"), isoTime(logs.begin()));
            xml.writeEndElement();
            for (const auto &[id, points] : *positions) {
                xml.writeStartElement(QStringLiteral("trk"));
                xml.writeTextElement(QStringLiteral("name"), logs.systemName(id));
                xml.writeStartElement(QStringLiteral("trkseg"));
                for (const TrackPoint &p : points) {
                    xml.writeStartElement(QStringLiteral("trkpt"));
                    xml.writeAttribute(QStringLiteral("lat"), QString::number(p.lat, 'f', 8));
                    xml.writeAttribute(QStringLiteral("lon"), QString::number(p.lon, 'f', 8));
                    xml.writeTextElement(QStringLiteral("ele"), QString::number(-p.depth, 'f', 2));
                    xml.writeTextElement(QStringLiteral("time"), isoTime(p.time));
                    xml.writeEndElement();
                }
                xml.writeEndElement();
                xml.writeEndElement();
            }
            xml.writeEndElement();
        }
        xml.writeEndDocument();
    }
    if (!out.commit())
        return std::unexpected(QStringLiteral("%1: %2").arg(file, out.errorString()));
    return {};
}

std::expected<qint64, QString> writeLog(const LogSet &logs, double from, double to, const QString &folder,
                                        const Progress &progress)
{
    if (logs.logs().empty())
        return std::unexpected(QStringLiteral("no logs"));
    const QByteArray digest = logs.logs().front()->schemas().defaultSchema().digest();
    for (const auto &log : logs.logs()) {
        if (log->schemas().defaultSchema().digest() != digest)
            return std::unexpected(QStringLiteral("%1 and %2 were written with different definitions: they cannot share one log")
                                       .arg(logs.logs().front()->folder(), log->folder()));
    }
    const QDir target(folder);
    if (target.exists() && !target.isEmpty())
        return std::unexpected(QStringLiteral("%1 is not empty: a new log goes in a new folder").arg(folder));
    if (!QDir().mkpath(folder))
        return std::unexpected(QStringLiteral("%1: cannot make the folder").arg(folder));
    // The definitions (and who recorded) come along as they were.
    const QDir source(logs.logs().front()->folder());
    for (const QString &name : source.entryList({QStringLiteral("IMC*.xml"), QStringLiteral("IMC*.xml.gz"),
                                                 QStringLiteral("Meta.json")}, QDir::Files)) {
        if (!QFile::copy(source.filePath(name), target.filePath(name)))
            return std::unexpected(QStringLiteral("%1: cannot copy it to %2").arg(source.filePath(name), folder));
    }
    const QString dataFile = target.filePath(QStringLiteral("Data.lsf"));
    QFile data(dataFile);
    if (!data.open(QIODevice::WriteOnly))
        return std::unexpected(QStringLiteral("%1: %2").arg(dataFile, data.errorString()));
    std::vector<quint64> offsets;
    std::vector<double> times;
    const qsizetype first = logs.upperBound(std::nextafter(from, -INFINITY));
    const qsizetype last = logs.upperBound(to);
    Ticker ticker(progress, last - first);
    QByteArray buffer;
    quint64 at = 0;
    for (qsizetype k = first; k < last; ++k) {
        if (!ticker.at(k - first)) {
            data.close();
            QDir(folder).removeRecursively();
            return std::unexpected(QStringLiteral("stopped"));
        }
        const QByteArrayView packet = logs.packet(k);
        offsets.push_back(at);
        times.push_back(logs.logOf(k).time(logs.indexInLog(k)));
        buffer.append(packet.data(), packet.size());
        at += quint64(packet.size());
        if (buffer.size() > (4 << 20)) {
            if (data.write(buffer) != buffer.size())
                return std::unexpected(QStringLiteral("%1: %2").arg(dataFile, data.errorString()));
            buffer.clear();
        }
    }
    if (data.write(buffer) != buffer.size() || !data.flush())
        return std::unexpected(QStringLiteral("%1: %2").arg(dataFile, data.errorString()));
    data.close();
    writeLogIndex(dataFile, offsets, times);
    ticker.done();
    return qint64(offsets.size());
}

} // namespace neptus::log
