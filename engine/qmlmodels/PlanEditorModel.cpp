#include "PlanEditorModel.h"

#include "core/SafeFile.h"
#include "mission/MissionXml.h"
#include "mission/Patterns.h"
#include "plans/Supervisor.h"

#include <QFileInfo>

#include <cmath>
#include <limits>

using namespace neptus::mission;
using namespace Qt::StringLiterals;

namespace {

// What an editor may add to a plan of a vehicle with no definition.
const QStringList knownTypes{u"Goto"_s, u"Loiter"_s, u"StationKeeping"_s, u"Rows"_s, u"YoYo"_s, u"FollowPath"_s,
                             u"ExpandingSquare"_s, u"PopUp"_s, u"Elevator"_s};

// Undo keeps this many edits.
constexpr qsizetype undoDepth = 200;

QString severityName(PlanProblem::Severity s) { return s == PlanProblem::Severity::Error ? u"error"_s : u"warning"_s; }

} // namespace

PlanEditorModel::PlanEditorModel(QObject *parent) : QObject(parent), m_vehicles(loadVehicles(vehicleFolders())) {}

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
    changed();
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
    const VehicleDefinition *v = m_vehicles.find(vehicle());
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
    if (const Plan *p = plan()) {
        m_undo.append(*p);
        if (m_undo.size() > undoDepth)
            m_undo.removeFirst();
        m_redo.clear();
    }
}

void PlanEditorModel::changed()
{
    m_pathPoints.clear();
    m_problems.clear();
    m_geometry = {};
    if (const Plan *p = plan()) {
        const VehicleDefinition *v = m_vehicles.find(p->vehicle);
        m_geometry = planGeometry(*p, v ? v->speeds() : SpeedModel{});
        m_problems = checkPlan(*p, m_mission, m_geometry, v);
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
        for (const ManeuverGeometry &g : m_geometry.maneuvers) {
            for (const Waypoint &w : g.points) {
                along += w.leg;
                m_pathPoints.append(QVariantMap{{u"lat"_s, w.lat}, {u"lon"_s, w.lon}, {u"maneuver"_s, g.id},
                                                {u"distance"_s, along}, {u"z"_s, w.z}, {u"zUnits"_s, w.zUnits}});
            }
        }
    }
    m_maneuverList = maneuverList();
    m_problemList = problemList();
    emit edited();
}

QVariantList PlanEditorModel::maneuverList() const
{
    QVariantList list;
    const Plan *p = plan();
    if (!p)
        return list;
    QHash<QString, QString> worst;
    for (const PlanProblem &problem : m_problems) {
        if (!problem.maneuver.isEmpty() && !worst.contains(problem.maneuver))
            worst.insert(problem.maneuver, severityName(problem.severity)); // worst first
    }
    for (qsizetype i = 0; i < p->maneuvers.size(); ++i) {
        const Maneuver &m = p->maneuvers[i];
        list.append(QVariantMap{{u"id"_s, m.id}, {u"type"_s, m.type}, {u"lat"_s, m.number(u"lat"_s)}, {u"lon"_s, m.number(u"lon"_s)},
                                {u"index"_s, int(i)}, {u"severity"_s, worst.value(m.id)}});
    }
    return list;
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

QVariantList PlanEditorModel::areas() const
{
    QVariantList list;
    for (const Map &map : m_mission.maps) {
        for (const Feature &f : map.features) {
            QVariantList points;
            for (const GeoPosition &p : areaOutline(f, m_mission))
                points.append(QVariantMap{{u"lat"_s, p.lat}, {u"lon"_s, p.lon}});
            if (points.size() >= 3)
                list.append(QVariantMap{{u"id"_s, f.id}, {u"name"_s, f.name}, {u"role"_s, f.attributes.value(u"role"_s, u"area"_s)},
                                        {u"points"_s, points}});
        }
    }
    return list;
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
    if (const VehicleDefinition *v = m_vehicles.find(p->vehicle)) {
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
    const Plan *p = plan();
    const Maneuver *m = p ? p->maneuver(id) : nullptr;
    if (!m)
        return list;
    const VehicleDefinition *v = m_vehicles.find(p->vehicle);
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
            list.append(QVariantMap{{u"name"_s, ps.name}, {u"value"_s, m->text(ps.name, ps.defaultValue)}, {u"unit"_s, ps.unit},
                                    {u"type"_s, ps.type}, {u"min"_s, ps.min.value_or(none)}, {u"max"_s, ps.max.value_or(none)},
                                    {u"values"_s, ps.values}, {u"problem"_s, problemOf(ps.name)}});
            listed << ps.name;
        }
    }
    for (auto it = m->parameters.cbegin(); it != m->parameters.cend(); ++it) {
        if (listed.contains(it.key()))
            continue;
        list.append(QVariantMap{{u"name"_s, it.key()}, {u"value"_s, it.value()}, {u"unit"_s, QString()}, {u"type"_s, u"text"_s},
                                {u"min"_s, none}, {u"max"_s, none}, {u"values"_s, QStringList()}, {u"problem"_s, problemOf(it.key())}});
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
    QList<LatLon> corners;
    for (const QVariant &v : area) {
        const QVariantMap c = v.toMap();
        corners.append({c.value(u"lat"_s).toDouble(), c.value(u"lon"_s).toDouble()});
    }
    auto rows = rowsOver(corners, {spacing, angle, overshoot, crossHatch}, {}, {});
    if (!rows) {
        fail(rows.error());
        return {};
    }
    // Placed like any maneuver (after the last), then given the path.
    const QString id = addManeuver(u"FollowPath"_s, rows->number(u"lat"_s), rows->number(u"lon"_s));
    if (id.isEmpty())
        return {};
    Maneuver *m = find(id);
    m->points = rows->points;
    changed();
    return id;
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
    for (const QVariant &v : m_maneuverList) {
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

bool PlanEditorModel::undo()
{
    Plan *p = editable();
    if (!p || m_undo.isEmpty())
        return false;
    m_redo.append(*p);
    *p = m_undo.takeLast();
    m_modified = true;
    changed();
    return true;
}

bool PlanEditorModel::redo()
{
    Plan *p = editable();
    if (!p || m_redo.isEmpty())
        return false;
    m_undo.append(*p);
    *p = m_redo.takeLast();
    m_modified = true;
    changed();
    return true;
}

bool PlanEditorModel::save()
{
    if (m_path.isEmpty()) {
        fail(u"no mission file to save to"_s);
        return false;
    }
    if (auto saved = neptus::saveFileKeepingPrevious(m_path, writeMission(m_mission)); !saved) {
        fail(saved.error());
        return false;
    }
    m_modified = false;
    fail({});
    emit edited();
    return true;
}
