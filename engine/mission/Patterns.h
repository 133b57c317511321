#pragma once

#include "mission/Mission.h"

#include <QList>
#include <QString>

#include <expected>

namespace neptus::mission {

// Survey patterns the plan editor makes from what the operator draws: rows
// covering a polygon (a lawn-mower, optionally cross-hatched), and a path
// along a drawn line. Each is one FollowPath maneuver (its position the
// pattern's first point, its points metres north/east of it), which every
// shipped vehicle translation understands; the editor then treats it as any
// other maneuver (drag, edit, validate).

struct LatLon
{
    double lat = 0, lon = 0; // degrees
};

struct RowsPattern
{
    double spacing = 20;     // metres between rows (the sensor's swath, less overlap)
    double angle = 0;        // the rows' direction, degrees clockwise from north
    double overshoot = 0;    // metres past the polygon's edge at each row's end, to turn in
    bool crossHatch = false; // then the same rows again at right angles
};

// What every pattern maneuver carries besides its path.
struct PatternDepth
{
    double z = 0;
    QString zUnits = QStringLiteral("DEPTH");
    double speed = 1.5;
    QString speedUnits = QStringLiteral("METERS_PS");
};

// Rows across `polygon` (at least three corners, in order), alternating in
// direction, each spanning the polygon over the band it covers (half a
// spacing either side of it, so slanted edges are covered too; a concave
// polygon's notch is crossed); as many
// rows as cover it, centred (half a spacing in from each edge when its width
// is a whole number of spacings). An error names what is wrong
// (too few corners, a spacing that is not positive or would make more than
// 10,000 rows).
std::expected<Maneuver, QString> rowsOver(const QList<LatLon> &polygon, const RowsPattern &pattern, const PatternDepth &depth,
                                          const QString &id);

// A FollowPath through the drawn points, in order.
std::expected<Maneuver, QString> pathAlong(const QList<LatLon> &line, const PatternDepth &depth, const QString &id);

} // namespace neptus::mission
