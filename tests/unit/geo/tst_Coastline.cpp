// The world coastline (GSHHG, Debian's gmt-gshhg packages): what is land and
// what is water, at every resolution, across the antimeridian, and clear
// errors for a missing or damaged file.
#include "geo/Coastline.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>
#include <netcdf.h>

#include <cmath>
#include <cstdio>

using neptus::geo::CoastArea;
using neptus::geo::Coastline;

namespace {

CoastArea readOrFail(const Coastline &coast, char resolution, double west, double south, double east, double north)
{
    QString error;
    CoastArea area = coast.read(resolution, west, south, east, north, &error);
    EXPECT_TRUE(error.isEmpty()) << error.toStdString();
    return area;
}

} // namespace

TEST(Coastline, DebianInstallsEveryResolution)
{
    Coastline coast;
    EXPECT_EQ(coast.available(), QStringLiteral("clihf")) << Coastline::defaultDirectory().toStdString();
}

TEST(Coastline, TheResolutionFollowsTheMapScale)
{
    Coastline coast;
    EXPECT_EQ(coast.resolutionFor(5), 'f');   // harbour: zoom 15
    EXPECT_EQ(coast.resolutionFor(30), 'f');
    EXPECT_EQ(coast.resolutionFor(150), 'h');
    EXPECT_EQ(coast.resolutionFor(600), 'i');
    EXPECT_EQ(coast.resolutionFor(3000), 'l');
    EXPECT_EQ(coast.resolutionFor(40000), 'c'); // the world
}

// The Douro mouth at Porto, at full resolution: the city is land, the sea
// off Foz and the open Atlantic are not, and there is a shore in between.
TEST(Coastline, PortoAndTheDouroMouth)
{
    Coastline coast;
    const CoastArea area = readOrFail(coast, 'f', -8.9, 41.0, -8.5, 41.3);
    EXPECT_GT(area.shores.size(), 0u);
    EXPECT_GT(area.pointCount(), 500u);
    EXPECT_TRUE(area.isLand(41.1496, -8.6110));  // Porto, Avenida dos Aliados
    EXPECT_TRUE(area.isLand(41.1230, -8.6110));  // Vila Nova de Gaia
    EXPECT_TRUE(area.isLand(41.2100, -8.6500));  // Matosinhos, inland
    EXPECT_FALSE(area.isLand(41.1500, -8.7500)); // off Foz do Douro
    EXPECT_FALSE(area.isLand(41.0500, -8.8800)); // open Atlantic
}

// Every level: sea round an island, a lake in a continent, a bin wholly
// inside a continent (no shore in it), and the open ocean.
TEST(Coastline, IslandsLakesAndContinents)
{
    Coastline coast;
    const CoastArea madeira = readOrFail(coast, 'i', -17.5, 32.3, -16.5, 33.2);
    EXPECT_TRUE(madeira.isLand(32.75, -16.95));
    EXPECT_FALSE(madeira.isLand(32.50, -16.95));

    const CoastArea geneva = readOrFail(coast, 'i', 6.0, 46.0, 7.0, 47.0);
    EXPECT_FALSE(geneva.isLand(46.45, 6.55)); // Lake Geneva (level 2)
    EXPECT_TRUE(geneva.isLand(46.70, 6.60));  // Vaud, north of it

    const CoastArea madrid = readOrFail(coast, 'h', -4.0, 40.2, -3.4, 40.6);
    EXPECT_TRUE(madrid.isLand(40.42, -3.70));

    const CoastArea atlantic = readOrFail(coast, 'l', -41, 34, -39, 36);
    EXPECT_FALSE(atlantic.isLand(35, -40));
}

// The whole world at crude resolution: land is about 29 % of the Earth's
// surface (Antarctica's ice front counted as land), which only comes out
// if every bin's rings close the right way.
TEST(Coastline, TheWorldIsAboutThirtyPercentLand)
{
    Coastline coast;
    const CoastArea world = readOrFail(coast, 'c', -180, -90, 180, 90);
    double land = 0, all = 0;
    for (double lat = -89; lat < 90; lat += 2) {
        for (double lon = -179; lon < 180; lon += 4) {
            const double w = std::cos(lat * M_PI / 180);
            all += w;
            if (world.isLand(lat, lon))
                land += w;
        }
    }
    EXPECT_NEAR(land / all, 0.29, 0.03);
    std::printf("land: %.1f %% of the surface\n", 100 * land / all);
}

// Fiji lies across 180°: a box from 175° E to 185° E (175° W) gives
// longitudes in its own frame, with Viti Levu and Vanua Levu as land.
TEST(Coastline, AcrossTheAntimeridian)
{
    Coastline coast;
    const CoastArea fiji = readOrFail(coast, 'i', 175, -20, 185, -15);
    EXPECT_TRUE(fiji.isLand(-17.80, 178.00));   // Viti Levu
    EXPECT_TRUE(fiji.isLand(-16.60, 179.20));   // Vanua Levu
    EXPECT_FALSE(fiji.isLand(-18.50, 182.00));  // the sea east of Lau
    for (const auto &shore : fiji.shores) {
        for (const auto &p : shore)
            ASSERT_TRUE(p.lon >= 175 && p.lon <= 185) << p.lon;
    }
}

TEST(Coastline, AMissingFolderIsNamed)
{
    Coastline coast(QStringLiteral("/nonexistent/gshhg"));
    EXPECT_EQ(coast.available(), QString());
    EXPECT_EQ(coast.resolutionFor(10), 0);
    QString error;
    const CoastArea area = coast.read('f', -9, 41, -8, 42, &error);
    EXPECT_TRUE(area.shores.empty());
    EXPECT_TRUE(error.contains(QStringLiteral("/nonexistent/gshhg/binned_GSHHS_f.nc"))) << error.toStdString();
    EXPECT_TRUE(error.contains(QStringLiteral("gmt-gshhg"))) << error.toStdString();
}

TEST(Coastline, DamagedFilesAreRefusedWithTheirName)
{
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    // Not netCDF at all.
    QFile junk(dir.filePath(QStringLiteral("binned_GSHHS_c.nc")));
    ASSERT_TRUE(junk.open(QIODevice::WriteOnly));
    junk.write(QByteArray(4096, 'x'));
    junk.close();
    // netCDF, but its bins do not tile the world.
    const QByteArray wrong = QFile::encodeName(dir.filePath(QStringLiteral("binned_GSHHS_l.nc")));
    int id = -1, dim = -1;
    ASSERT_EQ(nc_create(wrong.constData(), NC_CLOBBER, &id), NC_NOERR);
    ASSERT_EQ(nc_def_dim(id, "one", 1, &dim), NC_NOERR);
    const char *names[] = {"Bin_size_in_minutes", "N_bins_in_360_longitude_range", "N_bins_in_180_degree_latitude_range",
                           "N_bins_in_file", "N_segments_in_file", "N_points_in_file"};
    const int values[] = {20, 1080, 540, 12, 0, 0};
    int vars[6];
    for (int i = 0; i < 6; ++i)
        ASSERT_EQ(nc_def_var(id, names[i], NC_INT, 1, &dim, &vars[i]), NC_NOERR);
    ASSERT_EQ(nc_enddef(id), NC_NOERR);
    for (int i = 0; i < 6; ++i)
        ASSERT_EQ(nc_put_var_int(id, vars[i], &values[i]), NC_NOERR);
    ASSERT_EQ(nc_close(id), NC_NOERR);

    Coastline coast(dir.path());
    EXPECT_EQ(coast.available(), QStringLiteral("cl"));
    QString error;
    coast.read('c', -9, 41, -8, 42, &error);
    EXPECT_TRUE(error.startsWith(dir.filePath(QStringLiteral("binned_GSHHS_c.nc")))) << error.toStdString();
    coast.read('l', -9, 41, -8, 42, &error);
    EXPECT_TRUE(error.startsWith(QString::fromUtf8(wrong))) << error.toStdString();
    EXPECT_TRUE(error.contains(QStringLiteral("do not make"))) << error.toStdString();
    coast.read('x', -9, 41, -8, 42, &error);
    EXPECT_FALSE(error.isEmpty());
}
