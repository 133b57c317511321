#include "PlanEditorModel.h"

#include "charts/ChartCheck.h"
#include "core/SafeFile.h"
#include "mission/MissionXml.h"
#include "mission/NeptusExport.h"
#include "mission/Patterns.h"
#include "qmlmodels/MissionFeatures.h"
#include "plans/Supervisor.h"
#include "geo/Geodesy.h"
#include "processor/MissionTranslator.h"

#include <QDir>
#include <QFileInfo>
#include <QDateTime>
#include <QRegularExpression>
#include <QThreadPool>

#include <cmath>
#include <limits>

using namespace neptus::mission;
using namespace Qt::StringLiterals;

namespace {

// What an editor may add to a plan of a vehicle with no definition.
const QStringList knownTypes{u"Goto"_s, u"Loiter"_s, u"StationKeeping"_s, u"Rows"_s, u"YoYo"_s, u"FollowPath"_s,
                             u"ExpandingSquare"_s, u"CrossHatch"_s, u"PopUp"_s, u"Elevator"_s};

QList<LatLon> latLons(const QVariantList &points)
{
    QList<LatLon> list;
    for (const QVariant &v : points) {
        const QVariantMap c = v.toMap();
        list.append({c.value(u"lat"_s).toDouble(), c.value(u"lon"_s).toDouble()});
    }
    return list;
}

// Undo keeps this many edits.
constexpr qsizetype undoDepth = 200;

QString severityName(PlanProblem::Severity s) { return s == PlanProblem::Severity::Error ? u"error"_s : u"warning"_s; }

} // namespace

PlanEditorModel::PlanEditorModel(QObject *parent)
    : QObject(parent),
      m_maneuverRows(new RowModel({u"maneuver"_s, u"type"_s, u"lat"_s, u"lon"_s, u"severity"_s, u"arrival"_s}, this)),
      m_parameters(new RowModel({u"name"_s, u"value"_s, u"unit"_s, u"type"_s, u"min"_s, u"max"_s, u"values"_s, u"problem"_s}, this))
{
}

const VehicleCatalog &PlanEditorModel::vehicles() const
{
    // The console's, read once per mission by its plan desk; its own only without one (a test, a tool).
    if (m_desk && !m_desk->definitions().vehicles.isEmpty())
        return m_desk->definitions();
    if (!m_ownVehicles)
        m_ownVehicles = loadVehicles(vehicleFolders());
    return *m_ownVehicles;
}

void PlanEditorModel::fail(const QString &why)
{
    m_error = why;
    emit errorChanged();
}

void PlanEditorModel::setMissionPath(const QString &path)
{
    if (path == m_path)
        return;
    m_path = path;
    m_mission = {};
    m_undo.clear();
    m_redo.clear();
    m_modified = false;
    m_planId.clear();
    if (!path.isEmpty()) {
        auto loaded = loadMission(path);
        if (!loaded) {
            QStringList lines;
            for (const auto &e : loaded.error())
                lines << e.toString();
            fail(lines.join(u'\n'));
        } else {
            m_mission = std::move(*loaded);
            if (!m_mission.plans.isEmpty())
                m_planId = m_mission.plans.first().id;
            fail({});
        }
    }
    emit missionChanged();
    emit planChanged();
    missionReplaced();
}

QStringList PlanEditorModel::planIds() const
{
    QStringList ids;
    for (const Plan &p : m_mission.plans)
        ids << p.id;
    return ids;
}

void PlanEditorModel::setPlanId(const QString &id)
{
    if (id == m_planId || !m_mission.plan(id))
        return;
    m_planId = id;
    m_undo.clear();
    m_redo.clear();
    emit planChanged();
    otherPlansAgain();
    changed();
}

const Plan *PlanEditorModel::plan() const { return m_mission.plan(m_planId); }

Plan *PlanEditorModel::editable()
{
    for (Plan &p : m_mission.plans)
        if (p.id == m_planId)
            return &p;
    return nullptr;
}

QString PlanEditorModel::vehicle() const { return plan() ? plan()->vehicle : QString(); }

QStringList PlanEditorModel::maneuverTypes() const
{
    const VehicleDefinition *v = vehicles().find(vehicle());
    if (!v)
        return knownTypes;
    QStringList types;
    for (const ManeuverSpec &s : v->maneuvers)
        types << s.type;
    return types;
}

Maneuver *PlanEditorModel::find(const QString &id)
{
    Plan *p = editable();
    if (!p)
        return nullptr;
    for (Maneuver &m : p->maneuvers)
        if (m.id == id)
            return &m;
    return nullptr;
}

void PlanEditorModel::remember()
{
    m_undo.append(m_mission);
    if (m_undo.size() > undoDepth)
        m_undo.removeFirst();
    m_redo.clear();
}

void PlanEditorModel::setDesk(PlanDeskModel *desk)
{
    if (desk == m_desk)
        return;
    if (m_desk)
        disconnect(m_desk, nullptr, this, nullptr);
    m_desk = desk;
    if (desk)
        connect(desk, &PlanDeskModel::sharedChange, this, &PlanEditorModel::adoptShared);
    emit deskChanged();
    if (!m_path.isEmpty())
        changed(); // the mission came first: checked again against the desk's vehicle definitions
}

void PlanEditorModel::adoptShared()
{
    const Mission *shared = m_desk ? m_desk->sharedMission() : nullptr;
    if (!shared || m_path.isEmpty() || m_desk->missionPath() != m_path || shared->id != m_mission.id)
        return;
    remember();
    m_mission = *shared;
    if (!plan() && !m_mission.plans.isEmpty())
        m_planId = m_mission.plans.first().id;
    m_modified = false; // the desk wrote the file as it is now
    emit missionChanged();
    missionReplaced();
}

void PlanEditorModel::setCharts(ChartWatch *charts)
{
    if (charts == m_charts)
        return;
    if (m_charts)
        m_charts->disconnect(this);
    m_charts = charts;
    if (charts) // checked again once its cells are read
        connect(charts, &ChartWatch::chartsChanged, this, &PlanEditorModel::changed);
    emit chartsChanged();
    changed();
}

void PlanEditorModel::changed()
{
    m_pathPoints.clear();
    m_profileRuns.clear();
    m_profileTop.clear();
    m_profileLength = 1;
    m_problems.clear();
    m_geometry = {};
    if (const Plan *p = plan()) {
        const VehicleDefinition *v = vehicles().find(p->vehicle);
        m_geometry = planGeometry(*p, v ? v->speeds() : SpeedModel{}, &m_geometryCache);
        m_problems = checkPlan(*p, m_mission, m_geometry, v);
        if (m_charts && m_charts->cells()) {
            m_problems += neptus::charts::checkAgainstCharts(m_geometry, v, *m_charts->cells());
            std::stable_sort(m_problems.begin(), m_problems.end(),
                             [](const PlanProblem &a, const PlanProblem &b) { return a.severity > b.severity; });
        }
        checkBottom();
        for (const Transition &t : p->transitions) {
            if (neptus::plans::Supervisor::plain(t))
                continue;
            if (const auto &problem = conditionProblem(t.condition)) {
                const Maneuver *from = p->maneuver(t.from);
                m_problems.prepend({PlanProblem::Severity::Error, PlanProblem::Kind::Condition, t.from,
                                    u"%1 → %2: the condition does not compile (column %3): %4"_s.arg(t.from, t.to).arg(problem->column).arg(problem->message),
                                    from ? std::optional(from->number(u"lat"_s)) : std::nullopt,
                                    from ? std::optional(from->number(u"lon"_s)) : std::nullopt, t.line.value});
            }
        }
        double along = 0;
        QString unit;
        for (const ManeuverGeometry &g : m_geometry.maneuvers) {
            for (const Waypoint &w : g.points) {
                along += w.leg;
                m_pathPoints.append(QVariantMap{{u"lat"_s, w.lat}, {u"lon"_s, w.lon}, {u"maneuver"_s, g.id},
                                                {u"distance"_s, along}, {u"z"_s, w.z}, {u"zUnits"_s, w.zUnits}});
                // The profile: a new run where the units change.
                QList<QList<QPointF>> &runs = m_profileRuns[w.zUnits];
                if (w.zUnits != unit || runs.isEmpty())
                    runs.append(QList<QPointF>());
                unit = w.zUnits;
                runs.last().append(QPointF(along, w.z));
                m_profileTop[w.zUnits] = std::max(m_profileTop.value(w.zUnits, 1.0), w.z);
            }
        }
        m_profileLength = std::max(1.0, along);
    }
    m_maneuverRows->setRows(maneuverRowsNow());
    m_parameters->setRows(parameterRows(m_selected));
    const auto same = [](const PlanProblem &a, const PlanProblem &b) {
        return a.severity == b.severity && a.kind == b.kind && a.maneuver == b.maneuver && a.message == b.message && a.lat == b.lat
            && a.lon == b.lon;
    };
    const bool problemsMoved = !std::equal(m_problems.begin(), m_problems.end(), m_shownProblems.begin(), m_shownProblems.end(), same);
    if (problemsMoved) {
        m_shownProblems = m_problems;
        m_problemList = problemList();
    }
    if (m_desk)
        m_desk->shareEdits(m_mission); // only what changed goes out
    emit edited();
    if (problemsMoved)
        emit problemsChanged();
}

QList<RowModel::Row> PlanEditorModel::maneuverRowsNow() const
{
    QList<RowModel::Row> rows;
    const Plan *p = plan();
    if (!p)
        return rows;
    QHash<QString, QString> worst;
    for (const PlanProblem &problem : m_problems) {
        if (!problem.maneuver.isEmpty() && !worst.contains(problem.maneuver))
            worst.insert(problem.maneuver, severityName(problem.severity)); // worst first
    }
    // When the vehicle reaches each maneuver, seconds from the start along
    // the plan (-1: after one that never ends, or one it does not reach).
    QHash<QString, double> arrival;
    double elapsed = 0;
    for (const ManeuverGeometry &g : m_geometry.maneuvers) {
        if (elapsed < 0)
            break;
        const double transit = g.speed > 0 ? g.transit / g.speed : 0;
        arrival.insert(g.id, elapsed + transit);
        elapsed = g.duration ? elapsed + *g.duration : -1;
    }
    rows.reserve(p->maneuvers.size());
    for (const Maneuver &m : p->maneuvers) {
        // In the order of the roles.
        rows.append(RowModel::Row{m.id, m.type, m.number(u"lat"_s), m.number(u"lon"_s), worst.value(m.id), arrival.value(m.id, -1)});
    }
    return rows;
}

QVariantMap PlanEditorModel::profile() const
{
    QStringList units;
    QVariantMap top;
    for (const QString &unit : {u"DEPTH"_s, u"ALTITUDE"_s, u"HEIGHT"_s}) {
        if (m_profileRuns.contains(unit)) {
            units << unit;
            top.insert(unit, m_profileTop.value(unit, 1.0));
        }
    }
    return {{u"units"_s, units}, {u"top"_s, top}};
}

QVariant PlanEditorModel::profileLines(const QString &unit) const
{
    QList<QList<QPointF>> lines = m_profileRuns.value(unit);
    const double top = m_profileTop.value(unit, 1.0);
    const bool down = unit == u"DEPTH"_s;
    for (QList<QPointF> &line : lines) {
        for (QPointF &p : line) {
            const double f = std::max(0.0, p.y()) / top;
            p = QPointF(p.x() / m_profileLength, down ? f : 1 - f);
        }
    }
    return QVariant::fromValue(lines);
}

QVariantList PlanEditorModel::maneuvers() const
{
    QVariantList list;
    for (int i = 0; i < m_maneuverRows->count(); ++i) {
        QVariantMap m = m_maneuverRows->get(i);
        m.insert(u"id"_s, m.take(u"maneuver"_s));
        m.insert(u"index"_s, int(i));
        list.append(m);
    }
    return list;
}

void PlanEditorModel::setSelected(const QString &id)
{
    if (id == m_selected)
        return;
    m_selected = id;
    m_parameters->setRows(parameterRows(id));
    emit selectedChanged();
}

QString PlanEditorModel::maneuverNear(double lat, double lon, double metres) const
{
    const Waypoint at{lat, lon, 0, {}, 0, 0};
    QString nearest;
    double best = metres;
    const int latColumn = m_maneuverRows->column(u"lat"_s), lonColumn = m_maneuverRows->column(u"lon"_s);
    for (const RowModel::Row &row : m_maneuverRows->rows()) {
        const double d = distance(at, Waypoint{row[latColumn].toDouble(), row[lonColumn].toDouble(), 0, {}, 0, 0});
        if (d <= best) {
            best = d;
            nearest = row.first().toString();
        }
    }
    return nearest;
}

QVariantList PlanEditorModel::problemList() const
{
    QVariantList list;
    const double none = std::numeric_limits<double>::quiet_NaN();
    for (const PlanProblem &p : m_problems) {
        list.append(QVariantMap{{u"severity"_s, severityName(p.severity)}, {u"kind"_s, int(p.kind)}, {u"maneuver"_s, p.maneuver},
                                {u"message"_s, p.message}, {u"lat"_s, p.lat.value_or(none)}, {u"lon"_s, p.lon.value_or(none)}});
    }
    return list;
}

int PlanEditorModel::errorCount() const
{
    return int(std::count_if(m_problems.begin(), m_problems.end(),
                             [](const PlanProblem &p) { return p.severity == PlanProblem::Severity::Error; }));
}

QVariantMap PlanEditorModel::statistics() const
{
    const Plan *p = plan();
    return {{u"maneuvers"_s, p ? int(p->maneuvers.size()) : 0},
            {u"length"_s, m_geometry.length},
            {u"duration"_s, m_geometry.duration.value_or(-1)},
            {u"maxDepth"_s, m_geometry.maxDepth.value_or(-1)}};
}

QStringList PlanEditorModel::layers() const
{
    QStringList names;
    for (const Map &map : m_mission.maps)
        for (const Feature &f : map.features)
            if (!names.contains(f.layer))
                names << f.layer;
    std::sort(names.begin(), names.end());
    return names;
}

void PlanEditorModel::featuresEdited()
{
    m_featureList = missionFeatures(m_mission, m_path);
    emit featuresChanged();
    terrainAgain();
    changed();
}

void PlanEditorModel::checklistsEdited()
{
    emit checklistsChanged();
    if (m_desk)
        m_desk->shareEdits(m_mission);
    emit edited(); // modified
}

void PlanEditorModel::missionReplaced()
{
    otherPlansAgain();
    emit checklistsChanged();
    featuresEdited();
}

void PlanEditorModel::terrainAgain()
{
    QString file;
    GeoPosition origin = m_mission.home;
    for (const Map &map : m_mission.maps) {
        for (const Feature &f : map.features) {
            if (f.kind != u"model"_s || f.attributes.value(u"role"_s) != u"terrain"_s || f.attributes.value(u"file"_s).isEmpty() || !file.isEmpty())
                continue;
            file = QFileInfo(m_path).absoluteDir().absoluteFilePath(f.attributes.value(u"file"_s));
            if (const auto at = m_mission.position(f.position))
                origin = *at;
        }
    }
    if (file == m_terrainFile && origin == m_terrainOrigin)
        return;
    m_terrainFile = file;
    m_terrainOrigin = origin;
    m_seabed.reset();
    m_terrainImport.reset();
    m_terrainState = file.isEmpty() ? QString() : u"reading %1"_s.arg(QFileInfo(file).fileName());
    emit terrainChanged();
    if (file.isEmpty())
        return;
    // In the helper process, off the GUI thread: a terrain may be large, or damaged.
    m_terrainImport = std::make_unique<neptus::models::ModelImport>();
    connect(m_terrainImport.get(), &neptus::models::ModelImport::finished, this, [this] {
        const auto &mesh = m_terrainImport->result();
        if (!mesh) {
            m_terrainState = mesh.error();
        } else {
            m_seabed.emplace(*mesh);
            m_terrainState = u"%1: %2 triangles"_s.arg(QFileInfo(m_terrainFile).fileName()).arg(mesh->triangleCount());
        }
        emit terrainChanged();
        changed();
    });
    m_terrainImport->start(file);
}

void PlanEditorModel::checkBottom()
{
    if (!m_seabed || m_seabed->empty())
        return;
    const neptus::geo::Geodetic origin{neptus::geo::radians(m_terrainOrigin.lat), neptus::geo::radians(m_terrainOrigin.lon), 0};
    for (const ManeuverGeometry &g : m_geometry.maneuvers) {
        for (const Waypoint &w : g.points) {
            if (w.zUnits != u"DEPTH"_s)
                continue;
            const Eigen::Vector3d ned = neptus::geo::toNed({neptus::geo::radians(w.lat), neptus::geo::radians(w.lon), 0}, origin);
            const auto ground = m_seabed->heightAt(ned.y(), ned.x());
            if (!ground || w.z <= -*ground)
                continue;
            m_problems.prepend({PlanProblem::Severity::Error, PlanProblem::Kind::BelowBottom, g.id,
                                u"'%1' (%2): %3 m deep where the bottom is %4 m deep"_s.arg(g.id, g.type).arg(w.z, 0, 'f', 1).arg(-*ground, 0, 'f', 1),
                                w.lat, w.lon, 0});
            break; // once per maneuver
        }
    }
}

void PlanEditorModel::otherPlansAgain()
{
    m_otherPlans.clear();
    for (const Plan &p : m_mission.plans) {
        if (p.id == m_planId)
            continue;
        const VehicleDefinition *v = vehicles().find(p.vehicle);
        QVariantList path;
        for (const ManeuverGeometry &g : planGeometry(p, v ? v->speeds() : SpeedModel{}).maneuvers)
            for (const Waypoint &w : g.points)
                path.append(QVariantMap{{u"lat"_s, w.lat}, {u"lon"_s, w.lon}});
        m_otherPlans.append(QVariantMap{{u"id"_s, p.id}, {u"vehicle"_s, p.vehicle}, {u"path"_s, path}});
    }
    emit otherPlansChanged();
}

Feature *PlanEditorModel::feature(const QString &id)
{
    for (Map &map : m_mission.maps)
        for (Feature &f : map.features)
            if (f.id == id)
                return &f;
    return nullptr;
}

namespace {

const QStringList featureKinds{u"mark"_s, u"transponder"_s, u"path"_s, u"polygon"_s, u"circle"_s, u"box"_s,
                               u"cylinder"_s, u"ellipsoid"_s, u"image"_s, u"model"_s};
const QStringList areaKinds{u"polygon"_s, u"circle"_s, u"box"_s, u"cylinder"_s, u"ellipsoid"_s};
const QStringList solidKinds{u"box"_s, u"cylinder"_s, u"ellipsoid"_s};

Feature::Point pointAt(double lat, double lon)
{
    Feature::Point p;
    p.lat = lat;
    p.lon = lon;
    return p;
}

// A point moved to lat/lon keeps its depth or height.
void placePoint(Feature::Point &p, double lat, double lon)
{
    p.lat = lat;
    p.lon = lon;
    p.north.reset();
    p.east.reset();
}

bool isPosition(double lat, double lon)
{
    return std::isfinite(lat) && std::isfinite(lon) && std::abs(lat) <= 90 && std::abs(lon) <= 180;
}

struct PropertySpec
{
    QString name, type, unit;
    QStringList choices;
    std::optional<double> min;
};

// What each kind's form edits, as the mission format (schemas/mission.xsd) allows it.
QList<PropertySpec> propertiesOf(const QString &kind)
{
    QList<PropertySpec> specs{{u"name"_s, u"text"_s, {}, {}, {}}, {u"color"_s, u"color"_s, {}, {}, {}},
                              {u"layer"_s, u"text"_s, {}, {}, {}}};
    const QStringList roles{u"area"_s, u"operating-area"_s, u"no-go"_s, u"survey-area"_s};
    if (areaKinds.contains(kind))
        specs.append({u"role"_s, u"choice"_s, {}, roles, {}});
    if (kind == u"mark"_s)
        specs.append({u"role"_s, u"choice"_s, {}, {u"mark"_s, u"rally"_s}, {}});
    if (kind == u"circle"_s)
        specs.append({u"radius"_s, u"number"_s, u"m"_s, {}, 0.0});
    if (solidKinds.contains(kind)) {
        specs.append({u"width"_s, u"number"_s, u"m"_s, {}, 0.0});
        specs.append({u"length"_s, u"number"_s, u"m"_s, {}, 0.0});
        specs.append({u"bearing"_s, u"number"_s, u"°"_s, {}, {}});
    }
    if (areaKinds.contains(kind)) {
        specs.append({u"z-min"_s, u"number"_s, u"m"_s, {}, {}});
        specs.append({u"z-max"_s, u"number"_s, u"m"_s, {}, {}});
        specs.append({u"z-units"_s, u"choice"_s, {}, {u"DEPTH"_s, u"HEIGHT"_s}, {}});
    }
    if (kind == u"transponder"_s) {
        specs.append({u"depth"_s, u"number"_s, u"m"_s, {}, {}});
        specs.append({u"config"_s, u"text"_s, {}, {}, {}});
    }
    if (kind == u"image"_s || kind == u"model"_s) {
        specs.append({u"file"_s, u"text"_s, {}, {}, {}});
        specs.append({u"scale"_s, u"number"_s, kind == u"image"_s ? u"m/pixel"_s : QString(), {}, 0.0});
    }
    if (kind == u"image"_s)
        specs.append({u"rotation"_s, u"number"_s, u"°"_s, {}, {}});
    if (kind == u"model"_s)
        specs.append({u"role"_s, u"choice"_s, {}, {u"object"_s, u"terrain"_s}, {}});
    if (kind == u"model"_s)
        for (const QString &angle : {u"roll"_s, u"pitch"_s, u"yaw"_s})
            specs.append({angle, u"number"_s, u"°"_s, {}, {}});
    return specs;
}

} // namespace

QString PlanEditorModel::addFeature(const QString &kind, const QVariantList &points)
{
    if (!featureKinds.contains(kind)) {
        fail(u"no map feature '%1' (there are: %2)"_s.arg(kind, featureKinds.join(u", "_s)));
        return {};
    }
    QList<Feature::Point> at;
    for (const QVariant &v : points) {
        const QVariantMap c = v.toMap();
        const double lat = c.value(u"lat"_s).toDouble(), lon = c.value(u"lon"_s).toDouble();
        if (!isPosition(lat, lon)) {
            fail(u"not a position: %1, %2"_s.arg(lat).arg(lon));
            return {};
        }
        at.append(pointAt(lat, lon));
    }
    const qsizetype needed = kind == u"path"_s ? 2 : kind == u"polygon"_s ? 3 : 1;
    if (at.size() < needed || (needed == 1 && at.size() != 1)) {
        fail(u"a %1 takes %2 point%3, not %4"_s.arg(kind).arg(needed == 1 ? u"one"_s : u"%1 or more"_s.arg(needed))
                 .arg(needed == 1 ? u""_s : u"s"_s).arg(at.size()));
        return {};
    }
    if (m_path.isEmpty()) {
        fail(u"no mission is open to add to"_s);
        return {};
    }
    remember();
    if (m_mission.maps.isEmpty())
        m_mission.maps.append(Map{u"map"_s, {}, {}});
    Feature f;
    f.kind = kind;
    for (int n = 1;; ++n) {
        f.id = kind + QString::number(n);
        if (!feature(f.id))
            break;
    }
    if (needed == 1)
        f.position = at.first();
    else
        f.points = at;
    // What the format requires, at a size that shows at harbour scale.
    if (kind == u"circle"_s)
        f.attributes.insert(u"radius"_s, u"25"_s);
    if (solidKinds.contains(kind)) {
        f.attributes.insert(u"width"_s, u"40"_s);
        f.attributes.insert(u"length"_s, u"40"_s);
    }
    if (areaKinds.contains(kind) && kind != u"polygon"_s)
        f.attributes.insert(u"role"_s, u"area"_s);
    if (kind == u"image"_s || kind == u"model"_s) {
        f.attributes.insert(u"file"_s, QString());
        f.attributes.insert(u"scale"_s, kind == u"image"_s ? u"0.5"_s : u"1"_s);
    }
    m_mission.maps.first().features.append(f);
    m_modified = true;
    fail({});
    featuresEdited();
    return f.id;
}

bool PlanEditorModel::moveFeature(const QString &id, double lat, double lon)
{
    Feature *f = feature(id);
    if (!f || !isPosition(lat, lon))
        return false;
    const auto from = m_mission.position(f->position.lat || f->position.north ? f->position
                                         : f->points.isEmpty() ? Feature::Point{} : f->points.first());
    if (!from)
        return false;
    remember();
    f = feature(id);
    const double dLat = lat - from->lat, dLon = lon - from->lon;
    const auto shift = [&](Feature::Point &p) {
        if (const auto was = m_mission.position(p))
            placePoint(p, was->lat + dLat, was->lon + dLon);
    };
    shift(f->position);
    for (Feature::Point &p : f->points)
        shift(p);
    m_modified = true;
    featuresEdited();
    return true;
}

bool PlanEditorModel::moveFeaturePoint(const QString &id, int index, double lat, double lon)
{
    Feature *f = feature(id);
    if (!f || index < 0 || index >= f->points.size() || !isPosition(lat, lon))
        return false;
    remember();
    placePoint(feature(id)->points[index], lat, lon);
    m_modified = true;
    featuresEdited();
    return true;
}

bool PlanEditorModel::insertFeaturePoint(const QString &id, int index, double lat, double lon)
{
    Feature *f = feature(id);
    if (!f || (f->kind != u"path"_s && f->kind != u"polygon"_s) || index < 0 || index >= f->points.size() || !isPosition(lat, lon))
        return false;
    remember();
    feature(id)->points.insert(index + 1, pointAt(lat, lon));
    m_modified = true;
    featuresEdited();
    return true;
}

bool PlanEditorModel::removeFeaturePoint(const QString &id, int index)
{
    Feature *f = feature(id);
    if (!f || index < 0 || index >= f->points.size())
        return false;
    if (f->points.size() <= (f->kind == u"polygon"_s ? 3 : 2)) {
        fail(u"a %1 keeps at least %2 points"_s.arg(f->kind).arg(f->kind == u"polygon"_s ? 3 : 2));
        return false;
    }
    remember();
    feature(id)->points.removeAt(index);
    m_modified = true;
    featuresEdited();
    return true;
}

bool PlanEditorModel::removeFeature(const QString &id)
{
    if (!feature(id))
        return false;
    remember();
    for (Map &map : m_mission.maps)
        map.features.removeIf([&](const Feature &f) { return f.id == id; });
    m_modified = true;
    featuresEdited();
    return true;
}

QVariantList PlanEditorModel::featureProperties(const QString &id) const
{
    QVariantList list;
    const Feature *f = const_cast<PlanEditorModel *>(this)->feature(id);
    if (!f)
        return list;
    for (const PropertySpec &s : propertiesOf(f->kind)) {
        QString value = s.name == u"name"_s ? f->name : s.name == u"color"_s ? f->color : s.name == u"layer"_s ? f->layer
                        : s.name == u"depth"_s ? (f->position.depth ? formatNumber(*f->position.depth) : QString())
                                               : f->attributes.value(s.name);
        list.append(QVariantMap{{u"name"_s, s.name}, {u"value"_s, value}, {u"type"_s, s.type}, {u"choices"_s, s.choices}, {u"unit"_s, s.unit}});
    }
    return list;
}

bool PlanEditorModel::setFeatureProperty(const QString &id, const QString &name, const QString &value)
{
    Feature *f = feature(id);
    if (!f)
        return false;
    const QList<PropertySpec> specs = propertiesOf(f->kind);
    const auto spec = std::find_if(specs.begin(), specs.end(), [&](const PropertySpec &s) { return s.name == name; });
    if (spec == specs.end()) {
        fail(u"a %1 has no property '%2'"_s.arg(f->kind, name));
        return false;
    }
    const QString text = value.trimmed();
    bool number = true;
    const double v = text.toDouble(&number);
    const bool required = name == u"radius"_s || name == u"width"_s || name == u"length"_s || name == u"file"_s;
    if (text.isEmpty() && required) {
        fail(u"%1: a %2 needs one"_s.arg(name, f->kind));
        return false;
    }
    if (!text.isEmpty()) {
        if (spec->type == u"number"_s && (!number || !std::isfinite(v) || (spec->min && v < *spec->min))) {
            fail(spec->min ? u"%1: not a number ≥ %2: '%3'"_s.arg(name).arg(*spec->min).arg(text) : u"%1: not a number: '%2'"_s.arg(name, text));
            return false;
        }
        if (spec->type == u"choice"_s && !spec->choices.contains(text)) {
            fail(u"%1: one of %2, not '%3'"_s.arg(name, spec->choices.join(u", "_s), text));
            return false;
        }
        static const QRegularExpression colour(u"^#[0-9a-fA-F]{6}$"_s);
        if (spec->type == u"color"_s && !colour.match(text).hasMatch()) {
            fail(u"%1: a colour as #rrggbb, not '%2'"_s.arg(name, text));
            return false;
        }
    }
    remember();
    f = feature(id);
    if (name == u"name"_s)
        f->name = text;
    else if (name == u"color"_s)
        f->color = text;
    else if (name == u"layer"_s)
        f->layer = text;
    else if (name == u"depth"_s)
        f->position.depth = text.isEmpty() ? std::nullopt : std::optional(v);
    else if (text.isEmpty())
        f->attributes.remove(name);
    else
        f->attributes.insert(name, text);
    m_modified = true;
    fail({});
    featuresEdited();
    return true;
}

QString PlanEditorModel::freshId(const QString &type) const
{
    const Plan *p = plan();
    const QString stem = type.toLower();
    for (int n = 1;; ++n) {
        const QString id = stem + QString::number(n);
        if (!p || !p->maneuver(id))
            return id;
    }
}

QString PlanEditorModel::addManeuver(const QString &type, double lat, double lon)
{
    Plan *p = editable();
    if (!p) {
        fail(u"no plan is open to add to"_s);
        return {};
    }
    if (!maneuverTypes().contains(type)) {
        fail(u"%1 cannot do %2 (it can: %3)"_s.arg(p->vehicle, type, maneuverTypes().join(u", "_s)));
        return {};
    }
    if (!std::isfinite(lat) || !std::isfinite(lon) || std::abs(lat) > 90 || std::abs(lon) > 180) {
        fail(u"not a position: %1, %2"_s.arg(lat).arg(lon));
        return {};
    }
    remember();
    p = editable();
    Maneuver m;
    m.id = freshId(type);
    m.type = type;
    // A sensible maneuver at once: the vehicle's defaults, else a depth, a speed and IMC's units.
    const QMap<QString, QString> fallback{{u"z"_s, u"2"_s}, {u"z_units"_s, u"DEPTH"_s}, {u"speed"_s, u"1.5"_s}, {u"speed_units"_s, u"METERS_PS"_s}};
    for (auto it = fallback.cbegin(); it != fallback.cend(); ++it)
        m.parameters.insert(it.key(), it.value());
    if (const VehicleDefinition *v = vehicles().find(p->vehicle)) {
        if (const ManeuverSpec *spec = v->maneuver(type)) {
            for (const ParameterSpec &ps : spec->parameters)
                if (!ps.defaultValue.isEmpty())
                    m.parameters.insert(ps.name, ps.defaultValue);
        }
    }
    if (type == u"Loiter"_s || type == u"StationKeeping"_s || type == u"PopUp"_s) {
        m.parameters.insert(u"duration"_s, m.parameters.value(u"duration"_s, u"60"_s));
        m.parameters.insert(u"radius"_s, m.parameters.value(u"radius"_s, u"20"_s));
    }
    if (type == u"CrossHatch"_s) { // Neptus's defaults (RowsPattern.java)
        for (const auto &[name, value] : {std::pair{u"width"_s, u"100"_s}, std::pair{u"hstep"_s, u"27"_s},
                                          std::pair{u"coff"_s, u"15"_s}, std::pair{u"flags"_s, u"SQUARE_CURVE"_s}})
            m.parameters.insert(name, m.parameters.value(name, value));
    }
    m.parameters.insert(u"lat"_s, QString::number(lat, 'f', 8));
    m.parameters.insert(u"lon"_s, QString::number(lon, 'f', 8));
    // After the last maneuver: the one nothing leads on from (the plan's end).
    QString last;
    for (auto it = p->maneuvers.crbegin(); it != p->maneuvers.crend() && last.isEmpty(); ++it) {
        const bool leadsOn = std::any_of(p->transitions.begin(), p->transitions.end(), [&](const Transition &t) { return t.from == it->id; });
        if (!leadsOn)
            last = it->id;
    }
    if (!last.isEmpty())
        p->transitions.append(Transition{last, m.id, u"ManeuverIsDone"_s, {}, {}});
    if (p->start.isEmpty() || !p->maneuver(p->start))
        p->start = m.id;
    p->maneuvers.append(m);
    m_modified = true;
    fail({});
    changed();
    return m.id;
}

bool PlanEditorModel::moveManeuver(const QString &id, double lat, double lon)
{
    if (!find(id) || !std::isfinite(lat) || !std::isfinite(lon) || std::abs(lat) > 90 || std::abs(lon) > 180)
        return false;
    remember();
    Maneuver *m = find(id);
    m->parameters.insert(u"lat"_s, QString::number(lat, 'f', 8));
    m->parameters.insert(u"lon"_s, QString::number(lon, 'f', 8));
    m_modified = true;
    changed();
    return true;
}

bool PlanEditorModel::removeManeuver(const QString &id)
{
    if (!find(id))
        return false;
    remember();
    Plan *p = editable();
    // One in and one out: the plan goes on from the one before to the one after.
    QStringList before, after;
    for (const Transition &t : p->transitions) {
        if (t.to == id && t.from != id)
            before << t.from;
        if (t.from == id && t.to != id)
            after << t.to;
    }
    p->transitions.removeIf([&](const Transition &t) { return t.from == id || t.to == id; });
    if (before.size() == 1 && after.size() == 1)
        p->transitions.append(Transition{before.first(), after.first(), u"ManeuverIsDone"_s, {}, {}});
    p->maneuvers.removeIf([&](const Maneuver &m) { return m.id == id; });
    if (p->start == id)
        p->start = after.size() == 1 ? after.first() : p->maneuvers.isEmpty() ? QString() : p->maneuvers.first().id;
    m_modified = true;
    changed();
    return true;
}

bool PlanEditorModel::setParameter(const QString &id, const QString &name, const QString &value)
{
    if (!find(id) || name.isEmpty() || name == u"id"_s)
        return false;
    if (find(id)->text(name) == value)
        return true;
    remember();
    find(id)->parameters.insert(name, value.trimmed());
    m_modified = true;
    changed();
    return true;
}

QVariantList PlanEditorModel::parametersOf(const QString &id) const
{
    QVariantList list;
    for (const RowModel::Row &row : parameterRows(id))
        list.append(m_parameters->map(row));
    return list;
}

QList<RowModel::Row> PlanEditorModel::parameterRows(const QString &id) const
{
    QList<RowModel::Row> list;
    const Plan *p = plan();
    const Maneuver *m = p ? p->maneuver(id) : nullptr;
    if (!m)
        return list;
    const VehicleDefinition *v = vehicles().find(p->vehicle);
    const ManeuverSpec *spec = v ? v->maneuver(m->type) : nullptr;
    const QStringList problems = v ? v->checkManeuver(*m) : QStringList();
    const double none = std::numeric_limits<double>::quiet_NaN();
    const auto problemOf = [&](const QString &name) {
        for (const QString &what : problems)
            if (what.startsWith(name + u' '))
                return what;
        return QString();
    };
    QStringList listed;
    if (spec) {
        for (const ParameterSpec &ps : spec->parameters) {
            list.append(RowModel::Row{ps.name, m->text(ps.name, ps.defaultValue), ps.unit, ps.type, ps.min.value_or(none),
                                      ps.max.value_or(none), ps.values, problemOf(ps.name)});
            listed << ps.name;
        }
    }
    for (auto it = m->parameters.cbegin(); it != m->parameters.cend(); ++it) {
        if (listed.contains(it.key()))
            continue;
        list.append(RowModel::Row{it.key(), it.value(), QString(), u"text"_s, none, none, QStringList(), problemOf(it.key())});
    }
    return list;
}

QString PlanEditorModel::addRows(const QVariantList &area, double spacing, double angle, double overshoot, bool crossHatch)
{
    Plan *p = editable();
    if (!p) {
        fail(u"no plan is open to add to"_s);
        return {};
    }
    auto rows = rowsOver(latLons(area), {spacing, angle, overshoot, crossHatch}, {}, {});
    if (!rows) {
        fail(rows.error());
        return {};
    }
    return addPattern(*rows);
}

QString PlanEditorModel::addPattern(const Maneuver &made)
{
    // Placed like any maneuver (after the last), then given the path.
    const QString id = addManeuver(u"FollowPath"_s, made.number(u"lat"_s), made.number(u"lon"_s));
    if (id.isEmpty())
        return {};
    find(id)->points = made.points;
    changed();
    return id;
}

QString PlanEditorModel::addPathAlong(const QVariantList &line)
{
    if (!editable()) {
        fail(u"no plan is open to add to"_s);
        return {};
    }
    auto path = pathAlong(latLons(line), {}, {});
    if (!path) {
        fail(path.error());
        return {};
    }
    return addPattern(*path);
}

const std::optional<neptus::scripting::CompileError> &PlanEditorModel::conditionProblem(const QString &condition) const
{
    auto it = m_conditionChecks.constFind(condition);
    if (it == m_conditionChecks.cend())
        it = m_conditionChecks.insert(condition, neptus::plans::Supervisor::conditionProblem(condition));
    return *it;
}

QVariantMap PlanEditorModel::checkCondition(const QString &condition) const
{
    const auto &problem = conditionProblem(condition);
    if (!problem)
        return {{u"ok"_s, true}, {u"line"_s, 0}, {u"column"_s, 0}, {u"message"_s, QString()}};
    return {{u"ok"_s, false}, {u"line"_s, problem->line}, {u"column"_s, problem->column}, {u"message"_s, problem->message}};
}

QVariantList PlanEditorModel::nodes() const
{
    QVariantList list;
    const Plan *p = plan();
    if (!p)
        return list;
    // Columns by steps from the start (breadth first); what the start does
    // not reach goes after, each unreached maneuver starting its own walk.
    QHash<QString, int> column;
    QHash<QString, QStringList> next;
    for (const Transition &t : p->transitions)
        next[t.from] << t.to;
    int firstFree = 0;
    const auto walk = [&](const QString &from) {
        QList<QString> queue{from};
        column.insert(from, firstFree);
        for (qsizetype i = 0; i < queue.size(); ++i) {
            const int c = column.value(queue[i]);
            firstFree = std::max(firstFree, c + 1);
            for (const QString &to : next.value(queue[i])) {
                if (!column.contains(to) && p->maneuver(to)) {
                    column.insert(to, c + 1);
                    queue << to;
                }
            }
        }
    };
    if (p->maneuver(p->start))
        walk(p->start);
    for (const Maneuver &m : p->maneuvers)
        if (!column.contains(m.id))
            walk(m.id);
    QHash<int, int> rows;
    for (const QVariant &v : maneuvers()) {
        QVariantMap node = v.toMap();
        const QString id = node.value(u"id"_s).toString();
        const int c = column.value(id);
        node.insert(u"column"_s, c);
        node.insert(u"row"_s, rows[c]++);
        node.insert(u"start"_s, id == p->start);
        list.append(node);
    }
    return list;
}

QVariantList PlanEditorModel::transitions() const
{
    QVariantList list;
    const Plan *p = plan();
    if (!p)
        return list;
    for (qsizetype i = 0; i < p->transitions.size(); ++i) {
        const Transition &t = p->transitions[i];
        const bool plain = neptus::plans::Supervisor::plain(t);
        const auto &problem = plain ? std::optional<neptus::scripting::CompileError>() : conditionProblem(t.condition);
        list.append(QVariantMap{{u"index"_s, int(i)}, {u"from"_s, t.from}, {u"to"_s, t.to}, {u"condition"_s, t.condition},
                                {u"plain"_s, plain}, {u"problem"_s, problem ? problem->message : QString()},
                                {u"line"_s, problem ? problem->line : 0}, {u"column"_s, problem ? problem->column : 0}});
    }
    return list;
}

bool PlanEditorModel::addTransition(const QString &from, const QString &to, const QString &condition)
{
    const Plan *p = plan();
    if (!p || !p->maneuver(from) || !p->maneuver(to)) {
        fail(u"no maneuver %1 or %2 in the plan"_s.arg(from, to));
        return false;
    }
    remember();
    editable()->transitions.append(Transition{from, to, condition.trimmed().isEmpty() ? u"ManeuverIsDone"_s : condition.trimmed(), {}, {}});
    m_modified = true;
    fail({});
    changed();
    return true;
}

bool PlanEditorModel::setCondition(int transition, const QString &condition)
{
    const Plan *p = plan();
    if (!p || transition < 0 || transition >= p->transitions.size())
        return false;
    const QString text = condition.trimmed().isEmpty() ? u"ManeuverIsDone"_s : condition.trimmed();
    if (p->transitions[transition].condition == text)
        return true;
    remember();
    editable()->transitions[transition].condition = text;
    m_modified = true;
    changed();
    return true;
}

bool PlanEditorModel::removeTransition(int transition)
{
    const Plan *p = plan();
    if (!p || transition < 0 || transition >= p->transitions.size())
        return false;
    remember();
    editable()->transitions.removeAt(transition);
    m_modified = true;
    changed();
    return true;
}

bool PlanEditorModel::setStart(const QString &id)
{
    const Plan *p = plan();
    if (!p || !p->maneuver(id))
        return false;
    if (p->start == id)
        return true;
    remember();
    editable()->start = id;
    m_modified = true;
    changed();
    return true;
}

QVariantList PlanEditorModel::checklistItems() const
{
    QVariantList items;
    const double none = std::numeric_limits<double>::quiet_NaN();
    for (qsizetype l = 0; l < m_mission.checklists.size(); ++l) {
        const Checklist &list = m_mission.checklists[l];
        for (qsizetype g = 0; g < list.groups.size(); ++g) {
            for (qsizetype i = 0; i < list.groups[g].items.size(); ++i) {
                const ChecklistItem &item = list.groups[g].items[i];
                items.append(QVariantMap{{u"list"_s, int(l)}, {u"group"_s, int(g)}, {u"item"_s, int(i)},
                                         {u"checklist"_s, list.name.isEmpty() ? list.id : list.name}, {u"groupName"_s, list.groups[g].name},
                                         {u"text"_s, item.text}, {u"note"_s, item.note}, {u"variable"_s, item.variable},
                                         {u"min"_s, item.min.value_or(none)}, {u"max"_s, item.max.value_or(none)}});
            }
        }
    }
    return items;
}

bool PlanEditorModel::addChecklistItem(const QString &text)
{
    if (text.trimmed().isEmpty()) {
        fail(u"a checklist item needs its text"_s);
        return false;
    }
    if (m_path.isEmpty()) {
        fail(u"no mission is open to add to"_s);
        return false;
    }
    remember();
    if (m_mission.checklists.isEmpty())
        m_mission.checklists.append(Checklist{u"checks"_s, u"Checks"_s, {}});
    Checklist &list = m_mission.checklists.first();
    if (list.groups.isEmpty())
        list.groups.append({u"General"_s, {}});
    ChecklistItem item;
    item.text = text.trimmed();
    list.groups.last().items.append(item);
    m_modified = true;
    fail({});
    checklistsEdited();
    return true;
}

bool PlanEditorModel::setChecklistItem(int list, int group, int item, const QString &field, const QString &value)
{
    if (list < 0 || list >= m_mission.checklists.size() || group < 0 || group >= m_mission.checklists[list].groups.size()
        || item < 0 || item >= m_mission.checklists[list].groups[group].items.size())
        return false;
    const QString text = value.trimmed();
    std::optional<double> number;
    if (field == u"min"_s || field == u"max"_s) {
        bool ok = true;
        const double v = text.toDouble(&ok);
        if (!text.isEmpty() && (!ok || !std::isfinite(v))) {
            fail(u"%1: not a number: '%2'"_s.arg(field, text));
            return false;
        }
        if (!text.isEmpty())
            number = v;
    } else if (field == u"text"_s && text.isEmpty()) {
        fail(u"a checklist item needs its text"_s);
        return false;
    } else if (field != u"text"_s && field != u"note"_s && field != u"variable"_s) {
        fail(u"a checklist item has no field '%1'"_s.arg(field));
        return false;
    }
    remember();
    ChecklistItem &i = m_mission.checklists[list].groups[group].items[item];
    if (field == u"text"_s)
        i.text = text;
    else if (field == u"note"_s)
        i.note = text;
    else if (field == u"variable"_s)
        i.variable = text;
    else if (field == u"min"_s)
        i.min = number;
    else
        i.max = number;
    m_modified = true;
    fail({});
    checklistsEdited();
    return true;
}

bool PlanEditorModel::removeChecklistItem(int list, int group, int item)
{
    if (list < 0 || list >= m_mission.checklists.size() || group < 0 || group >= m_mission.checklists[list].groups.size()
        || item < 0 || item >= m_mission.checklists[list].groups[group].items.size())
        return false;
    remember();
    m_mission.checklists[list].groups[group].items.removeAt(item);
    m_modified = true;
    checklistsEdited();
    return true;
}

QVariantList PlanEditorModel::exportTargets() const
{
    QVariantList list;
    if (const VehicleDefinition *v = vehicles().find(vehicle()))
        for (const Translation &t : v->translations)
            list.append(QVariantMap{{u"target"_s, t.target}, {u"name"_s, t.name}, {u"extension"_s, t.extension}});
    return list;
}

bool PlanEditorModel::exportPlan(const QString &target)
{
    const Plan *p = plan();
    const VehicleDefinition *v = p ? vehicles().find(p->vehicle) : nullptr;
    const Translation *t = v ? v->translation(target) : nullptr;
    if (!t) {
        fail(u"%1 has no translation to '%2'"_s.arg(p ? p->vehicle : u"no plan"_s, target));
        return false;
    }
    if (m_export.value(u"busy"_s).toBool()) {
        fail(u"an export is under way"_s);
        return false;
    }
    if (errorCount() > 0) {
        fail(u"%1 has errors: mend them before exporting it (the problems list)"_s.arg(p->id));
        return false;
    }
    const QString path = QFileInfo(m_path).absoluteDir().filePath(p->id + u'.' + (t->extension.isEmpty() ? u"txt"_s : t->extension));
    m_export = {{u"busy"_s, true}, {u"target"_s, target}, {u"step"_s, 1}, {u"steps"_s, 3}, {u"what"_s, u"checking the plan"_s},
                {u"path"_s, QString()}, {u"error"_s, QString()}, {u"started"_s, QDateTime::currentMSecsSinceEpoch()}};
    emit exportChanged();
    fail({});
    // On a worker: a 10,000-maneuver plan takes seconds in the helper.
    const QPointer<PlanEditorModel> self(this);
    const auto step = [self](QVariantMap changes) {
        QMetaObject::invokeMethod(self.data(), [self, changes] {
            if (!self)
                return;
            for (auto it = changes.cbegin(); it != changes.cend(); ++it)
                self->m_export.insert(it.key(), it.value());
            emit self->exportChanged();
        }, Qt::QueuedConnection);
    };
    QThreadPool::globalInstance()->start([mission = m_mission, planId = p->id, vehicle = *v, target, path, step] {
        step({{u"step"_s, 2}, {u"what"_s, u"translating (the mission processor)"_s}});
        auto made = neptus::processor::translatePlan(mission, planId, vehicle, target);
        if (!made) {
            QStringList lines;
            for (const auto &e : made.error())
                lines << e.toString();
            step({{u"busy"_s, false}, {u"error"_s, lines.join(u'\n')}});
            return;
        }
        step({{u"step"_s, 3}, {u"what"_s, u"writing %1"_s.arg(path)}});
        if (auto saved = neptus::saveFileKeepingPrevious(path, *made); !saved) {
            step({{u"busy"_s, false}, {u"error"_s, saved.error()}});
            return;
        }
        step({{u"busy"_s, false}, {u"path"_s, path}, {u"what"_s, u"%1 bytes"_s.arg(made->size())}});
    });
    return true;
}

bool PlanEditorModel::undo()
{
    if (m_undo.isEmpty())
        return false;
    m_redo.append(m_mission);
    restore(m_undo.takeLast());
    return true;
}

bool PlanEditorModel::redo()
{
    if (m_redo.isEmpty())
        return false;
    m_undo.append(m_mission);
    restore(m_redo.takeLast());
    return true;
}

void PlanEditorModel::restore(Mission mission)
{
    // Only what differs is worked out again. Parts the edit did not touch
    // are still shared with the snapshot, and comparing those is a pointer test.
    const Mission before = std::exchange(m_mission, std::move(mission));
    m_modified = true;
    if (before.maps != m_mission.maps)
        featuresEdited();
    else
        changed();
    if (before.checklists != m_mission.checklists)
        emit checklistsChanged();
    const auto others = [this](const Mission &m) {
        QList<Plan> list;
        for (const Plan &p : m.plans)
            if (p.id != m_planId)
                list << p;
        return list;
    };
    if (others(before) != others(m_mission)) // undoing another console's change
        otherPlansAgain();
}

bool PlanEditorModel::saveAs(const QString &path)
{
    if (path.isEmpty() || QFileInfo(path).isDir()) {
        fail(u"no mission file to save to"_s);
        return false;
    }
    if (auto saved = neptus::saveFileKeepingPrevious(path, writeMission(m_mission)); !saved) {
        fail(saved.error());
        return false;
    }
    const bool moved = path != m_path;
    m_path = path;
    m_modified = false;
    fail({});
    if (moved)
        emit missionChanged();
    emit edited();
    return true;
}

QStringList PlanEditorModel::knownVehicles() const
{
    QStringList ids;
    for (const VehicleDefinition &v : vehicles().vehicles)
        ids << v.id;
    std::sort(ids.begin(), ids.end());
    return ids;
}

QVariantMap PlanEditorModel::exportNeptus(const QString &path)
{
    const auto exported = neptus::mission::exportNeptus(m_mission, m_path);
    QString message;
    if (exported) {
        if (auto saved = neptus::saveFileKeepingPrevious(path, exported->nmisz); !saved)
            return {{u"ok"_s, false}, {u"message"_s, saved.error()}};
        QStringList lost;
        for (const auto &w : exported->warnings)
            lost << w.toString();
        message = lost.isEmpty() ? u"Written for Neptus: %1"_s.arg(QFileInfo(path).fileName())
                                 : u"Written for Neptus: %1; %2 thing(s) Neptus has no words for: %3"_s
                                       .arg(QFileInfo(path).fileName()).arg(lost.size()).arg(lost.mid(0, 3).join(u"; "_s));
        return {{u"ok"_s, true}, {u"message"_s, message}};
    }
    for (const auto &e : exported.error())
        message += (message.isEmpty() ? QString() : u"; "_s) + e.toString();
    return {{u"ok"_s, false}, {u"message"_s, message}};
}

bool PlanEditorModel::save()
{
    return saveAs(m_path);
}
