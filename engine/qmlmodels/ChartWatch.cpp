#include "qmlmodels/ChartWatch.h"

#include "alarms/AlarmGraph.h"
#include "charts/ChartCheck.h"
#include "charts/ChartFiles.h"
#include "geo/Geodesy.h"
#include "qmlmodels/Tracks.h"

#include <QtConcurrent/QtConcurrentRun>

using namespace neptus;
using namespace Qt::StringLiterals;

ChartWatch::ChartWatch(geo::Tracks *tracks, alarms::AlarmGraph *alarms, QObject *parent)
    : QObject(parent)
    , m_tracks(tracks)
    , m_alarms(alarms)
{
    // Once a second, not on every model sync: a vehicle moves a few metres in that time.
    m_timer.setInterval(1000);
    connect(&m_timer, &QTimer::timeout, this, &ChartWatch::check);
}

// (A read still going ends on its own: the job holds only its path and its result.)
ChartWatch::~ChartWatch() = default;

void ChartWatch::setCharts(const QString &path)
{
    if (path == m_path)
        return;
    m_path = path;
    m_cells.reset();
    m_verdicts.clear(); // (the maps ask again on the chartsChanged below)
    m_timer.stop();
    m_error.clear();
    if (m_vehicles.vehicles.isEmpty())
        m_vehicles = mission::loadVehicles(mission::vehicleFolders());
    if (path.isEmpty()) {
        m_loading = false;
        emit chartsChanged();
        return;
    }
    m_loading = true;
    emit chartsChanged();
    auto result = std::make_shared<std::expected<std::shared_ptr<const std::vector<charts::Cell>>, QString>>();
    m_load.disconnect(this);
    connect(&m_load, &QFutureWatcherBase::finished, this, [this, path, result] {
        if (path != m_path)
            return;
        m_loading = false;
        if (*result)
            m_cells = **result;
        else
            m_error = result->error();
        emit chartsChanged();
        m_timer.start();
        check();
    });
    m_load.setFuture(QtConcurrent::run([path, result] { *result = charts::sharedCells(path); }));
}

void ChartWatch::setCells(std::shared_ptr<const std::vector<charts::Cell>> cells)
{
    m_cells = std::move(cells);
    m_loading = false;
    emit chartsChanged();
    m_timer.start();
    check();
}

ChartWatch::Verdict ChartWatch::judge(const QString &system) const
{
    Verdict v;
    const geo::Tracks::Track *track = m_tracks->track(system);
    const mission::VehicleDefinition *vehicle = m_vehicles.find(system);
    if (!m_cells || !track || track->fixes.empty() || !vehicle)
        return v;
    const geo::Tracks::Fix &at = track->latest;
    const auto need = charts::requiredDepth(vehicle, at.depth); // the plan check's rule
    if (!need)
        return v; // aircraft and the rest do not float
    v.report = charts::reportAt(*m_cells, geo::degrees(at.lon), geo::degrees(at.lat), 0, false);
    v.need = need->metres;
    if (!v.report.covered) {
        v.level = alarms::Info;
        v.text = u"%1 is off the charts: the water there is not known"_s.arg(system);
    } else if (v.report.land) {
        v.level = alarms::Error;
        v.text = u"%1 is on land on the chart (%2)"_s.arg(system, v.report.cell);
    } else if (v.report.depthMin && *v.report.depthMin < v.need) {
        v.level = alarms::Error;
        v.text = u"%1 is in water charted %2–%3 m%4, shallower than the %5 m it needs"_s.arg(
            system, QString::number(*v.report.depthMin, 'f', 1), QString::number(v.report.depthMax.value_or(*v.report.depthMin), 'f', 1),
            v.report.place.isEmpty() ? QString() : u" in "_s + v.report.place, QString::number(v.need, 'f', 1));
    } else {
        v.level = alarms::Normal;
        v.text = v.report.depthMin ? u"charted %1–%2 m"_s.arg(QString::number(*v.report.depthMin, 'f', 1),
                                                              QString::number(v.report.depthMax.value_or(*v.report.depthMin), 'f', 1))
                                   : u"no depth charted"_s;
    }
    return v;
}

void ChartWatch::check()
{
    if (!m_cells)
        return;
    m_verdicts.clear();
    for (const QString &system : m_tracks->systems()) {
        const Verdict v = judge(system);
        m_verdicts.insert(system, v);
        const QString message = v.level == alarms::Normal ? QString() : v.text;
        if (v.level == alarms::Unknown || m_raised.value(system) == std::pair{v.level, message})
            continue;
        // (Raised again at the same level only the message changes: the alarm is not announced twice.)
        m_raised.insert(system, {v.level, message});
        m_alarms->raise(m_alarms->ensure(u"systems/%1/chart"_s.arg(system)), alarms::Level(v.level), message);
    }
    ++m_revision;
    emit judged();
}

QVariantMap ChartWatch::under(const QString &system) const
{
    const auto looked = m_verdicts.constFind(system);
    const Verdict v = looked != m_verdicts.cend() ? *looked : judge(system);
    if (v.level == alarms::Unknown)
        return {};
    return {{u"covered"_s, v.report.covered}, {u"land"_s, v.report.land},
            {u"min"_s, v.report.depthMin ? QVariant(*v.report.depthMin) : QVariant()},
            {u"max"_s, v.report.depthMax ? QVariant(*v.report.depthMax) : QVariant()}, {u"place"_s, v.report.place},
            {u"need"_s, v.need}, {u"text"_s, v.text}, {u"safe"_s, v.level == alarms::Normal}};
}
