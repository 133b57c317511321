// The simulators' waters: tools/run shows the demo where the map is true.
#include "geo/Coastline.h"
#include "geo/Geodesy.h"
#include "mission/MissionXml.h"
#include "mission/PlanGeometry.h"
#include "sim/Scenario.h"

#include "Paths.h"

#include <QFile>

#include <gtest/gtest.h>

#include <cmath>

using neptus::geo::CoastArea;
using neptus::geo::Coastline;
using namespace Qt::StringLiterals;

// The demo is where the map is true: every point tools/run shows — the
// simulators' circles (their default and docs/examples/leixoes-sims.json), the
// example mission's home, map features and every point its plans make the
// vehicles visit — is sea at GSHHG's full resolution, so no screenshot draws a
// vehicle on land.
TEST(DemoWaters, EverythingToolsRunShowsIsAtSea)
{
    using namespace neptus;
    Coastline coast;
    QString error;
    const CoastArea area = coast.read('f', -8.9, 41.0, -8.5, 41.3, &error);
    ASSERT_TRUE(error.isEmpty()) << error.toStdString();
    ASSERT_GT(area.rings.size(), 0u);
    int checked = 0;
    auto atSea = [&](double lat, double lon, const std::string &what) {
        ++checked;
        EXPECT_FALSE(area.isLand(lat, lon)) << what << " at " << lat << ", " << lon << " is on land";
    };
    // A circle of `radius` metres around a point: where a simulator drives.
    auto circleAtSea = [&](double lat, double lon, double radius, const std::string &what) {
        for (int degrees = 0; degrees < 360; degrees += 15) {
            const Eigen::Vector3d ned{radius * std::cos(geo::radians(degrees)), radius * std::sin(geo::radians(degrees)), 0};
            const geo::Geodetic p = geo::fromNed(ned, geo::Geodetic{geo::radians(lat), geo::radians(lon), 0});
            atSea(geo::degrees(p.lat), geo::degrees(p.lon), what);
        }
    };
    const sim::SimulatedVehicle::Config standard;
    circleAtSea(standard.latDeg, standard.lonDeg, standard.radiusM, "neptus-sim's default circle");

    QFile scenarioFile(test::sourcePath(u"docs/examples/leixoes-sims.json"_s));
    ASSERT_TRUE(scenarioFile.open(QIODevice::ReadOnly));
    const auto scenario = sim::readScenario(scenarioFile.readAll(), scenarioFile.fileName());
    ASSERT_TRUE(scenario.has_value()) << scenario.error().toStdString();
    for (const sim::ScenarioVehicle &v : scenario->vehicles)
        circleAtSea(v.config.latDeg, v.config.lonDeg, v.config.radiusM, v.config.name.toStdString());

    const auto mission = mission::loadMission(test::sourcePath(u"docs/examples/leixoes.xml"_s));
    ASSERT_TRUE(mission.has_value());
    atSea(mission->home.lat, mission->home.lon, "home");
    for (const mission::Map &map : mission->maps)
        for (const mission::Feature &f : map.features)
            for (const mission::Feature::Point &point : QList{f.position} + f.points)
                if (const auto at = mission->position(point))
                    atSea(at->lat, at->lon, f.id.toStdString());
    for (const mission::Plan &plan : mission->plans)
        for (const mission::ManeuverGeometry &m : mission::planGeometry(plan).maneuvers)
            for (const mission::Waypoint &w : m.points)
                atSea(w.lat, w.lon, (plan.id + u'/' + m.id).toStdString());
    EXPECT_GT(checked, 100);
}
