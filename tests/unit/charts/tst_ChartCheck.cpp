// Plans checked against the NOAA cell of ../shared/fixtures/charts: land,
// water shallower than the vehicle needs, leaving the charts, and a plan in
// open water that the charts let through.
#include "charts/ChartCheck.h"
#include "charts/S57Reader.h"
#include "mission/MissionXml.h"

#include "Fixtures.h"
#include "Missions.h"

#include <gtest/gtest.h>

using namespace neptus;
using namespace neptus::charts;
using namespace Qt::StringLiterals;

namespace {

// Across Eastern Bay, Chesapeake Bay (the README's deep probe point is the first Goto).
const char *const missionText = R"(<mission format="1" id="bay" name="Eastern Bay">
  <home lat="38.8503" lon="-76.312942" height="0"/>
  <vehicle id="boat"/><vehicle id="auv"/>
  <plan id="ashore" vehicle="boat" start="a">
    <maneuvers>
      <Goto id="a" lat="38.8503" lon="-76.33" z="0" z_units="DEPTH" speed="2"/>
      <Goto id="b" lat="38.8503" lon="-76.39" z="0" z_units="DEPTH" speed="2"/>
    </maneuvers>
    <transition from="a" to="b"/>
  </plan>
  <plan id="deep" vehicle="auv" start="d">
    <maneuvers><Goto id="d" lat="38.8503" lon="-76.312942" z="15" z_units="DEPTH" speed="1.5"/></maneuvers>
  </plan>
  <plan id="open" vehicle="boat" start="o1">
    <maneuvers>
      <Goto id="o1" lat="38.8503" lon="-76.312942" z="0" z_units="DEPTH" speed="2"/>
      <Goto id="o2" lat="38.8503" lon="-76.30" z="0" z_units="DEPTH" speed="2"/>
    </maneuvers>
    <transition from="o1" to="o2"/>
  </plan>
  <plan id="away" vehicle="boat" start="x">
    <maneuvers><Goto id="x" lat="38.5" lon="-75.0" z="0" z_units="DEPTH" speed="2"/></maneuvers>
  </plan>
</mission>)";

mission::VehicleDefinition vehicle(const QString &id, const QString &kind)
{
    mission::VehicleDefinition v;
    v.id = id;
    v.kind = kind;
    if (kind == u"USV")
        v.limits.draft = 0.3;
    else
        v.limits.minAltitude = 2;
    return v;
}

QStringList said(const QList<mission::PlanProblem> &problems)
{
    QStringList out;
    for (const auto &p : problems)
        out << (p.severity == mission::PlanProblem::Severity::Error ? u"error: "_s : u"warning: "_s) + p.message
                   + (p.verdict().isEmpty() ? QString() : u" ("_s + p.verdict() + u')');
    return out;
}

} // namespace

TEST(ChartCheck, PlansAgainstTheNoaaCell)
{
    NEPTUS_REQUIRE_FIXTURE(path, "charts/US4MD81M/US4MD81M.000");
    auto cell = readS57(path);
    ASSERT_TRUE(cell) << cell.error().toStdString();
    cell->index();
    const std::vector<Cell> cells{*cell};
    const auto m = mission::readMission(QByteArray(missionText), u"bay.xml"_s);
    ASSERT_TRUE(m) << test::errorsText(m.error()).toStdString();
    const auto boat = vehicle(u"boat"_s, u"USV"_s), auv = vehicle(u"auv"_s, u"UUV"_s);
    const auto check = [&](const char *plan, const mission::VehicleDefinition &v) {
        return checkAgainstCharts(mission::planGeometry(*m->plan(QString::fromLatin1(plan))), &v, cells);
    };

    // A boat driven ashore: land, where the leg reaches it (about 38.8503, -76.37).
    const auto ashore = check("ashore", boat);
    const QString text = said(ashore).join(u'\n');
    ASSERT_FALSE(ashore.isEmpty());
    EXPECT_EQ(ashore[0].severity, mission::PlanProblem::Severity::Error);
    const auto land = std::find_if(ashore.begin(), ashore.end(), [](const auto &p) { return p.kind == mission::PlanProblem::Kind::ChartLand; });
    ASSERT_NE(land, ashore.end()) << text.toStdString();
    EXPECT_EQ(land->maneuver, u"b"_s);
    EXPECT_EQ(land->message, u"'b' (Goto): a leg crosses land (chart US4MD81M.000)"_s);
    EXPECT_EQ(land->verdict(), u"unsafe"_s);
    EXPECT_NEAR(*land->lat, 38.8503, 1e-6);
    EXPECT_GT(*land->lon, -76.372);
    EXPECT_LT(*land->lon, -76.35);

    // An AUV planned at 15 m where the chart says 10.9–18.2 m needs 17 m: unsafe.
    const auto deep = check("deep", auv);
    ASSERT_EQ(deep.size(), 1) << said(deep).join(u'\n').toStdString();
    EXPECT_EQ(deep[0].kind, mission::PlanProblem::Kind::ChartShallow);
    EXPECT_EQ(deep[0].message, u"'d' (Goto): a leg enters water charted 10.9–18.2 m in Eastern Bay, shallower than the 17.0 m it "
                               "needs (15.0 m deep and 2.0 m above the bottom; chart US4MD81M.000)"_s);
    // The same place at 5 m is fine.
    mission::Plan shallower = *m->plan(u"deep"_s);
    shallower.maneuvers[0].set(u"z"_s, 5);
    EXPECT_TRUE(checkAgainstCharts(mission::planGeometry(shallower), &auv, cells).isEmpty());

    // Open water for a boat: nothing to say.
    EXPECT_TRUE(check("open", boat).isEmpty()) << said(check("open", boat)).join(u'\n').toStdString();

    // Off the charts: a warning, nothing more is known.
    const auto away = check("away", boat);
    ASSERT_EQ(away.size(), 1);
    EXPECT_EQ(away[0].kind, mission::PlanProblem::Kind::ChartCoverage);
    EXPECT_EQ(away[0].severity, mission::PlanProblem::Severity::Warning);

    // Aircraft fly over all of it.
    EXPECT_TRUE(check("ashore", vehicle(u"x8"_s, u"UAV"_s)).isEmpty());
}

TEST(ChartCheck, HazardsAndRestrictedAreasOnTheWay)
{
    // A wreck 3.5 m deep on the way of an AUV at 5 m, one 30 m deep further on, a restricted area crossed.
    Cell c;
    c.name = u"XX5TEST.000"_s;
    c.usageBand = 5;
    Feature cover;
    cover.objectClass = u"M_COVR"_s;
    cover.geometry = Feature::Geometry::Area;
    cover.attributes.insert(u"CATCOV"_s, u"1"_s);
    cover.parts = {{{-8.8, 41.1, 0}, {-8.6, 41.1, 0}, {-8.6, 41.2, 0}, {-8.8, 41.2, 0}}};
    c.features.push_back(cover);
    Feature depth = cover;
    depth.objectClass = u"DEPARE"_s;
    depth.attributes = {{u"DRVAL1"_s, u"10"_s}, {u"DRVAL2"_s, u"20"_s}};
    c.features.push_back(depth);
    // (Two wrecks alike, neither named: each is a problem of its own.)
    for (const auto &[lon, valsou] : {std::pair{-8.70, u"3.5"_s}, std::pair{-8.68, u"3.5"_s}, std::pair{-8.65, u"30"_s}}) {
        Feature wreck;
        wreck.objectClass = u"WRECKS"_s;
        wreck.attributes.insert(u"VALSOU"_s, valsou);
        wreck.parts = {{{lon, 41.15001, 0}}};
        c.features.push_back(wreck);
    }
    Feature range = cover;
    range.objectClass = u"RESARE"_s;
    range.attributes = {{u"OBJNAM"_s, u"Firing Range"_s}};
    range.parts = {{{-8.62, 41.14, 0}, {-8.61, 41.14, 0}, {-8.61, 41.16, 0}, {-8.62, 41.16, 0}}};
    c.features.push_back(range);
    c.index();
    mission::Plan plan;
    plan.id = u"p"_s;
    for (const auto &[id, lon] : {std::pair{u"w"_s, -8.75}, std::pair{u"e"_s, -8.605}}) {
        mission::Maneuver g;
        g.id = id;
        g.type = u"Goto"_s;
        g.set(u"lat"_s, 41.15);
        g.set(u"lon"_s, lon);
        g.set(u"speed"_s, 2);
        g.set(u"z"_s, 5);
        g.parameters.insert(u"z_units"_s, u"DEPTH"_s);
        plan.maneuvers.append(g);
    }
    plan.start = u"w"_s;
    plan.transitions.append({u"w"_s, u"e"_s, u"ManeuverIsDone"_s, {}, {}});
    const auto auv = vehicle(u"auv"_s, u"UUV"_s);
    const auto problems = checkAgainstCharts(mission::planGeometry(plan), &auv, {c});
    const QStringList text = said(problems);
    ASSERT_EQ(problems.size(), 3) << text.join(u'\n').toStdString();
    for (int i : {0, 1}) {
        EXPECT_TRUE(text[i].startsWith(u"error: 'e' (Goto): a leg passes "_s)) << text[i].toStdString();
        EXPECT_TRUE(text[i].endsWith(u"m from a wreck (charted depth 3.5 m; it needs 7.0 m) (unsafe)"_s)) << text[i].toStdString();
    }
    EXPECT_NEAR(*problems[0].lon, -8.70, 0.0005);
    EXPECT_NEAR(*problems[1].lon, -8.68, 0.0005);
    EXPECT_EQ(text[2], u"warning: 'e' (Goto): a leg enters a restricted area \"Firing Range\""_s);
}
