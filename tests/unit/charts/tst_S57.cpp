// A real NOAA ENC cell (../shared/fixtures/charts, its README's figures) read
// with GDAL, in this process and through the helper with its cache; and the
// helper's failures (a damaged cell, a crash, a hang) as errors naming the cell.
#include "charts/ChartFiles.h"
#include "charts/S57Reader.h"

#include "Fixtures.h"

#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>

#include <algorithm>
#include <tuple>

#include <gtest/gtest.h>

using namespace neptus::charts;
using namespace Qt::StringLiterals;

namespace {

QString writeFile(const QTemporaryDir &dir, const QString &name, const QByteArray &bytes)
{
    const QString path = dir.filePath(name);
    QFile file(path);
    file.open(QIODevice::WriteOnly);
    file.write(bytes);
    file.close();
    return path;
}

} // namespace

TEST(S57, TheNoaaCellReadsAsItsReadmeCountsWithItsUpdatesApplied)
{
    NEPTUS_REQUIRE_FIXTURE(path, "charts/US4MD81M/US4MD81M.000");
    const auto cell = readS57(path);
    ASSERT_TRUE(cell) << cell.error().toStdString();
    EXPECT_EQ(cell->name, u"US4MD81M.000"_s);
    EXPECT_EQ(cell->edition, 31);
    EXPECT_EQ(cell->update, 3) << "the three update files applied";
    EXPECT_EQ(cell->usageBand, 4);
    EXPECT_EQ(cell->scale, 80000);
    EXPECT_EQ(cell->comment, u"Produced by NOAA"_s);
    const QMap<QString, int> expected{
        {u"DEPARE"_s, 525}, {u"DEPCNT"_s, 566}, {u"SOUNDG"_s, 56}, {u"DRGARE"_s, 7}, {u"LNDARE"_s, 183},
        {u"COALNE"_s, 1826}, {u"RESARE"_s, 12}, {u"CTNARE"_s, 55}, {u"MIPARE"_s, 3}, {u"OBSTRN"_s, 219},
        {u"WRECKS"_s, 111}, {u"UWTROC"_s, 18}, {u"BOYLAT"_s, 71}, {u"BOYSPP"_s, 19}, {u"BOYSAW"_s, 2},
        {u"BCNLAT"_s, 194}, {u"BCNSPP"_s, 30}, {u"LIGHTS"_s, 151}, {u"FAIRWY"_s, 20}};
    const auto counts = cell->counts();
    for (auto it = expected.cbegin(); it != expected.cend(); ++it)
        EXPECT_EQ(counts.value(it.key()), it.value()) << it.key().toStdString();
    int soundings = 0, pointLand = 0;
    for (const Feature &f : cell->features) {
        if (f.objectClass == u"SOUNDG")
            for (const auto &p : f.parts)
                soundings += int(p.size());
        pointLand += f.objectClass == u"LNDARE" && f.geometry == Feature::Geometry::Point;
    }
    EXPECT_EQ(soundings, 3326);
    EXPECT_EQ(pointLand, 21) << "162 land polygons and 21 points";
    const auto b = cell->bounds();
    EXPECT_NEAR(b.west, -76.58278, 1e-5);
    EXPECT_NEAR(b.east, -76.02961, 1e-5);
    EXPECT_NEAR(b.south, 38.36667, 1e-5);
    EXPECT_NEAR(b.north, 39.03333, 1e-5);

    // The README's probe points.
    const std::vector<Cell> cells{*cell};
    EXPECT_TRUE(reportAt(cells, -76.544591, 38.381221).land);
    const auto shallow = reportAt(cells, -76.114104, 38.679014);
    EXPECT_FALSE(shallow.land);
    EXPECT_EQ(shallow.depthMin, 0.0);
    EXPECT_EQ(shallow.depthMax, 1.8);
    EXPECT_EQ(shallow.place, u"Island Creek"_s);
    const auto deep = reportAt(cells, -76.312942, 38.850300);
    EXPECT_EQ(deep.depthMin, 10.9);
    EXPECT_EQ(deep.depthMax, 18.2);
    EXPECT_EQ(deep.place, u"Eastern Bay"_s);
    ASSERT_TRUE(deep.sounding);
    EXPECT_NEAR(*deep.sounding, 12.4, 1e-6);
    EXPECT_NEAR(deep.soundingDistance, 177, 2);
    for (const auto &probe : {shallow, deep}) {
        EXPECT_TRUE(probe.hazards.empty());
        EXPECT_TRUE(probe.restrictions.empty());
    }
}

TEST(S57, TheHelperReadsACellOnceAndTheCacheAnswersAfter)
{
    NEPTUS_REQUIRE_FIXTURE(path, "charts/US4MD81M");
    QTemporaryDir cache;
    LoadOptions options;
    options.cacheDir = cache.path();
    std::vector<QString> seen;
    const auto first = loadCells(path, options, [&](int done, int total, const QString &cell) {
        EXPECT_EQ(total, 1);
        EXPECT_EQ(done, 0);
        seen.push_back(cell);
    });
    ASSERT_TRUE(first) << first.error().toStdString();
    ASSERT_EQ(first->size(), 1u);
    ASSERT_EQ(seen.size(), 1u);
    EXPECT_TRUE(seen[0].endsWith(u"US4MD81M.000"_s));
    EXPECT_EQ(first->front().counts().value(u"WRECKS"_s), 111);
    // Its sector light (ogrinfo: LIGHTS 587-590 at -76.4358, 38.8990, white 51.5-96.5, red
    // 96.5-202, white 202-11, red 11-51.5, bearings from seaward): the four sectors as
    // directions from the light, half a circle round, the third across north.
    std::vector<std::tuple<double, double, AidColour>> sectors;
    for (const Feature &f : first->front().features)
        if (const auto sector = lightSector(f))
            sectors.emplace_back(sector->from, sector->to, aidColour(f));
    std::ranges::sort(sectors);
    EXPECT_EQ(sectors, (std::vector<std::tuple<double, double, AidColour>>{{22, 191, AidColour::Yellow}, {191, 231.5, AidColour::Red},
                                                                          {231.5, 276.5, AidColour::Yellow}, {276.5, 22, AidColour::Red}}))
        << "white lights are drawn yellow, as S-52 draws them";
    // Its aids of several colours (ogrinfo: COLPAT 1 on 1 BOYLAT, 16 BOYSPP and 4 BCNLAT, COLPAT 2 on
    // 2 BOYSAW and 2 BCNSPP): filled with their bands; South River Junction Buoy SR green-red-green.
    QMap<QString, int> banded;
    for (const Feature &f : first->front().features)
        if (const auto bands = aidBands(f)) {
            ++banded[f.objectClass + u' ' + patternName(bands->pattern)];
            if (f.name() == u"South River Junction Buoy SR"_s) {
                EXPECT_EQ(bands->colours, (std::vector{AidColour::Green, AidColour::Red, AidColour::Green}));
            }
        }
    EXPECT_EQ(banded, (QMap<QString, int>{{u"BCNLAT horizontal"_s, 4}, {u"BCNSPP vertical"_s, 2}, {u"BOYLAT horizontal"_s, 1},
                                          {u"BOYSAW vertical"_s, 2}, {u"BOYSPP horizontal"_s, 16}}));
    bool fromCache = false;
    const auto again = loadCell(seen[0], options, &fromCache);
    ASSERT_TRUE(again) << again.error().toStdString();
    EXPECT_TRUE(fromCache);
    EXPECT_EQ(again->features.size(), first->front().features.size());
    EXPECT_EQ(QDir(cache.path()).entryList({u"*.nqchart"_s}).size(), 1);

    // A damaged cache file is read again from the cell, and replaced.
    const QString cached = QDir(cache.path()).entryInfoList({u"*.nqchart"_s}).value(0).absoluteFilePath();
    writeFile(cache, QFileInfo(cached).fileName(), "NQCHART2\ngarbage");
    const auto mended = loadCell(seen[0], options, &fromCache);
    ASSERT_TRUE(mended) << mended.error().toStdString();
    EXPECT_FALSE(fromCache);
    EXPECT_TRUE(loadCell(seen[0], options, &fromCache) && fromCache);
}

TEST(S57, AChartThatCannotBeReadIsAnErrorNamingIt)
{
    QTemporaryDir dir;
    LoadOptions options;
    options.cacheDir = dir.filePath(u"cache"_s);
    const QString damaged = writeFile(dir, u"XX4BAD.000"_s, QByteArray(4096, 'x'));
    const auto result = loadCell(damaged, options);
    ASSERT_FALSE(result);
    EXPECT_TRUE(result.error().startsWith(damaged + u": not an S-57 cell"_s)) << result.error().toStdString();
    EXPECT_EQ(findCells(dir.filePath(u"nothing"_s)).error(), dir.filePath(u"nothing"_s) + u": no such file or folder"_s);
    QDir(dir.path()).mkdir(u"empty"_s);
    EXPECT_EQ(findCells(dir.filePath(u"empty"_s)).error(), dir.filePath(u"empty"_s) + u": holds no S-57 cell (*.000)"_s);

    // The reader crashing or hanging costs an error, never the caller.
    const QString crasher = writeFile(dir, u"crash-helper"_s, "#!/bin/sh\nkill -SEGV $$\n");
    QFile::setPermissions(crasher, QFile::ReadOwner | QFile::ExeOwner);
    options.helper = crasher;
    EXPECT_EQ(loadCell(damaged, options).error(), damaged + u": the S-57 reader crashed on it (the cell is damaged)"_s);
    const QString slow = writeFile(dir, u"slow-helper"_s, "#!/bin/sh\nexec sleep 30\n");
    QFile::setPermissions(slow, QFile::ReadOwner | QFile::ExeOwner);
    options.helper = slow;
    options.timeout = std::chrono::milliseconds(300);
    EXPECT_EQ(loadCell(damaged, options).error(), damaged + u": reading took longer than 0.3 s, stopped"_s);
    options.helper = u"/nonexistent/neptus-chart-import"_s;
    EXPECT_TRUE(loadCell(damaged, options).error().contains(u"the helper /nonexistent/neptus-chart-import is missing"_s));
}
