#include "GeoFunctions.h"

#include "Geodesy.h"

#include <cmath>
#include <numbers>

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

QVariantMap GeoFunctions::toNed(double lat, double lon, double originLat, double originLon) const
{
    const auto ned = geo::toNed({radians(lat), radians(lon), 0}, {radians(originLat), radians(originLon), 0});
    return {{QStringLiteral("north"), ned.x()}, {QStringLiteral("east"), ned.y()}};
}

QVariantMap GeoFunctions::fromNed(double north, double east, double originLat, double originLon) const
{
    const Geodetic origin{radians(originLat), radians(originLon), 0};
    // Down chosen so the point lies on the surface: the Earth's curve drops
    // away by d² / 2R over a distance d.
    const double drop = (north * north + east * east) / (2 * wgs84.a);
    const auto p = geo::fromNed({north, east, drop}, origin);
    return {{QStringLiteral("lat"), degrees(p.lat)}, {QStringLiteral("lon"), degrees(p.lon)}};
}

double GeoFunctions::metresPerPixel(double lat, double zoomLevel) const
{
    return 2 * std::numbers::pi * wgs84.a * std::cos(radians(lat)) / (256 * std::exp2(zoomLevel));
}

} // namespace neptus::geo
