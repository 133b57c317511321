#include "Patterns.h"

#include "geo/Geodesy.h"

#include <algorithm>
#include <cmath>
#include <vector>

using namespace Qt::StringLiterals;

namespace neptus::mission {

namespace {

using Vec = Eigen::Vector2d; // metres north, east of the pattern's local origin

// A FollowPath through `points` (metres north/east of `origin`), positioned at the first.
Maneuver followPath(const std::vector<Vec> &points, const geo::Geodetic &origin, const PatternDepth &depth, const QString &id)
{
    Maneuver m;
    m.id = id;
    m.type = u"FollowPath"_s;
    const geo::Geodetic start = geo::fromNed({points.front().x(), points.front().y(), 0}, origin);
    // Positions to about a centimetre (8 decimals of a degree), offsets to a millimetre.
    m.parameters.insert(u"lat"_s, QString::number(geo::degrees(start.lat), 'f', 8));
    m.parameters.insert(u"lon"_s, QString::number(geo::degrees(start.lon), 'f', 8));
    m.parameters.insert(u"z"_s, formatNumber(depth.z));
    m.parameters.insert(u"z_units"_s, depth.zUnits);
    m.parameters.insert(u"speed"_s, formatNumber(depth.speed));
    m.parameters.insert(u"speed_units"_s, depth.speedUnits);
    for (const Vec &p : points) {
        const Vec d = p - points.front();
        m.points.append({std::round(d.x() * 1000) / 1000, std::round(d.y() * 1000) / 1000, 0, std::nullopt});
    }
    return m;
}

std::vector<Vec> toPlane(const QList<LatLon> &points, const geo::Geodetic &origin)
{
    std::vector<Vec> out;
    out.reserve(size_t(points.size()));
    for (const LatLon &p : points) {
        const Eigen::Vector3d ned = geo::toNed({geo::radians(p.lat), geo::radians(p.lon), 0}, origin);
        out.emplace_back(ned.x(), ned.y());
    }
    return out;
}

bool finite(const QList<LatLon> &points)
{
    return std::all_of(points.begin(), points.end(), [](const LatLon &p) {
        return std::isfinite(p.lat) && std::isfinite(p.lon) && std::abs(p.lat) <= 90 && std::abs(p.lon) <= 360;
    });
}

// Rows across the polygon at `angle` (degrees from north), appended to `path`.
std::expected<void, QString> addRows(const std::vector<Vec> &polygon, double angle, const RowsPattern &pattern, std::vector<Vec> &path)
{
    const double a = geo::radians(angle);
    const Vec along(std::cos(a), std::sin(a)), across(-std::sin(a), std::cos(a));
    double lo = polygon.front().dot(across), hi = lo;
    for (const Vec &p : polygon) {
        lo = std::min(lo, p.dot(across));
        hi = std::max(hi, p.dot(across));
    }
    const double width = hi - lo;
    if (width / pattern.spacing > 10000)
        return std::unexpected(u"%1 m across at %2 m spacing would be more than 10,000 rows"_s.arg(width, 0, 'f', 0).arg(pattern.spacing));
    // As many rows as cover the width (each covers half a spacing either
    // side), centred: half a spacing in when the width is a whole number of
    // spacings, one row in the middle of a polygon narrower than a spacing.
    const int rows = std::max(1, int(std::ceil(width / pattern.spacing - 1e-6)));
    const double first = lo + (width - (rows - 1) * pattern.spacing) / 2;
    bool forward = true;
    for (int r = 0; r < rows; ++r) {
        // The row spans the polygon over the whole band it covers (half a
        // spacing either side), not only on its own line: at a slanted edge
        // the band reaches further than the line does.
        const double t = first + r * pattern.spacing, h = pattern.spacing / 2;
        double sMin = 0, sMax = 0;
        bool found = false;
        const auto take = [&](double s) {
            sMin = found ? std::min(sMin, s) : s;
            sMax = found ? std::max(sMax, s) : s;
            found = true;
        };
        for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
            const double ta = polygon[j].dot(across), tb = polygon[i].dot(across);
            const double sa = polygon[j].dot(along), sb = polygon[i].dot(along);
            if (ta >= t - h && ta <= t + h)
                take(sa); // a corner inside the band
            for (const double edge : {t - h, t + h}) { // where the edge crosses the band's sides
                if ((ta < edge && edge < tb) || (tb < edge && edge < ta))
                    take(sa + (edge - ta) / (tb - ta) * (sb - sa));
            }
        }
        if (!found)
            continue;
        sMin -= pattern.overshoot;
        sMax += pattern.overshoot;
        const Vec start = (forward ? sMin : sMax) * along + t * across, end = (forward ? sMax : sMin) * along + t * across;
        path.push_back(start);
        path.push_back(end);
        forward = !forward;
    }
    return {};
}

} // namespace

std::expected<Maneuver, QString> rowsOver(const QList<LatLon> &polygon, const RowsPattern &pattern, const PatternDepth &depth,
                                          const QString &id)
{
    if (polygon.size() < 3)
        return std::unexpected(u"a survey area needs at least three corners (it has %1)"_s.arg(polygon.size()));
    if (!finite(polygon))
        return std::unexpected(u"a corner of the survey area is not a position"_s);
    if (!(pattern.spacing > 0) || !std::isfinite(pattern.spacing))
        return std::unexpected(u"the spacing between rows must be more than 0 m"_s);
    if (!std::isfinite(pattern.angle) || !std::isfinite(pattern.overshoot) || pattern.overshoot < 0)
        return std::unexpected(u"the rows' angle must be a number and their overshoot 0 m or more"_s);
    const geo::Geodetic origin{geo::radians(polygon.front().lat), geo::radians(polygon.front().lon), 0};
    const std::vector<Vec> corners = toPlane(polygon, origin);
    double area = 0; // shoelace
    for (size_t i = 0, j = corners.size() - 1; i < corners.size(); j = i++)
        area += corners[j].x() * corners[i].y() - corners[i].x() * corners[j].y();
    if (std::abs(area) / 2 < 1)
        return std::unexpected(u"the survey area has no inside (its corners are in a line)"_s);
    std::vector<Vec> path;
    if (auto made = addRows(corners, pattern.angle, pattern, path); !made)
        return std::unexpected(made.error());
    if (pattern.crossHatch) {
        if (auto made = addRows(corners, pattern.angle + 90, pattern, path); !made)
            return std::unexpected(made.error());
    }
    if (path.empty())
        return std::unexpected(u"the survey area has no inside (its corners are in a line)"_s);
    return followPath(path, origin, depth, id);
}

std::expected<Maneuver, QString> pathAlong(const QList<LatLon> &line, const PatternDepth &depth, const QString &id)
{
    if (line.size() < 2)
        return std::unexpected(u"a path needs at least two points (it has %1)"_s.arg(line.size()));
    if (!finite(line))
        return std::unexpected(u"a point of the path is not a position"_s);
    const geo::Geodetic origin{geo::radians(line.front().lat), geo::radians(line.front().lon), 0};
    return followPath(toPlane(line, origin), origin, depth, id);
}

} // namespace neptus::mission
