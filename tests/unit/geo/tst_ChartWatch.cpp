// The charted water under each vehicle, watched as it moves: a boat driven
// onto a shoal or ashore raises its chart alarm, back in deep water it
// clears; an AUV at depth needs its depth plus its minimum altitude; off the
// charts is said; aircraft and unknown systems are not judged.
#include "alarms/AlarmGraph.h"
#include "geo/Geodesy.h"
#include "charts/Chart.h"
#include "qmlmodels/ChartWatch.h"
#include "qmlmodels/Tracks.h"
#include "qmlmodels/VariableTreeModel.h"

#include <gtest/gtest.h>

using namespace neptus;
using namespace Qt::StringLiterals;

namespace {

// A 0.1° cell: land west of -8.78, a 0-0.5 m shoal at -8.76…-8.75, 10-20 m east of it (and 3-4 m between).
std::shared_ptr<const std::vector<charts::Cell>> cells()
{
    const auto area = [](const QString &cls, double west, double east, QMap<QString, QString> attributes) {
        charts::Feature f;
        f.objectClass = cls;
        f.geometry = charts::Feature::Geometry::Area;
        f.parts = {{{west, 41.1, 0}, {east, 41.1, 0}, {east, 41.2, 0}, {west, 41.2, 0}}};
        f.attributes = std::move(attributes);
        return f;
    };
    charts::Cell c;
    c.name = u"XX5TEST.000"_s;
    c.usageBand = 5;
    c.features = {area(u"M_COVR"_s, -8.8, -8.7, {{u"CATCOV"_s, u"1"_s}}), area(u"LNDARE"_s, -8.8, -8.78, {}),
                  area(u"DEPARE"_s, -8.78, -8.76, {{u"DRVAL1"_s, u"3"_s}, {u"DRVAL2"_s, u"4"_s}}),
                  area(u"DEPARE"_s, -8.76, -8.75, {{u"DRVAL1"_s, u"0"_s}, {u"DRVAL2"_s, u"0.5"_s}}),
                  area(u"DEPARE"_s, -8.75, -8.7, {{u"DRVAL1"_s, u"10"_s}, {u"DRVAL2"_s, u"20"_s}})};
    c.index();
    return std::make_shared<const std::vector<charts::Cell>>(std::vector<charts::Cell>{c});
}

mission::VehicleDefinition vehicle(const QString &id, const QString &kind)
{
    mission::VehicleDefinition v;
    v.id = id;
    v.kind = kind;
    v.limits.draft = 0.3;
    v.limits.minAltitude = 2;
    return v;
}

struct Watching : ::testing::Test
{
    tree::VariableTree tree;
    tree::VariableTreeModel model{&tree};
    geo::Tracks tracks{&model};
    alarms::AlarmGraph graph;
    ChartWatch watch{&tracks, &graph};
    Watching()
    {
        mission::VehicleCatalog catalog;
        catalog.vehicles = {vehicle(u"boat"_s, u"USV"_s), vehicle(u"auv"_s, u"UUV"_s), vehicle(u"plane"_s, u"UAV"_s)};
        watch.setVehicles(catalog);
        watch.setCells(cells());
    }
    void at(const QString &system, double lon, double depth = 0)
    {
        geo::Tracks::Fix fix;
        fix.time = 1000 + ++n;
        fix.lat = geo::radians(41.15);
        fix.lon = geo::radians(lon);
        fix.depth = float(depth);
        tracks.append(system, fix);
        watch.check();
    }
    std::pair<alarms::Level, QString> alarm(const QString &system) const
    {
        const auto node = graph.find(u"systems/%1/chart"_s.arg(system));
        return node == alarms::AlarmGraph::noNode ? std::pair{alarms::Unknown, QString()}
                                                  : std::pair{graph.ownLevel(node), graph.message(node)};
    }
    int n = 0;
};

} // namespace

TEST_F(Watching, ABoatOnAShoalOrAshoreRaisesItsChartAlarmAndDeepWaterClearsIt)
{
    at(u"boat"_s, -8.72);
    EXPECT_EQ(alarm(u"boat"_s).first, alarms::Normal);
    EXPECT_EQ(watch.under(u"boat"_s).value(u"text"_s).toString(), u"charted 10.0–20.0 m"_s);
    at(u"boat"_s, -8.755);
    EXPECT_EQ(alarm(u"boat"_s), (std::pair{alarms::Error, u"boat is in water charted 0.0–0.5 m, shallower than the 0.8 m it needs"_s}));
    at(u"boat"_s, -8.79);
    EXPECT_EQ(alarm(u"boat"_s), (std::pair{alarms::Error, u"boat is on land on the chart (XX5TEST.000)"_s}));
    at(u"boat"_s, -8.72);
    EXPECT_EQ(alarm(u"boat"_s).first, alarms::Normal) << "back in deep water";
    at(u"boat"_s, -8.5);
    EXPECT_EQ(alarm(u"boat"_s), (std::pair{alarms::Info, u"boat is off the charts: the water there is not known"_s}));
}

TEST_F(Watching, AnAuvAtDepthNeedsItsDepthAndItsMinimumAltitude)
{
    at(u"auv"_s, -8.77, 1); // 3-4 m charted, 1 + 2 needed
    EXPECT_EQ(alarm(u"auv"_s).first, alarms::Normal);
    at(u"auv"_s, -8.77, 2); // 2 + 2 > 3
    EXPECT_EQ(alarm(u"auv"_s), (std::pair{alarms::Error, u"auv is in water charted 3.0–4.0 m, shallower than the 4.0 m it needs"_s}));
    EXPECT_EQ(watch.under(u"auv"_s).value(u"need"_s).toDouble(), 4);
}

TEST_F(Watching, AircraftAndSystemsWithNoDefinitionAreNotJudged)
{
    at(u"plane"_s, -8.79);
    at(u"0x4001"_s, -8.79);
    EXPECT_EQ(alarm(u"plane"_s).first, alarms::Unknown);
    EXPECT_EQ(alarm(u"0x4001"_s).first, alarms::Unknown);
    EXPECT_TRUE(watch.under(u"plane"_s).isEmpty());
}

// A label asks under() as often as it is drawn; the charts are looked up
// once a look (a second), and under() says what that look found.
TEST_F(Watching, UnderSaysWhatTheLastLookFoundAndEachLookCounts)
{
    const int before = watch.revision();
    at(u"boat"_s, -8.72);
    EXPECT_EQ(watch.revision(), before + 1);
    EXPECT_EQ(watch.under(u"boat"_s).value(u"text"_s).toString(), u"charted 10.0–20.0 m"_s);
    geo::Tracks::Fix fix;
    fix.time = 5000;
    fix.lat = geo::radians(41.15);
    fix.lon = geo::radians(-8.755);
    tracks.append(u"boat"_s, fix); // over the shoal, not looked at yet
    EXPECT_EQ(watch.under(u"boat"_s).value(u"text"_s).toString(), u"charted 10.0–20.0 m"_s);
    watch.check();
    EXPECT_EQ(watch.revision(), before + 2);
    EXPECT_EQ(watch.under(u"boat"_s).value(u"safe"_s).toBool(), false);
}
