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

std::vector<PlanRun> planRuns(const LogSet &logs, const std::map<quint16, std::vector<TrackPoint>> &all)
{
    std::vector<PlanRun> runs;
    if (logs.logs().empty())
        return runs;
    const msg::MessageDef *stateDef = logs.logs().front()->schemas().defaultSchema().byAbbrev(u"PlanControlState");
    if (!stateDef)
        return runs;
    QHash<quint16, size_t> open; // system → its run in `runs`
    for (qsizetype k = 0; k < logs.count(); ++k) {
        const LogFile &log = logs.logOf(k);
        const qsizetype i = logs.indexInLog(k);
        if (log.messageId(i) != stateDef->id)
            continue;
        const auto m = logs.decode(k);
        if (!m || !m->def())
            continue;
        const quint16 system = m->header.src;
        const bool executing = m->integer(u"state") == 3;
        const QString plan = m->text(u"plan_id");
        const auto current = open.constFind(system);
        if (current != open.cend() && (!executing || runs[*current].plan != plan)) {
            PlanRun &run = runs[*current];
            run.end = logs.time(k);
            if (!executing)
                run.outcome = m->enumText(m->def()->fieldIndex.value(QStringLiteral("last_outcome")));
            open.remove(system);
        }
        if (executing && !open.contains(system)) {
            runs.push_back({system, logs.systemName(system), plan, {}, logs.time(k), logs.time(k), 0, 0});
            open.insert(system, runs.size() - 1);
        } else if (executing) {
            runs[open.value(system)].end = logs.time(k);
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

std::vector<LogMarker> markersOf(const LogSet &logs)
{
    std::vector<LogMarker> markers;
    if (logs.logs().empty())
        return markers;
    const msg::Schema &schema = logs.logs().front()->schemas().defaultSchema();
    const auto idOf = [&](QStringView abbrev) {
        const msg::MessageDef *def = schema.byAbbrev(abbrev);
        return def ? def->id : msg::Schema::noMessage;
    };
    const quint16 logBook = idOf(u"LogBookEntry"), entityState = idOf(u"EntityState"),
                  planState = idOf(u"PlanControlState"), planControl = idOf(u"PlanControl");
    QHash<quint32, qint64> entityLevels; // (system, entity) → last state
    QHash<quint16, std::pair<QString, double>> executing; // system → the plan it runs, since when
    QHash<quint16, QString> finished; // a plan said over while its state still says EXECUTING
    for (qsizetype k = 0; k < logs.count(); ++k) {
        const LogFile &log = logs.logOf(k);
        const qsizetype i = logs.indexInLog(k);
        const quint16 id = log.messageId(i);
        if (id != logBook && id != entityState && id != planState && id != planControl)
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
        } else if (id == entityState) {
            const quint32 key = (quint32(m->header.src) << 8) | m->header.srcEnt;
            const qint64 state = m->integer(u"state"); // BOOT, NORMAL, FAULT, ERROR, FAILURE
            const qint64 before = entityLevels.value(key, 1);
            entityLevels.insert(key, state);
            if (state >= 2 && state != before)
                markers.push_back({t, LogMarker::Alarm, QStringLiteral("%1 entity %2: %3 %4")
                                                            .arg(who).arg(m->header.srcEnt)
                                                            .arg(m->enumText(m->def()->fieldIndex.value(QStringLiteral("state"))),
                                                                 m->text(u"description"))});
        } else if (id == planControl) {
            // A vehicle's final reply to START (SUCCESS or FAILURE) for the plan it runs, after
            // its first reply (the start): the plan is over. DUNE's logs end there.
            const qint64 type = m->integer(u"type"), op = m->integer(u"op");
            const auto running = executing.constFind(m->header.src);
            if (op != 0 || (type != 1 && type != 2) || running == executing.cend()
                || running->first != m->text(u"plan_id") || t - running->second < 1.0)
                continue;
            markers.push_back({t, type == 2 ? LogMarker::Alarm : LogMarker::PlanEnd,
                               QStringLiteral("%1: plan %2 ended (%3): %4")
                                   .arg(who, running->first, type == 2 ? QStringLiteral("FAILURE") : QStringLiteral("SUCCESS"),
                                        m->text(u"info"))});
            finished.insert(m->header.src, running->first);
            executing.remove(m->header.src);
        } else {
            const bool running = m->integer(u"state") == 3; // EXECUTING
            const QString plan = m->text(u"plan_id");
            const QString was = executing.value(m->header.src).first;
            if (!running)
                finished.remove(m->header.src);
            else if (finished.value(m->header.src) == plan)
                continue;
            if (running && was != plan) {
                if (!was.isEmpty())
                    markers.push_back({t, LogMarker::PlanEnd, QStringLiteral("%1: plan %2 ended").arg(who, was)});
                markers.push_back({t, LogMarker::PlanStart, QStringLiteral("%1: plan %2 started").arg(who, plan)});
                executing.insert(m->header.src, {plan, t});
            } else if (!running && !was.isEmpty()) {
                markers.push_back({t, LogMarker::PlanEnd, QStringLiteral("%1: plan %2 ended (%3)")
                                                             .arg(who, was, m->enumText(m->def()->fieldIndex.value(QStringLiteral("last_outcome"))))});
                executing.remove(m->header.src);
            }
        }
    }
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
