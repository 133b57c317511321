// Geodesy against published reference values (each test names its source),
// plus round trips that must hold everywhere.
#include "geo/Geodesy.h"
#include "geo/Polygon.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace neptus::geo;

namespace {
double dms(double d, double m, double s) { return radians(std::copysign(std::abs(d) + m / 60 + s / 3600, d)); }
Geodetic deg(double lat, double lon, double h) { return {radians(lat), radians(lon), h}; }
constexpr double arcsecond = 4.84813681109536e-6; // rad
} // namespace

// GNU Octave mapping package, geodetic2ecef documentation: Aalborg GPS Centre on WGS84.
TEST(Geodesy, EcefOfAalborgGpsCentre)
{
    const auto ecef = toEcef(deg(57.02929569, 9.950248114, 56.95));
    EXPECT_NEAR(ecef.x(), 3426949.39675307, 1e-3);
    EXPECT_NEAR(ecef.y(), 601195.852419885, 1e-3);
    EXPECT_NEAR(ecef.z(), 5327723.99358255, 1e-3);
}

// PROJ documentation, the "cart" conversion: a point on GRS80.
TEST(Geodesy, EcefOnGrs80FromTheProjManual)
{
    const auto ecef = toEcef(deg(45.3935192042, 17.7562015132, 133.12), grs80);
    EXPECT_NEAR(ecef.x(), 4272922.1553, 1e-3);
    EXPECT_NEAR(ecef.y(), 1368283.0597, 1e-3);
    EXPECT_NEAR(ecef.z(), 4518261.3501, 1e-3);
    const auto back = fromEcef(ecef, grs80);
    EXPECT_NEAR(degrees(back.lat), 45.3935192042, 1e-10);
    EXPECT_NEAR(degrees(back.lon), 17.7562015132, 1e-10);
    EXPECT_NEAR(back.height, 133.12, 1e-6);
}

// The ellipsoid's definition: the equator at Greenwich lies at a, the poles at b.
TEST(Geodesy, EcefOfTheAxes)
{
    EXPECT_NEAR((toEcef(deg(0, 0, 0)) - Eigen::Vector3d(wgs84.a, 0, 0)).norm(), 0, 1e-9);
    EXPECT_NEAR((toEcef(deg(90, 0, 0)) - Eigen::Vector3d(0, 0, 6356752.314245179)).norm(), 0, 1e-6);
    EXPECT_NEAR((toEcef(deg(-90, 123, 10)) - Eigen::Vector3d(0, 0, -6356762.314245179)).norm(), 0, 1e-6);
    EXPECT_NEAR((toEcef(deg(0, 90, 0)) - Eigen::Vector3d(0, wgs84.a, 0)).norm(), 0, 1e-9);
}

// ECEF -> geodetic -> ECEF is exact from the deep sea to orbit, poles included.
TEST(Geodesy, EcefRoundTripEverywhere)
{
    for (double lat = -90; lat <= 90; lat += 7.5)
        for (double lon = -180; lon < 180; lon += 30)
            for (double h : {-11000.0, 0.0, 35.0, 8848.0, 400e3, 36000e3}) {
                const auto point = deg(lat, lon, h);
                const auto back = fromEcef(toEcef(point));
                ASSERT_NEAR(back.lat, point.lat, 1e-12) << lat << " " << lon << " " << h;
                if (std::abs(lat) < 90) {
                    ASSERT_NEAR(std::remainder(back.lon - point.lon, 2 * M_PI), 0, 1e-12);
                }
                ASSERT_NEAR(back.height, h, 1e-6) << lat << " " << lon << " " << h;
            }
}

// MathWorks Mapping Toolbox, geodetic2ned / ned2geodetic documentation:
// Mount Mansfield seen from an aircraft, WGS84 (values printed to 5 digits).
TEST(Geodesy, NedOfMountMansfieldFromAnAircraft)
{
    const auto aircraft = deg(44.532, -72.782, 1699);
    const auto mountain = deg(44.544, -72.814, 1340);
    const auto ned = toNed(mountain, aircraft);
    EXPECT_NEAR(ned.x(), 1334.3, 0.05);
    EXPECT_NEAR(ned.y(), -2543.6, 0.05);
    EXPECT_NEAR(ned.z(), 359.65, 0.005);

    const auto back = fromNed({1334.3, -2543.6, 359.65}, aircraft);
    EXPECT_NEAR(degrees(back.lat), 44.544, 1e-5);
    EXPECT_NEAR(degrees(back.lon), -72.814, 1e-5);
    EXPECT_NEAR(back.height, 1340, 0.05);
}

// Vincenty (1975), as worked in Geoscience Australia's GDA technical manual:
// Flinders Peak to Buninyong on GRS80.
TEST(Geodesy, VincentyFlindersPeakToBuninyong)
{
    const auto g = inverse(dms(-37, 57, 3.72030), dms(144, 25, 29.52440),
                           dms(-37, 39, 10.15610), dms(143, 55, 35.38390), grs80);
    ASSERT_TRUE(g);
    EXPECT_NEAR(g->distance, 54972.271, 0.001);
    EXPECT_NEAR(g->initialAzimuth, dms(306, 52, 5.37), 0.01 * arcsecond);
    // The manual gives the reverse azimuth, 127°10'25.07", i.e. the arrival direction + 180°.
    EXPECT_NEAR(g->finalAzimuth - M_PI, dms(127, 10, 25.07), 0.01 * arcsecond);
}

TEST(Geodesy, InverseOfTheSamePointAndOfNearlyAntipodalPoints)
{
    const auto same = inverse(0.7, -0.15, 0.7, -0.15);
    ASSERT_TRUE(same);
    EXPECT_EQ(same->distance, 0);
    // A quarter of the equator: a * pi / 2, heading east.
    const auto quarter = inverse(0, 0, 0, radians(90));
    ASSERT_TRUE(quarter);
    EXPECT_NEAR(quarter->distance, wgs84.a * M_PI / 2, 1e-4); // Vincenty's series: micrometres
    EXPECT_NEAR(quarter->initialAzimuth, M_PI / 2, 1e-12);
    // Vincenty does not converge here; say so rather than return a wrong number.
    EXPECT_FALSE(inverse(0, 0, radians(0.5), radians(179.7)));
}

// An IMC EstimatedState: reference plus NED offsets, as DUNE displaces it.
TEST(Geodesy, ImcPositionMovesTheReferenceByItsOffsets)
{
    const double lat = radians(41.18), lon = radians(-8.70);
    const auto here = imcPosition(lat, lon, 0, 0, 0, 0);
    EXPECT_EQ(here.lat, lat);
    EXPECT_EQ(here.lon, lon);

    const auto moved = imcPosition(lat, lon, 0, 300, -400, 2);
    const auto g = inverse(lat, lon, moved.lat, moved.lon);
    ASSERT_TRUE(g);
    EXPECT_NEAR(g->distance, 500, 0.02);                          // a straight 500 m, nearly on the surface
    EXPECT_NEAR(g->initialAzimuth, 2 * M_PI + std::atan2(-400, 300), 1e-4);
    EXPECT_NEAR(moved.height, -2, 0.05);                           // 2 m down (the Earth's curve adds ~2 cm)
    const auto ned = toNed(moved, here);
    EXPECT_NEAR((ned - Eigen::Vector3d(300, -400, 2)).norm(), 0, 1e-6);
}

// Web Mercator as the OpenStreetMap tile scheme uses it.
TEST(Geodesy, WebMercator)
{
    EXPECT_NEAR((toMercator(0, 0) - Eigen::Vector2d(0.5, 0.5)).norm(), 0, 1e-15);
    // The projection's edge is the latitude where the map is square: 85.0511287798°.
    EXPECT_NEAR(toMercator(radians(85.0511287798), radians(-180)).norm(), 0, 1e-10);
    // Google Maps JavaScript API, "Map and tile coordinates": Chicago (41.85, -87.65)
    // has world coordinate (65.67, 95.17) on the 256-unit world.
    // (A Vector2d, not auto: an Eigen expression would outlive its operand.)
    const Eigen::Vector2d world = toMercator(radians(41.85), radians(-87.65)) * 256;
    EXPECT_NEAR(world.x(), 65.67, 0.005);
    EXPECT_NEAR(world.y(), 95.17, 0.005);
    // OpenStreetMap wiki, "Zoom levels": 156,543.03 m per pixel at the equator at zoom 0, halving per level.
    EXPECT_NEAR(metresPerPixel(0, 0), 156543.03, 0.01);
    EXPECT_NEAR(metresPerPixel(radians(60), 18), 156543.03 / 2 / (1 << 18), 1e-6);
    const auto back = fromMercator(toMercator(radians(-33.9), radians(151.2)));
    EXPECT_NEAR(degrees(back.x()), -33.9, 1e-12);
    EXPECT_NEAR(degrees(back.y()), 151.2, 1e-12);
}

// A line thinned for drawing: points within the tolerance of the last kept
// (in x and in y) left out, the ends always kept.
TEST(Polygon, ThinnedKeepsTheEndsAndDropsWhatIsCloserThanTheTolerance)
{
    const std::vector<std::pair<double, double>> line{{0, 0}, {0.4, 0.1}, {1, 0}, {1.2, 0.3}, {1.3, 0.2}, {3, 0}, {3.1, 0}};
    const auto kept = neptus::geo::thinned(line, 1.0, [](const auto &p) { return p; });
    const std::vector<std::pair<double, double>> expected{{0, 0}, {1, 0}, {3, 0}, {3.1, 0}};
    EXPECT_EQ(kept, expected);
    EXPECT_EQ(neptus::geo::thinned(line, 0.0, [](const auto &p) { return p; }), line) << "nothing dropped at 0";
    EXPECT_TRUE(neptus::geo::thinned(std::vector<std::pair<double, double>>{}, 1.0, [](const auto &p) { return p; }).empty());
}
