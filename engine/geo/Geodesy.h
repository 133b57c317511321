#pragma once

#include <Eigen/Core>

#include <optional>

// Positions on the Earth, as vehicles report them and consoles draw them.
// Angles are radians, lengths metres, heights above the ellipsoid.
//
//   geodetic (lat, lon, height)  <->  ECEF (x, y, z)  <->  local NED (north, east, down)
//
// IMC vehicles report a reference (EstimatedState lat/lon/height) plus NED
// offsets (x, y, z) from it; imcPosition() turns that into one geodetic point
// the way DUNE does (through ECEF, not a flat-Earth approximation).
namespace neptus::geo {

struct Ellipsoid
{
    double a; // semi-major axis, m
    double f; // flattening
    double b() const { return a * (1 - f); }
    double e2() const { return f * (2 - f); }
};

inline constexpr Ellipsoid wgs84{6378137.0, 1.0 / 298.257223563};
inline constexpr Ellipsoid grs80{6378137.0, 1.0 / 298.257222101};

struct Geodetic
{
    double lat = 0; // rad, positive north
    double lon = 0; // rad, positive east
    double height = 0; // m above the ellipsoid
};

Eigen::Vector3d toEcef(const Geodetic &point, const Ellipsoid &e = wgs84);
// Exact to well below a millimetre anywhere, including the poles and the
// Earth's centre region (iterates to convergence).
Geodetic fromEcef(const Eigen::Vector3d &ecef, const Ellipsoid &e = wgs84);

// Rotation taking ECEF vectors into the local north-east-down frame at `origin`.
Eigen::Matrix3d ecefToNed(const Geodetic &origin);

// `point` in metres north, east and down of `origin`.
Eigen::Vector3d toNed(const Geodetic &point, const Geodetic &origin, const Ellipsoid &e = wgs84);
// The point `ned` metres north, east and down of `origin`.
Geodetic fromNed(const Eigen::Vector3d &ned, const Geodetic &origin, const Ellipsoid &e = wgs84);

// An IMC EstimatedState's position: the reference (lat, lon, height) moved by
// its offsets x (north), y (east), z (down).
Geodetic imcPosition(double lat, double lon, double height, double x, double y, double z);

// Distance along the ellipsoid between two points and the azimuths (rad,
// clockwise from north, in [0, 2π)) at each end: Vincenty's inverse formula.
struct Geodesic
{
    double distance = 0;
    double initialAzimuth = 0; // leaving the first point, towards the second
    double finalAzimuth = 0;   // arriving at the second point
};
// Empty for nearly antipodal points, where the formula does not converge.
std::optional<Geodesic> inverse(double lat1, double lon1, double lat2, double lon2, const Ellipsoid &e = wgs84);

// Web Mercator (EPSG:3857), as map tiles use: x, y in [0, 1) across the
// world, x east from 180° W, y south from 85.05° N.
Eigen::Vector2d toMercator(double lat, double lon);
Eigen::Vector2d fromMercator(const Eigen::Vector2d &xy); // (lat, lon)
// Metres one screen pixel covers at a latitude (rad) on a Web Mercator map of
// 256-pixel tiles at a zoom level (as Qt Location and tile servers draw it).
double metresPerPixel(double lat, double zoomLevel);

constexpr double degrees(double radians) { return radians * 57.295779513082320876798154814105; }
constexpr double radians(double degrees) { return degrees * 0.017453292519943295769236907684886; }

} // namespace neptus::geo
