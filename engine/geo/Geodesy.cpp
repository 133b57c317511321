#include "geo/Geodesy.h"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

namespace neptus::geo {

namespace {
constexpr double pi = std::numbers::pi;

double wrapAngle(double a)
{
    a = std::fmod(a, 2 * pi);
    return a < 0 ? a + 2 * pi : a;
}
} // namespace

Eigen::Vector3d toEcef(const Geodetic &p, const Ellipsoid &e)
{
    const double sinLat = std::sin(p.lat);
    const double cosLat = std::cos(p.lat);
    const double n = e.a / std::sqrt(1 - e.e2() * sinLat * sinLat); // prime vertical radius
    return {(n + p.height) * cosLat * std::cos(p.lon),
            (n + p.height) * cosLat * std::sin(p.lon),
            (n * (1 - e.e2()) + p.height) * sinLat};
}

Geodetic fromEcef(const Eigen::Vector3d &ecef, const Ellipsoid &e)
{
    const double p = std::hypot(ecef.x(), ecef.y());
    Geodetic out;
    out.lon = std::atan2(ecef.y(), ecef.x());
    double lat = std::atan2(ecef.z(), p * (1 - e.e2()));
    double n = e.a;
    // Fixed point of lat = atan2(z + e² N sin(lat), p); converges in a few steps.
    for (int i = 0; i < 30; ++i) {
        const double sinLat = std::sin(lat);
        n = e.a / std::sqrt(1 - e.e2() * sinLat * sinLat);
        const double next = std::atan2(ecef.z() + e.e2() * n * sinLat, p);
        const bool done = std::abs(next - lat) < 1e-15;
        lat = next;
        if (done)
            break;
    }
    const double sinLat = std::sin(lat);
    n = e.a / std::sqrt(1 - e.e2() * sinLat * sinLat);
    out.lat = lat;
    // Valid at every latitude, unlike p / cos(lat) - N near the poles.
    out.height = p * std::cos(lat) + ecef.z() * sinLat - e.a * e.a / n;
    return out;
}

Eigen::Matrix3d ecefToNed(const Geodetic &o)
{
    const double sLat = std::sin(o.lat), cLat = std::cos(o.lat);
    const double sLon = std::sin(o.lon), cLon = std::cos(o.lon);
    Eigen::Matrix3d r;
    r << -sLat * cLon, -sLat * sLon, cLat,
         -sLon,        cLon,         0,
         -cLat * cLon, -cLat * sLon, -sLat;
    return r;
}

Eigen::Vector3d toNed(const Geodetic &point, const Geodetic &origin, const Ellipsoid &e)
{
    return ecefToNed(origin) * (toEcef(point, e) - toEcef(origin, e));
}

Geodetic fromNed(const Eigen::Vector3d &ned, const Geodetic &origin, const Ellipsoid &e)
{
    return fromEcef(toEcef(origin, e) + ecefToNed(origin).transpose() * ned, e);
}

Geodetic imcPosition(double lat, double lon, double height, double x, double y, double z)
{
    const Geodetic reference{lat, lon, height};
    if (x == 0 && y == 0 && z == 0)
        return reference;
    return fromNed({x, y, z}, reference);
}

std::optional<Geodesic> inverse(double lat1, double lon1, double lat2, double lon2, const Ellipsoid &e)
{
    const double f = e.f, a = e.a, b = e.b();
    const double L = lon2 - lon1;
    const double u1 = std::atan((1 - f) * std::tan(lat1));
    const double u2 = std::atan((1 - f) * std::tan(lat2));
    const double sinU1 = std::sin(u1), cosU1 = std::cos(u1);
    const double sinU2 = std::sin(u2), cosU2 = std::cos(u2);

    double lambda = L;
    double sinSigma = 0, cosSigma = 0, sigma = 0, cos2Alpha = 0, cos2SigmaM = 0;
    double sinLambda = 0, cosLambda = 0;
    bool converged = false;
    for (int i = 0; i < 200; ++i) {
        sinLambda = std::sin(lambda);
        cosLambda = std::cos(lambda);
        const double t1 = cosU2 * sinLambda;
        const double t2 = cosU1 * sinU2 - sinU1 * cosU2 * cosLambda;
        sinSigma = std::sqrt(t1 * t1 + t2 * t2);
        if (sinSigma == 0)
            return Geodesic{}; // the same point
        cosSigma = sinU1 * sinU2 + cosU1 * cosU2 * cosLambda;
        sigma = std::atan2(sinSigma, cosSigma);
        const double sinAlpha = cosU1 * cosU2 * sinLambda / sinSigma;
        cos2Alpha = 1 - sinAlpha * sinAlpha;
        cos2SigmaM = cos2Alpha != 0 ? cosSigma - 2 * sinU1 * sinU2 / cos2Alpha : 0; // 0 along the equator
        const double c = f / 16 * cos2Alpha * (4 + f * (4 - 3 * cos2Alpha));
        const double previous = lambda;
        lambda = L + (1 - c) * f * sinAlpha
                     * (sigma + c * sinSigma * (cos2SigmaM + c * cosSigma * (-1 + 2 * cos2SigmaM * cos2SigmaM)));
        if (std::abs(lambda - previous) < 1e-12) {
            converged = true;
            break;
        }
    }
    if (!converged)
        return std::nullopt;

    const double uSq = cos2Alpha * (a * a - b * b) / (b * b);
    const double A = 1 + uSq / 16384 * (4096 + uSq * (-768 + uSq * (320 - 175 * uSq)));
    const double B = uSq / 1024 * (256 + uSq * (-128 + uSq * (74 - 47 * uSq)));
    const double deltaSigma = B * sinSigma
        * (cos2SigmaM + B / 4 * (cosSigma * (-1 + 2 * cos2SigmaM * cos2SigmaM)
            - B / 6 * cos2SigmaM * (-3 + 4 * sinSigma * sinSigma) * (-3 + 4 * cos2SigmaM * cos2SigmaM)));

    Geodesic g;
    g.distance = b * A * (sigma - deltaSigma);
    g.initialAzimuth = wrapAngle(std::atan2(cosU2 * sinLambda, cosU1 * sinU2 - sinU1 * cosU2 * cosLambda));
    g.finalAzimuth = wrapAngle(std::atan2(cosU1 * sinLambda, -sinU1 * cosU2 + cosU1 * sinU2 * cosLambda));
    return g;
}

Eigen::Vector2d toMercator(double lat, double lon)
{
    return {(lon + pi) / (2 * pi), 0.5 - std::asinh(std::tan(lat)) / (2 * pi)};
}

Eigen::Vector2d fromMercator(const Eigen::Vector2d &xy)
{
    return {std::atan(std::sinh(pi * (1 - 2 * xy.y()))), xy.x() * 2 * pi - pi};
}

double metresPerPixel(double lat, double zoomLevel)
{
    return 2 * pi * wgs84.a * std::cos(lat) / (256 * std::exp2(zoomLevel));
}

} // namespace neptus::geo
