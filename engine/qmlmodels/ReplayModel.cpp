#include "qmlmodels/ReplayModel.h"

#include "session/ConsoleReplay.h"

#include <QDir>
#include <QFileInfo>


using namespace neptus;

ReplayModel::ReplayModel(std::shared_ptr<const log::LogSet> logs, log::ReplayTarget *target, QObject *parent)
    : QObject(parent)
    , m_player(logs, target)
    , m_logs(logs)
    , m_logTracks(log::tracks(*logs))
{
    QStringList names;
    for (const auto &file : logs->logs()) {
        names.append(QFileInfo(file->folder()).fileName());
        if (!file->damage().isEmpty())
            m_problems.append(file->damage());
    }
    m_name = names.join(QStringLiteral(" + "));
    // Exports beside the (first) log, or in the home folder when it cannot be written.
    const QString beside = QDir(logs->logs().front()->folder()).filePath(QStringLiteral("exports"));
    m_exportFolder = QFileInfo(logs->logs().front()->folder()).isWritable()
        ? beside
        : QDir::home().filePath(QStringLiteral("neptus-exports/") + names.value(0));
    // One pass over the log for the plans' runs: the markers and the plan list both use it.
    const auto planEvents = log::planEvents(*logs);
    addMarkers(log::markersOf(*logs, planEvents));
    // The console's own alarms: a console fed the whole log, off the GUI thread.
    m_exports.start([self = this, logs, stop = m_stopExport] {
        ManualClock clock;
        const log::LogFile &first = *logs->logs().front();
        session::Console console(std::shared_ptr<const msg::Schema>(first.sharedSchemas(), &first.schemas().defaultSchema()),
                                 &clock);
        session::ConsoleReplay target(console, clock);
        std::vector<log::LogMarker> found;
        console.alarmGraph().setAnnouncer([&](const alarms::AlarmGraph::Alarm &alarm) {
            found.push_back({clock.now().toMSecsSinceEpoch() / 1000.0, log::LogMarker::Alarm,
                             QStringLiteral("%1: %2").arg(alarm.origin, alarm.message)});
        });
        log::Player player(logs, &target);
        for (double t = logs->begin(); t < logs->end() && !stop->load(); t += 1.0) {
            player.advanceTo(t + 1.0);
            console.check(); // silence and entity health, as the console's timer does
        }
        if (!found.empty() && !stop->load())
            QMetaObject::invokeMethod(self, [self, found] { self->addMarkers(found); }, Qt::QueuedConnection);
    });
    for (const log::PlanRun &run : log::planRuns(*logs, planEvents, m_logTracks))
        m_plans.append(QVariantMap{{QStringLiteral("system"), run.systemName}, {QStringLiteral("plan"), run.plan},
                                   {QStringLiteral("outcome"), run.outcome}, {QStringLiteral("reason"), run.reason}, {QStringLiteral("begin"), run.begin},
                                   {QStringLiteral("end"), run.end}, {QStringLiteral("duration"), run.end - run.begin},
                                   {QStringLiteral("distance"), run.distance}, {QStringLiteral("maxDepth"), run.maxDepth}});
    connect(&m_player, &log::Player::positionChanged, this, &ReplayModel::positionChanged);
    connect(&m_player, &log::Player::playingChanged, this, &ReplayModel::playingChanged);
    connect(&m_player, &log::Player::speedChanged, this, &ReplayModel::speedChanged);
    connect(&m_player, &log::Player::decodeFailed, this, [this](const QString &why) {
        m_problems.append(why);
        emit problemsChanged();
    });
}

void ReplayModel::addMarkers(const std::vector<log::LogMarker> &markers)
{
    static const char *const kinds[] = {"note", "alarm", "planStart", "planEnd"};
    for (const log::LogMarker &marker : markers)
        m_markers.append(QVariantMap{{QStringLiteral("time"), marker.time},
                                     {QStringLiteral("kind"), QString::fromLatin1(kinds[marker.kind])},
                                     {QStringLiteral("text"), marker.text}});
    std::stable_sort(m_markers.begin(), m_markers.end(), [](const QVariant &a, const QVariant &b) {
        return a.toMap().value(QStringLiteral("time")).toDouble() < b.toMap().value(QStringLiteral("time")).toDouble();
    });
    emit markersChanged();
}

void ReplayModel::setTracks(geo::Tracks *tracks)
{
    m_tracks = tracks;
    connect(&m_player, &log::Player::jumped, this, &ReplayModel::redrawTrails, Qt::UniqueConnection);
    redrawTrails(m_player.position());
}

void ReplayModel::redrawTrails(double t)
{
    if (!m_tracks)
        return;
    for (const auto &[id, points] : m_logTracks) {
        const QString system = m_logs->systemName(id);
        m_tracks->clear(system);
        std::vector<geo::Tracks::Fix> fixes;
        for (const log::TrackPoint &p : points) {
            if (p.time > t)
                break;
            geo::Tracks::Fix fix;
            fix.time = p.time;
            fix.lat = p.lat * M_PI / 180;
            fix.lon = p.lon * M_PI / 180;
            fix.depth = float(p.depth);
            fixes.push_back(fix);
        }
        m_tracks->append(id, system, fixes);
    }
}

void ReplayModel::setExportFolder(const QString &folder)
{
    if (folder == m_exportFolder)
        return;
    m_exportFolder = folder;
    emit exportChanged();
}

void ReplayModel::exportTo(const QString &format)
{
    if (m_exportProgress >= 0)
        return;
    const auto track = log::trackFormat(format);
    if (format != u"csv" && !track) {
        m_exportResult = tr("no export as '%1' (csv, kml, geojson, gpx)").arg(format);
        emit exportChanged();
        return;
    }
    const QString target = format == u"csv" ? QDir(m_exportFolder).filePath(QStringLiteral("csv"))
                                             : QDir(m_exportFolder).filePath(m_name.section(u' ', 0, 0) + u'.' + format);
    m_exportProgress = 0;
    m_exportResult.clear();
    emit exportChanged();
    // The destructor stops the export and waits for it: `self` outlives the task.
    ReplayModel *self = this;
    const auto progress = [self, stop = m_stopExport](double fraction) {
        QMetaObject::invokeMethod(self, [self, fraction] {
            if (self->m_exportProgress >= 0 && fraction > self->m_exportProgress) {
                self->m_exportProgress = fraction;
                emit self->exportChanged();
            }
        }, Qt::QueuedConnection);
        return !stop->load();
    };
    m_exports.start([self, logs = m_logs, track, target, progress] {
        QString result;
        if (!QDir().mkpath(QFileInfo(target).absolutePath())) {
            result = tr("cannot make %1").arg(QFileInfo(target).absolutePath());
        } else if (track) {
            const auto done = log::exportTracks(*logs, *track, target, progress);
            result = done ? target : done.error();
        } else {
            const auto done = log::exportCsv(*logs, target, progress);
            result = done ? tr("%1 files in %2").arg(done->size()).arg(target) : done.error();
        }
        QMetaObject::invokeMethod(self, [self, result] {
            self->m_exportProgress = -1;
            self->m_exportResult = result;
            emit self->exportChanged();
        }, Qt::QueuedConnection);
    });
}

ReplayModel::~ReplayModel()
{
    m_stopExport->store(true);
    m_exports.waitForDone();
}

QList<QPointF> ReplayModel::series(const QString &path)
{
    if (const auto cached = m_series.constFind(path); cached != m_series.cend())
        return *cached;
    QList<QPointF> points;
    if (const auto values = log::fieldSeries(m_player.logs(), path)) {
        points.reserve(qsizetype(values->size()));
        for (const auto &[t, v] : *values)
            points.append(QPointF(t, v));
    }
    m_series.insert(path, points);
    return points;
}

double ReplayModel::nextMarker(int direction) const
{
    const double now = m_player.position();
    double best = -1;
    for (const QVariant &entry : m_markers) {
        const double t = entry.toMap().value(QStringLiteral("time")).toDouble();
        if (direction >= 0 && t > now + 0.001 && (best < 0 || t < best))
            best = t;
        if (direction < 0 && t < now - 0.5 && t > best)
            best = t;
    }
    return best;
}
