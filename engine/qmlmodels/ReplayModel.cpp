#include "qmlmodels/ReplayModel.h"

#include <QFileInfo>

using namespace neptus;

ReplayModel::ReplayModel(std::shared_ptr<const log::LogSet> logs, log::ReplayTarget *target, QObject *parent)
    : QObject(parent)
    , m_player(logs, target)
{
    QStringList names;
    for (const auto &file : logs->logs()) {
        names.append(QFileInfo(file->folder()).fileName());
        if (!file->damage().isEmpty())
            m_problems.append(file->damage());
    }
    m_name = names.join(QStringLiteral(" + "));
    static const char *const kinds[] = {"note", "alarm", "planStart", "planEnd"};
    for (const log::LogMarker &marker : log::markersOf(*logs))
        m_markers.append(QVariantMap{{QStringLiteral("time"), marker.time},
                                     {QStringLiteral("kind"), QString::fromLatin1(kinds[marker.kind])},
                                     {QStringLiteral("text"), marker.text}});
    for (const log::PlanRun &run : log::planRuns(*logs))
        m_plans.append(QVariantMap{{QStringLiteral("system"), run.systemName}, {QStringLiteral("plan"), run.plan},
                                   {QStringLiteral("outcome"), run.outcome}, {QStringLiteral("begin"), run.begin},
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
    if (!m_trails) {
        m_trails.emplace();
        const QHash<quint16, QString> names = log::systemNames(m_player.logs());
        for (auto &[id, points] : log::tracks(m_player.logs()))
            m_trails->push_back({id, names.value(id, msg::systemLabel(id)), std::move(points)});
    }
    for (const auto &[id, system, points] : *m_trails) {
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
