#include "PlanCheck.h"

#include "geo/Geodesy.h"
#include "geo/Polygon.h"
#include "mission/Vehicle.h"

#include <QHash>
#include <QSet>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

using namespace Qt::StringLiterals;

namespace neptus::mission {

namespace {

using Vec = Eigen::Vector2d; // metres north (x) and east (y) of the check's origin

// A no-go or operating area on the plane: a polygon (circles, boxes and
// ellipses made into one), with the depth or height range it holds.
struct Area
{
    QString id, name;
    std::vector<Vec> outline;
    std::optional<double> zMin, zMax;
    QString zUnits;
    Vec lo{0, 0}, hi{0, 0}; // its bounding box: most legs are nowhere near most areas

    void bound()
    {
        lo = hi = outline.front();
        for (const Vec &v : outline) {
            lo = lo.cwiseMin(v);
            hi = hi.cwiseMax(v);
        }
    }
    bool near(const Vec &p, const Vec &q) const
    {
        return std::max(p.x(), q.x()) >= lo.x() && std::min(p.x(), q.x()) <= hi.x() && std::max(p.y(), q.y()) >= lo.y()
               && std::min(p.y(), q.y()) <= hi.y();
    }
    QString label() const { return name.isEmpty() || name == id ? u"'%1'"_s.arg(id) : u"'%1' (%2)"_s.arg(id, name); }

    bool contains(const Vec &p) const
    {
        return near(p, p) && geo::insideRing(outline, p.x(), p.y(), [](const Vec &v) { return std::pair(v.x(), v.y()); });
    }
    // Where the segment first crosses the outline, as a fraction along it.
    std::optional<double> firstCrossing(const Vec &p, const Vec &q) const
    {
        std::optional<double> first;
        if (!near(p, q))
            return first;
        const Vec d = q - p;
        for (size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++) {
            const Vec &a = outline[j], e = outline[i] - outline[j];
            const double den = d.x() * e.y() - d.y() * e.x();
            if (std::abs(den) < 1e-12)
                continue; // parallel
            const Vec w = a - p;
            const double t = (w.x() * e.y() - w.y() * e.x()) / den, u = (w.x() * d.y() - w.y() * d.x()) / den;
            if (t >= 0 && t <= 1 && u >= 0 && u <= 1 && (!first || t < *first))
                first = t;
        }
        return first;
    }
    // Whether a leg between depths (or heights) z1 and z2 in `units` passes through the area's range.
    bool holdsZ(double z1, double z2, const QString &units) const
    {
        if (!zMin && !zMax)
            return true;
        if (units != zUnits)
            return true; // not comparable: assume it does
        const double lo = std::min(z1, z2), hi = std::max(z1, z2);
        return !(zMax && lo > *zMax) && !(zMin && hi < *zMin);
    }
};

std::optional<double> number(const Feature &f, const QString &name)
{
    bool ok = false;
    const double v = f.attributes.value(name).toDouble(&ok);
    return ok && std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

// The local tangent plane at the plan's first point (exact, through ECEF:
// the rotation and the origin worked out once, as thousands of points go through).
struct Plane
{
    geo::Geodetic origin;
    Eigen::Vector3d originEcef;
    Eigen::Matrix3d rotation;

    explicit Plane(const geo::Geodetic &origin) : origin(origin), originEcef(geo::toEcef(origin)), rotation(geo::ecefToNed(origin)) {}
    Vec toPlane(double lat, double lon) const
    {
        const Eigen::Vector3d ned = rotation * (geo::toEcef({geo::radians(lat), geo::radians(lon), 0}) - originEcef);
        return {ned.x(), ned.y()};
    }
    std::pair<double, double> toGeo(const Vec &v) const
    {
        const geo::Geodetic g = geo::fromNed({v.x(), v.y(), 0}, origin);
        return {geo::degrees(g.lat), geo::degrees(g.lon)};
    }
};

// The mission's areas of a role, on the plane.
std::vector<Area> areas(const Mission &mission, const QString &role, const Plane &plane)
{
    std::vector<Area> out;
    for (const Map &map : mission.maps) {
        for (const Feature &f : map.features) {
            if (f.attributes.value(u"role"_s, u"area"_s) != role)
                continue;
            Area a{f.id, f.name, {}, number(f, u"z-min"_s), number(f, u"z-max"_s), f.attributes.value(u"z-units"_s)};
            for (const GeoPosition &p : areaOutline(f, mission))
                a.outline.push_back(plane.toPlane(p.lat, p.lon));
            if (a.outline.size() >= 3) {
                a.bound();
                out.push_back(std::move(a));
            }
        }
    }
    return out;
}

} // namespace

QList<GeoPosition> areaOutline(const Feature &f, const Mission &mission)
{
    QList<GeoPosition> outline;
    if (f.kind == u"polygon") {
        for (const Feature::Point &p : f.points)
            if (const auto at = mission.position(p))
                outline.append(*at);
        return outline;
    }
    const bool round = f.kind == u"circle" || f.kind == u"cylinder" || f.kind == u"ellipsoid";
    const auto centre = mission.position(f.position);
    if (!centre || !(round || f.kind == u"box"))
        return outline;
    // Metres east and north of the centre, before the turn by bearing.
    const double halfEast = f.kind == u"circle" ? number(f, u"radius"_s).value_or(0) : number(f, u"width"_s).value_or(0) / 2;
    const double halfNorth = f.kind == u"circle" ? halfEast : number(f, u"length"_s).value_or(0) / 2;
    std::vector<Vec> corners; // (north, east)
    if (round) {
        for (int i = 0; i < 64; ++i) { // within 0.12 % of the radius
            const double a = 2 * std::numbers::pi * i / 64;
            corners.emplace_back(std::cos(a) * halfNorth, std::sin(a) * halfEast);
        }
    } else {
        corners = {{halfNorth, halfEast}, {-halfNorth, halfEast}, {-halfNorth, -halfEast}, {halfNorth, -halfEast}};
    }
    const double turn = geo::radians(number(f, u"bearing"_s).value_or(0));
    const geo::Geodetic origin{geo::radians(centre->lat), geo::radians(centre->lon), 0};
    for (const Vec &c : corners) {
        const double n = c.x() * std::cos(turn) - c.y() * std::sin(turn), e = c.x() * std::sin(turn) + c.y() * std::cos(turn);
        const geo::Geodetic at = geo::fromNed({n, e, 0}, origin);
        outline.append({geo::degrees(at.lat), geo::degrees(at.lon), 0});
    }
    return outline;
}

namespace {

struct Leg
{
    const ManeuverGeometry *maneuver;
    Vec from, to;
    double zFrom, zTo;
    QString zUnits;
};

} // namespace

QString PlanProblem::verdict() const
{
    if (severity != Severity::Error)
        return {};
    static const QList<Kind> unsafe{Kind::NoGo, Kind::OutsideOperatingArea, Kind::BelowBottom, Kind::ChartLand,
                                    Kind::ChartShallow, Kind::ChartHazard};
    return unsafe.contains(kind) ? u"unsafe"_s : u"impossible"_s;
}

QList<PlanProblem> checkPlan(const Plan &plan, const Mission &mission, const PlanGeometry &geometry,
                             const VehicleDefinition *vehicle)
{
    QList<PlanProblem> problems;
    QHash<QString, qsizetype> order; // maneuver id -> index in the plan
    for (qsizetype i = 0; i < plan.maneuvers.size(); ++i)
        order.insert(plan.maneuvers[i].id, i);
    QHash<QString, const ManeuverGeometry *> geometryOf;
    for (const ManeuverGeometry &g : geometry.maneuvers)
        geometryOf.insert(g.id, &g);
    const auto add = [&](PlanProblem::Severity severity, PlanProblem::Kind kind, const QString &maneuver, const QString &message) -> PlanProblem & {
        PlanProblem p{severity, kind, maneuver, message, std::nullopt, std::nullopt, plan.line.value};
        if (const auto m = order.constFind(maneuver); m != order.cend())
            p.line = plan.maneuvers[*m].line.value;
        if (const ManeuverGeometry *g = geometryOf.value(maneuver); g && !g->points.isEmpty()) {
            p.lat = g->points.first().lat;
            p.lon = g->points.first().lon;
        }
        problems.append(p);
        return problems.last();
    };
    using Severity = PlanProblem::Severity;
    using Kind = PlanProblem::Kind;

    // The graph: a start, transitions between maneuvers the plan has, every
    // maneuver reachable, and a way out of every loop.
    if (plan.maneuvers.isEmpty()) {
        add(Severity::Error, Kind::NoStart, {}, u"plan '%1' has no maneuvers"_s.arg(plan.id));
    } else if (!order.contains(plan.start)) {
        add(Severity::Error, Kind::NoStart, {},
            plan.start.isEmpty() ? u"plan '%1' has no start maneuver"_s.arg(plan.id)
                                 : u"plan '%1' starts at '%2', which it does not have"_s.arg(plan.id, plan.start));
    }
    std::vector<std::vector<qsizetype>> next(size_t(plan.maneuvers.size()));
    for (const Transition &t : plan.transitions) {
        const auto from = order.constFind(t.from), to = order.constFind(t.to);
        if (from == order.cend() || to == order.cend()) {
            add(Severity::Error, Kind::UnknownManeuver, from != order.cend() ? t.from : QString(),
                u"a transition goes from '%1' to '%2', and the plan has no '%3'"_s.arg(t.from, t.to, from == order.cend() ? t.from : t.to))
                .line = t.line.value;
            continue;
        }
        next[size_t(*from)].push_back(*to);
    }
    if (order.contains(plan.start)) {
        std::vector<bool> reached(next.size(), false);
        std::vector<qsizetype> stack{order.value(plan.start)};
        reached[size_t(stack.back())] = true;
        while (!stack.empty()) {
            const qsizetype at = stack.back();
            stack.pop_back();
            for (qsizetype to : next[size_t(at)]) {
                if (!reached[size_t(to)]) {
                    reached[size_t(to)] = true;
                    stack.push_back(to);
                }
            }
        }
        for (size_t i = 0; i < reached.size(); ++i) {
            if (!reached[i]) {
                const Maneuver &m = plan.maneuvers[qsizetype(i)];
                add(Severity::Warning, Kind::Unreachable, m.id, u"'%1' (%2) cannot be reached from the start '%3'"_s.arg(m.id, m.type, plan.start));
            }
        }
        // Loops with no way out (Tarjan's strongly connected components, iteratively).
        const size_t n = next.size();
        std::vector<int> index(n, -1), low(n, 0), component(n, -1);
        std::vector<bool> onStack(n, false);
        std::vector<size_t> sccStack;
        int counter = 0, components = 0;
        for (size_t root = 0; root < n; ++root) {
            if (index[root] >= 0 || !reached[root])
                continue;
            std::vector<std::pair<size_t, size_t>> work{{root, 0}};
            while (!work.empty()) {
                auto &[v, edge] = work.back();
                if (edge == 0 && index[v] < 0) {
                    index[v] = low[v] = counter++;
                    sccStack.push_back(v);
                    onStack[v] = true;
                }
                if (edge < next[v].size()) {
                    const size_t w = size_t(next[v][edge++]);
                    if (index[w] < 0)
                        work.push_back({w, 0});
                    else if (onStack[w])
                        low[v] = std::min(low[v], index[w]);
                    continue;
                }
                if (low[v] == index[v]) {
                    size_t w;
                    do {
                        w = sccStack.back();
                        sccStack.pop_back();
                        onStack[w] = false;
                        component[w] = components;
                    } while (w != v);
                    ++components;
                }
                const size_t done = v;
                work.pop_back();
                if (!work.empty())
                    low[work.back().first] = std::min(low[work.back().first], low[done]);
            }
        }
        std::vector<std::vector<size_t>> members(static_cast<size_t>(components));
        std::vector<bool> leaves(static_cast<size_t>(components), false), cyclic(static_cast<size_t>(components), false);
        for (size_t v = 0; v < n; ++v) {
            if (component[v] < 0)
                continue;
            members[size_t(component[v])].push_back(v);
            for (qsizetype w : next[v]) {
                if (component[size_t(w)] != component[v])
                    leaves[size_t(component[v])] = true;
                else
                    cyclic[size_t(component[v])] = true; // an edge inside: a self-loop or a cycle
            }
        }
        for (size_t c = 0; c < members.size(); ++c) {
            if (!cyclic[c] || leaves[c])
                continue;
            std::sort(members[c].begin(), members[c].end());
            QStringList ids;
            for (size_t v : members[c])
                ids << plan.maneuvers[qsizetype(v)].id;
            add(Severity::Warning, Kind::EndlessLoop, ids.first(),
                u"%1 lead only to each other: the plan never ends by itself"_s.arg(ids.size() == 1 ? u"'%1'"_s.arg(ids.first())
                                                                                                    : ids.join(u" → "_s)));
        }
    }

    // Kept from another console's mission, run by no vehicle here.
    for (const Maneuver &m : plan.maneuvers)
        if (m.type == u"Unsupported")
            add(Severity::Error, Kind::Vehicle, m.id, u"'%1' (%2): %3"_s.arg(m.id, m.text(u"kind"_s),
                                                                         m.text(u"reason"_s, u"no vehicle here executes it"_s)));

    // The vehicle: maneuvers and parameters, and how long it can go.
    if (vehicle) {
        for (const Maneuver &m : plan.maneuvers) {
            for (const QString &what : vehicle->checkManeuver(m))
                add(Severity::Error, Kind::Vehicle, m.id, u"'%1' (%2): %3"_s.arg(m.id, m.type, what));
        }
        if (const QString past = vehicle->checkEndurance(plan.id, geometry); !past.isEmpty())
            add(Severity::Warning, Kind::Endurance, {}, past);
    }

    // Where it goes: every leg, the transits between maneuvers included,
    // against the no-go areas and inside the operating areas.
    const Waypoint *first = nullptr;
    for (const ManeuverGeometry &g : geometry.maneuvers) {
        if (!g.points.isEmpty()) {
            first = &g.points.first();
            break;
        }
    }
    if (first) {
        const Plane plane({geo::radians(first->lat), geo::radians(first->lon), 0});
        const std::vector<Area> noGo = areas(mission, u"no-go"_s, plane), operating = areas(mission, u"operating-area"_s, plane);
        if (!noGo.empty() || !operating.empty()) {
            std::vector<Leg> legs;
            const Waypoint *previous = nullptr;
            for (const ManeuverGeometry &g : geometry.maneuvers) {
                for (const Waypoint &w : g.points) {
                    if (previous)
                        legs.push_back({&g, plane.toPlane(previous->lat, previous->lon), plane.toPlane(w.lat, w.lon), previous->z, w.z, w.zUnits});
                    else
                        legs.push_back({&g, plane.toPlane(w.lat, w.lon), plane.toPlane(w.lat, w.lon), w.z, w.z, w.zUnits});
                    previous = &w;
                }
            }
            QSet<QString> said; // one problem per maneuver and area
            const auto mark = [&](PlanProblem &p, const Vec &where) {
                const auto [lat, lon] = plane.toGeo(where);
                p.lat = lat;
                p.lon = lon;
            };
            for (const Leg &leg : legs) {
                const QString &id = leg.maneuver->id;
                const QString what = u"'%1' (%2)"_s.arg(id, leg.maneuver->type);
                for (const Area &area : noGo) {
                    if (said.contains(id + u'\n' + area.id) || !area.holdsZ(leg.zFrom, leg.zTo, leg.zUnits))
                        continue;
                    std::optional<Vec> where;
                    if (area.contains(leg.from))
                        where = leg.from;
                    else if (const auto t = area.firstCrossing(leg.from, leg.to))
                        where = leg.from + *t * (leg.to - leg.from);
                    if (where) {
                        said.insert(id + u'\n' + area.id);
                        mark(add(Severity::Error, Kind::NoGo, id, u"%1: a leg crosses the no-go area %2"_s.arg(what, area.label())), *where);
                    }
                }
                if (operating.empty() || said.contains(id + u"\noperating"_s))
                    continue;
                // Inside when some operating area holds both ends and the leg never crosses its edge.
                bool inside = false;
                for (const Area &area : operating) {
                    if (area.contains(leg.from) && area.contains(leg.to) && !area.firstCrossing(leg.from, leg.to)) {
                        inside = true;
                        break;
                    }
                }
                if (!inside) {
                    said.insert(id + u"\noperating"_s);
                    // Mark where it leaves: the first crossing of an area it starts in, else its start.
                    Vec where = leg.from;
                    for (const Area &area : operating) {
                        if (area.contains(leg.from)) {
                            if (const auto t = area.firstCrossing(leg.from, leg.to))
                                where = leg.from + *t * (leg.to - leg.from);
                            break;
                        }
                    }
                    QStringList names;
                    for (const Area &area : operating)
                        names << area.label();
                    mark(add(Severity::Error, Kind::OutsideOperatingArea, id,
                             u"%1: a leg leaves the operating area %2"_s.arg(what, names.join(u", "_s))), where);
                }
            }
        }
    }

    // Worst first, then in plan order (the plan itself before its maneuvers).
    std::stable_sort(problems.begin(), problems.end(), [&order](const PlanProblem &a, const PlanProblem &b) {
        if (a.severity != b.severity)
            return a.severity == Severity::Error;
        return order.value(a.maneuver, -1) < order.value(b.maneuver, -1);
    });
    return problems;
}

} // namespace neptus::mission
