#pragma once

#include "mission/Mission.h"

#include <QHash>
#include <QList>
#include <QMap>
#include <QString>

#include <optional>

namespace neptus::mission {

// What a plan implies: the points each maneuver makes the vehicle visit, how
// far it goes and for how long at the planned speeds, and how deep or high.
// Worked out on a local tangent plane around each maneuver's position (WGS84
// through geo/), which is exact to centimetres over the few kilometres a
// maneuver spans; transits between maneuvers are geodesics.

// Turning planned speeds into metres per second: RPM and percentages need
// the vehicle's figures (its definition's limits); these are the defaults.
struct SpeedModel
{
    double metresPerSecondPerRpm = 1.0 / 1000; // 1000 RPM ≈ 1 m/s, as LSTS's AUVs
    double maxSpeed = 2.0;                      // what 100 % means, m/s
    double defaultSpeed = 1.0;                  // for maneuvers that give no speed
    friend bool operator==(const SpeedModel &, const SpeedModel &) = default;
};

struct Waypoint
{
    double lat = 0; // degrees
    double lon = 0;
    double z = 0;
    QString zUnits; // NONE, DEPTH, ALTITUDE, HEIGHT
    // From the previous point along the plan: metres, and the heading there
    // in degrees from north (0 for the plan's first point).
    double leg = 0;
    double heading = 0;
};

struct ManeuverGeometry
{
    QString id;
    QString type;
    // The path the maneuver itself makes; the first point is where it begins
    // (the vehicle arrives there from the previous maneuver's last point).
    QList<Waypoint> points;
    double transit = 0;  // metres from the previous maneuver's end to points.first()
    double length = 0;   // metres along points (laps of a timed loiter included)
    double speed = 0;    // m/s
    // Seconds, transit included; empty when the maneuver does not end by
    // itself (a loiter or station keeping with no duration).
    std::optional<double> duration;
    double minZ = 0, maxZ = 0; // the z range it visits, in zUnits (a yo-yo's amplitude included)
    QString zUnits;
};

struct PlanGeometry
{
    QList<ManeuverGeometry> maneuvers; // in execution order (Plan::executionOrder)
    double length = 0;
    std::optional<double> duration;    // empty when some maneuver never ends by itself
    std::optional<double> maxDepth;    // over maneuvers in DEPTH
    std::optional<double> maxAltitude; // over maneuvers in ALTITUDE (above the bottom)
    std::optional<double> maxHeight;   // over maneuvers in HEIGHT (above the surface)
};

// `previous` is where the vehicle is before the maneuver (its transit starts
// there); none for the first.
ManeuverGeometry maneuverGeometry(const Maneuver &maneuver, const Waypoint *previous = nullptr,
                                  const SpeedModel &speeds = {});
// What planGeometry worked out for each maneuver the last time, for a plan
// edited a maneuver at a time (the plan editor: a drag moves one of a
// thousand). A maneuver whose parameters and points are still the very ones
// it was worked out from (implicitly shared: a pointer test, no comparing),
// entered from the same point at the same speeds, is not worked out again.
class PlanGeometryCache
{
    friend PlanGeometry planGeometry(const Plan &, const SpeedModel &, PlanGeometryCache *);
    struct Entry
    {
        QString type;
        QMap<QString, QString> parameters;
        QList<PathPoint> points;
        std::optional<std::pair<double, double>> from; // the previous maneuver's end (lat, lon)
        ManeuverGeometry geometry;
    };
    QHash<QString, Entry> m_entries; // by maneuver id
    SpeedModel m_speeds;
};

PlanGeometry planGeometry(const Plan &plan, const SpeedModel &speeds = {}, PlanGeometryCache *cache = nullptr);

// Patterns IMC has no maneuver for: their points are worked out here, metres
// north (x) and east (y) of the maneuver's position, and the IMC translation
// sends them as a FollowPath.
//
// ExpandingSquare's corners: legs of hstep, hstep, 2·hstep, 2·hstep, …
// turning right from `bearing`, until a leg would pass `width`.
QList<PathPoint> expandingSquareOffsets(const Maneuver &maneuver);
// CrossHatch, as LSTS Neptus makes its CrossHatchPattern
// (ManeuversUtil.calcCrossHatchPatternPoints): a square of `width` centred on
// the position, covered by rows `hstep` apart along `bearing` (first turn to
// the right) and then by rows across them, each row run on `coff` metres past
// the square; the turns square with SQUARE_CURVE in `flags`, else cut
// diagonally. At most 10,000 rows each way.
QList<PathPoint> crossHatchOffsets(const Maneuver &maneuver);

// A Rows' alternation (percent): 100 when the maneuver says none. IMC's
// zero is not "none" here: DUNE's RowsStages steps 0 and then 2·hstep (each
// row driven twice), so an absent alternation is sent as 100, as Neptus
// always sends it (RowsManeuver.serializeToIMC).
double rowsAlternation(const Maneuver &maneuver);

// Whether `type` is such a pattern; its points (empty for any other
// maneuver); the parameters that only shape them (the FollowPath leaves
// them out); and the FollowPath's `custom` tuple list: the maneuver's own,
// after what names the pattern for a Neptus console that reads the plan back
// (CrossHatch: Pattern=CrossHatchPattern, bearingRad, width, hstep, sRange,
// curvOff, squareCurve, the keys and order of RowsPattern.serializeToIMC,
// whose parseIMCMessage needs every one).
bool isWorkedPattern(const QString &type);
QList<PathPoint> patternOffsets(const Maneuver &maneuver);
const QStringList &patternShapeParameters(const QString &type);
QString patternCustom(const Maneuver &maneuver);

// Great-circle distance in metres (WGS84 geodesic).
double distance(const Waypoint &a, const Waypoint &b);
// `to` with its leg and heading set from `from` (geodesic; heading 0 for no distance).
Waypoint arriving(const Waypoint &from, Waypoint to);

} // namespace neptus::mission
