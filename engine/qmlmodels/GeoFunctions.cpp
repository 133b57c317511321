#include "qmlmodels/GeoFunctions.h"

#include "geo/Geodesy.h"
#include "geo/MapProjection.h"

namespace neptus::geo {

QVariantMap GeoFunctions::measure(double lat1, double lon1, double lat2, double lon2) const
{
    const auto g = inverse(radians(lat1), radians(lon1), radians(lat2), radians(lon2));
    if (!g)
        return {{QStringLiteral("valid"), false}};
    return {{QStringLiteral("distance"), g->distance},
            {QStringLiteral("bearing"), degrees(g->initialAzimuth)},
            {QStringLiteral("valid"), true}};
}

double GeoFunctions::metresPerPixel(double lat, double zoomLevel) const
{
    return geo::metresPerPixel(radians(lat), zoomLevel);
}

QVariantMap GeoFunctions::ned(double lat, double lon, double homeLat, double homeLon) const
{
    const Eigen::Vector3d v = toNed({radians(lat), radians(lon), 0}, {radians(homeLat), radians(homeLon), 0});
    return {{QStringLiteral("north"), v.x()}, {QStringLiteral("east"), v.y()}};
}

QPointF GeoFunctions::project(double lat, double lon, double centerLat, double centerLon, double zoomLevel,
                              double bearing, double width, double height) const
{
    const MapProjection view{centerLat, centerLon, zoomLevel, bearing, {width, height}};
    return view.project(radians(lat), radians(lon));
}

QVariantMap GeoFunctions::coordinateAt(double x, double y, double centerLat, double centerLon, double zoomLevel,
                                       double bearing, double width, double height) const
{
    const MapProjection view{centerLat, centerLon, zoomLevel, bearing, {width, height}};
    const Eigen::Vector2d c = view.toCoordinate({x, y});
    return {{QStringLiteral("lat"), degrees(c.x())}, {QStringLiteral("lon"), degrees(c.y())}};
}

} // namespace neptus::geo
