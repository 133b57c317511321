#include "mission/PlanGeometry.h"

#include "geo/Geodesy.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace neptus::mission {

using namespace Qt::StringLiterals;

namespace {

constexpr int circleSegments = 36;

double headingDegrees(double north, double east)
{
    const double heading = geo::degrees(std::atan2(east, north));
    return heading < 0 ? heading + 360 : heading;
}

double speedOf(const Maneuver &m, const SpeedModel &speeds)
{
    const double value = m.number(u"speed"_s);
    const QString units = m.text(u"speed_units"_s, u"METERS_PS"_s);
    double speed = value;
    if (units == u"RPM")
        speed = value * speeds.metresPerSecondPerRpm;
    else if (units == u"PERCENTAGE")
        speed = value / 100 * speeds.maxSpeed;
    return speed > 0 ? speed : speeds.defaultSpeed;
}

QList<PathPoint> circle(double radius)
{
    QList<PathPoint> points;
    for (int i = 0; i <= circleSegments; ++i) {
        const double a = 2 * std::numbers::pi * i / circleSegments;
        points.append(PathPoint{radius * std::cos(a), radius * std::sin(a), 0, {}});
    }
    return points;
}

// Lawnmower: rows of `length` along `bearing`, `hstep` apart across a
// `width`, first turn to the left unless CURVE_RIGHT; each row extended by
// the curve offset at both ends; steps alternate between alternation % and
// (200 − alternation) % of hstep, as DUNE's RowsStages makes them (100: even
// rows; 0: every row driven twice, the next 2·hstep on); cross_angle slants
// the step off the perpendicular. No alternation is 100 (rowsAlternation).
QList<PathPoint> rows(const Maneuver &m)
{
    QList<PathPoint> points;
    const double bearing = geo::radians(m.number(u"bearing"_s));
    const double cross = geo::radians(m.number(u"cross_angle"_s));
    const double length = m.number(u"length"_s);
    const double width = m.number(u"width"_s);
    const double hstep = m.number(u"hstep"_s);
    const double offset = m.number(u"coff"_s);
    const double alternation = std::clamp(rowsAlternation(m), 0.0, 100.0);
    const bool right = m.text(u"flags"_s).contains(u"CURVE_RIGHT"_s);
    const Eigen::Vector2d along(std::cos(bearing), std::sin(bearing));
    const double side = bearing + (right ? 1 : -1) * (std::numbers::pi / 2) + cross;
    const Eigen::Vector2d across(std::cos(side), std::sin(side));
    const int count = hstep > 0 ? static_cast<int>(std::floor(width / hstep + 1e-9)) + 1 : 1;
    Eigen::Vector2d start(0, 0);
    for (int row = 0; row < count; ++row) {
        const bool forward = row % 2 == 0;
        const Eigen::Vector2d a = start + along * (forward ? -offset : length + offset);
        const Eigen::Vector2d b = start + along * (forward ? length + offset : -offset);
        points.append(PathPoint{a.x(), a.y(), 0, {}});
        points.append(PathPoint{b.x(), b.y(), 0, {}});
        const double step = hstep * (row % 2 == 0 ? alternation : 200 - alternation) / 100;
        start += across * step;
    }
    return points;
}

} // namespace

QList<PathPoint> expandingSquareOffsets(const Maneuver &m)
{
    const double bearing = geo::radians(m.number(u"bearing"_s));
    const double hstep = m.number(u"hstep"_s);
    const double width = m.number(u"width"_s);
    QList<PathPoint> points{PathPoint{}};
    if (hstep <= 0)
        return points;
    double north = 0, east = 0;
    for (int leg = 0; leg < 10000; ++leg) {
        const double legLength = hstep * (leg / 2 + 1);
        if (legLength > width + 1e-9)
            break;
        const double heading = bearing + leg * (std::numbers::pi / 2);
        north += std::cos(heading) * legLength;
        east += std::sin(heading) * legLength;
        PathPoint p;
        p.x = north;
        p.y = east;
        points.append(p);
    }
    return points;
}

double rowsAlternation(const Maneuver &m)
{
    return m.number(u"alternation"_s, 100);
}

namespace {

// Neptus's rows (ManeuversUtil.calcRowsPoints without alternation, cross
// angle or mirroring): from `curvOff` before the first row, rows of `length`
// run on `curvOff` at each end, `hstep` apart to the right, as long as a row
// fits in `width`; turned to `bearing` (radians).
QList<PathPoint> neptusRows(double width, double length, double hstep, double curvOff, bool squareCurve, double bearing)
{
    width = std::abs(width);
    length = std::abs(length);
    hstep = std::abs(hstep) > 0 ? std::abs(hstep) : 0.1; // as Neptus does
    QList<PathPoint> points{PathPoint{-curvOff, 0, 0, {}}};
    bool forward = true;
    int rows = 0;
    for (double y = 0; y <= width && rows < 10000; y += hstep, ++rows) {
        const double x = forward ? length + curvOff : -curvOff;
        forward = !forward;
        points.append(PathPoint{x, y, 0, {}});
        if (y + hstep <= width)
            points.append(PathPoint{x + (squareCurve ? 0 : (forward ? curvOff : -curvOff)), y + hstep, 0, {}});
    }
    const double c = std::cos(bearing), s = std::sin(bearing);
    for (PathPoint &p : points)
        p = PathPoint{p.x * c - p.y * s, p.x * s + p.y * c, 0, {}};
    return points;
}

} // namespace

QList<PathPoint> crossHatchOffsets(const Maneuver &m)
{
    const double bearing = geo::radians(m.number(u"bearing"_s));
    const double width = std::abs(m.number(u"width"_s));
    const double hstep = m.number(u"hstep"_s), curvOff = m.number(u"coff"_s);
    const bool square = m.text(u"flags"_s).contains(u"SQUARE_CURVE"_s);
    const double c = std::cos(bearing), s = std::sin(bearing), half = width / 2;
    QList<PathPoint> points;
    // From the square's corner behind and left of the centre along the bearing, then from the one behind and right across it.
    for (const auto &[side, turn] : {std::pair{-half, 0.0}, std::pair{half, -std::numbers::pi / 2}}) {
        const double baseX = -half * c - side * s, baseY = -half * s + side * c;
        for (PathPoint p : neptusRows(width, width, hstep, curvOff, square, bearing + turn)) {
            p.x += baseX;
            p.y += baseY;
            points.append(p);
        }
    }
    return points;
}

bool isWorkedPattern(const QString &type)
{
    return type == u"ExpandingSquare" || type == u"CrossHatch";
}

QList<PathPoint> patternOffsets(const Maneuver &m)
{
    if (m.type == u"ExpandingSquare")
        return expandingSquareOffsets(m);
    if (m.type == u"CrossHatch")
        return crossHatchOffsets(m);
    return {};
}

const QStringList &patternShapeParameters(const QString &type)
{
    static const QStringList square{u"width"_s, u"hstep"_s, u"bearing"_s},
        crossHatch{u"width"_s, u"hstep"_s, u"bearing"_s, u"coff"_s, u"flags"_s}, none;
    return type == u"ExpandingSquare" ? square : type == u"CrossHatch" ? crossHatch : none;
}

QString patternCustom(const Maneuver &m)
{
    const QString own = m.text(u"custom"_s);
    if (m.type != u"CrossHatch")
        return own;
    // RowsPattern.serializeToIMC's keys in its order; parseIMCMessage reads every one (sRange too: a
    // missing one throws in Neptus), so the maneuver's own sRange, else Neptus's 30 m, goes in its place.
    QStringList rest;
    QString sRange = u"30"_s;
    for (const QString &entry : own.split(u';', Qt::SkipEmptyParts)) {
        const QString key = entry.section(u'=', 0, 0);
        if (key == u"sRange")
            sRange = entry.section(u'=', 1);
        else if (!QStringList{u"Pattern"_s, u"bearingRad"_s, u"width"_s, u"hstep"_s, u"curvOff"_s, u"squareCurve"_s}.contains(key))
            rest << entry;
    }
    const QStringList pattern{u"Pattern=CrossHatchPattern"_s,
                              u"bearingRad="_s + formatNumber(geo::radians(m.number(u"bearing"_s))),
                              u"width="_s + formatNumber(m.number(u"width"_s)),
                              u"hstep="_s + formatNumber(m.number(u"hstep"_s)),
                              u"sRange="_s + sRange,
                              u"curvOff="_s + formatNumber(m.number(u"coff"_s)),
                              u"squareCurve="_s + (m.text(u"flags"_s).contains(u"SQUARE_CURVE"_s) ? u"true"_s : u"false"_s)};
    // The maneuver's other settings follow (Neptus itself would send only the pattern's).
    return (pattern + rest).join(u';');
}

double distance(const Waypoint &a, const Waypoint &b)
{
    return arriving(a, b).leg;
}

Waypoint arriving(const Waypoint &from, Waypoint to)
{
    to.leg = to.heading = 0;
    if (const auto g = geo::inverse(geo::radians(from.lat), geo::radians(from.lon), geo::radians(to.lat), geo::radians(to.lon))) {
        to.leg = g->distance;
        to.heading = g->distance > 0 ? std::fmod(geo::degrees(g->initialAzimuth) + 360, 360) : 0;
    }
    return to;
}

ManeuverGeometry maneuverGeometry(const Maneuver &m, const Waypoint *previous, const SpeedModel &speeds)
{
    ManeuverGeometry g;
    g.id = m.id;
    g.type = m.type;
    if (!m.has(u"lat"_s))
        return g; // no place (a kept Unsupported one) and no duration known: it stays where the vehicle is
    g.speed = speedOf(m, speeds);
    const bool elevator = m.type == u"Elevator";
    const double z = m.number(elevator ? u"end_z"_s : u"z"_s);
    g.zUnits = m.text(elevator ? u"end_z_units"_s : u"z_units"_s, u"NONE"_s);
    g.minZ = g.maxZ = z;
    const double duration = m.number(u"duration"_s);
    // Once there: how long the maneuver lasts by its own clock (a loiter's laps
    // for `duration`, a station keeping, a pop-up's wait), and whether it ends.
    double hold = 0;
    bool circling = false;
    bool endless = false;
    // The path it makes, in metres north, east and down of its position.
    QList<PathPoint> offsets;

    if (m.type == u"Rows") {
        offsets = rows(m);
    } else if (m.type == u"FollowPath" || m.type == u"FollowTrajectory" || isWorkedPattern(m.type)) {
        offsets = isWorkedPattern(m.type) ? patternOffsets(m) : m.points;
        for (const PathPoint &p : std::as_const(offsets)) {
            g.minZ = std::min(g.minZ, z + p.z);
            g.maxZ = std::max(g.maxZ, z + p.z);
        }
    } else if (m.type == u"Loiter" || m.type == u"CompassCalibration") {
        if (m.text(u"type"_s) != u"HOVER")
            offsets = circle(m.number(u"radius"_s));
        circling = true;
        hold = duration;
        endless = duration <= 0;
        if (m.type == u"CompassCalibration") {
            g.minZ = z - m.number(u"amplitude"_s);
            g.maxZ = z + m.number(u"amplitude"_s);
        }
    } else {
        // Goto, PopUp, StationKeeping, YoYo, Elevator, ScheduledGoto, Launch, Takeoff, Land: a point.
        if (m.type == u"StationKeeping") {
            hold = duration;
            endless = duration <= 0;
        } else if (m.type == u"PopUp") {
            hold = duration;
        } else if (m.type == u"YoYo") {
            g.minZ = z - m.number(u"amplitude"_s);
            g.maxZ = z + m.number(u"amplitude"_s);
        } else if (elevator) {
            const double startZ = m.number(u"start_z"_s);
            g.minZ = std::min(startZ, z);
            g.maxZ = std::max(startZ, z);
        }
    }
    if (offsets.isEmpty())
        offsets.append(PathPoint{});
    // Depth, altitude and height stop at zero: a yo-yo 10 m either side of 5 m
    // goes from the surface to 15 m (DUNE limits it so).
    if (g.zUnits != u"NONE")
        g.minZ = std::max(g.minZ, 0.0);

    // On the ellipsoid; legs inside the maneuver on its plane (the transit to it as a geodesic, below).
    const double lat = m.number(u"lat"_s), lon = m.number(u"lon"_s);
    const geo::Geodetic origin{geo::radians(lat), geo::radians(lon), 0};
    double along = 0;
    for (qsizetype i = 0; i < offsets.size(); ++i) {
        const PathPoint &p = offsets[i];
        Waypoint w{lat, lon, z + p.z, g.zUnits, 0, 0}; // an offset of zero is the position as written
        if (p.x != 0 || p.y != 0) {
            const geo::Geodetic at = geo::fromNed(Eigen::Vector3d(p.x, p.y, 0), origin);
            w.lat = geo::degrees(at.lat);
            w.lon = geo::degrees(at.lon);
        }
        if (i > 0) {
            const Eigen::Vector2d step(p.x - offsets[i - 1].x, p.y - offsets[i - 1].y);
            w.leg = step.norm();
            w.heading = w.leg > 0 ? headingDegrees(step.x(), step.y()) : g.points.last().heading;
            along += w.leg;
        }
        g.points.append(w);
    }
    if (previous) {
        g.points.first() = arriving(*previous, g.points.first());
        g.transit = g.points.first().leg;
    }
    // A timed loiter covers its circle for as long as it lasts; an endless one, one lap at least.
    g.length = circling && hold > 0 ? hold * g.speed : along;
    if (!endless)
        g.duration = g.transit / g.speed + (circling ? hold : g.length / g.speed + hold);
    return g;
}

PlanGeometry planGeometry(const Plan &plan, const SpeedModel &speeds, PlanGeometryCache *cache)
{
    PlanGeometry result;
    result.duration = 0.0;
    const Waypoint *previous = nullptr;
    QHash<QString, PlanGeometryCache::Entry> kept; // what the cache holds after this plan
    const bool sameSpeeds = cache && cache->m_speeds == speeds;
    for (const Maneuver *m : plan.executionOrder()) {
        if (cache) {
            const std::optional<std::pair<double, double>> from =
                previous ? std::optional(std::pair(previous->lat, previous->lon)) : std::nullopt;
            const auto found = cache->m_entries.constFind(m->id);
            if (sameSpeeds && found != cache->m_entries.cend() && found->type == m->type && found->from == from
                && found->parameters.isSharedWith(m->parameters) && found->points.isSharedWith(m->points))
                result.maneuvers.append(found->geometry);
            else
                result.maneuvers.append(maneuverGeometry(*m, previous, speeds));
            kept.insert(m->id, {m->type, m->parameters, m->points, from, result.maneuvers.last()});
        } else {
            result.maneuvers.append(maneuverGeometry(*m, previous, speeds));
        }
        const ManeuverGeometry &g = result.maneuvers.last();
        if (!g.points.isEmpty())
            previous = &g.points.last();
        result.length += g.length + g.transit;
        if (result.duration && g.duration)
            *result.duration += *g.duration;
        else
            result.duration.reset();
        const auto raise = [&](std::optional<double> &max) { max = std::max(max.value_or(g.maxZ), g.maxZ); };
        if (g.zUnits == u"DEPTH")
            raise(result.maxDepth);
        else if (g.zUnits == u"ALTITUDE")
            raise(result.maxAltitude);
        else if (g.zUnits == u"HEIGHT")
            raise(result.maxHeight);
    }
    if (cache) {
        cache->m_entries = std::move(kept);
        cache->m_speeds = speeds;
    }
    return result;
}

} // namespace neptus::mission
