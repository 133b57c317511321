// Plans executed end to end: a console (session::Console with its links and
// a plans::PlanClient) sends a plan to neptus-sim processes, checks the
// vehicle holds exactly that plan, starts it and follows it in its variable
// tree to the vehicle's word that it ended; over IMC/UDP and over DDS.
// Vehicles run 30 simulated seconds per second (--time-factor).
#include "geo/Geodesy.h"
#include "mission/ImcPlan.h"
#include "mission/MissionXml.h"
#include "mission/NeptusImport.h"
#include "mission/PlanGeometry.h"
#include "plans/PlanClient.h"
#include "plans/PlanDatabase.h"
#include "plans/PlanDesk.h"
#include "session/Console.h"

#include "Missions.h"
#include "Schemas.h"
#include "PlanRun.h"
#include "SimProcess.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

#include <limits>

using namespace neptus;
using namespace Qt::StringLiterals;
using namespace neptus::test;


TEST(PlanExecution, AnAuvOverImcRunsGotoLoiterRowsToTheEndWhileASecondConsoleWatches)
{
    test::SimProcess vehicle;
    vehicle.start({u"--id"_s, u"0x1f"_s, u"--name"_s, u"lauv-sim-1"_s, u"--port"_s, u"16120"_s, u"--time-factor"_s, u"30"_s});
    const transport::ImcUdpConfig config = imcTo({16120});
    session::Console console(test::shippedSchema()), watcher(test::shippedSchema());
    ASSERT_TRUE(console.startImc(config));
    ASSERT_TRUE(watcher.startImc(config));
    ASSERT_TRUE(QTest::qWaitFor([&] { return heard(console.tree(), u"lauv-sim-1"_s) && heard(watcher.tree(), u"lauv-sim-1"_s); }, 15000));
    runPlan(console, 0x1f, u"lauv-sim-1"_s, missionFor("lauv-sim-1", 2, "DEPTH"), &watcher);
}

TEST(PlanExecution, AUsvOverDdsRunsGotoLoiterRowsToTheEnd)
{
    session::Console console(test::shippedSchema());
    ASSERT_TRUE(console.startDds({9, {}, 0x4001}));
    test::SimProcess vehicle;
    vehicle.start({u"--dds"_s, u"--dds-domain"_s, u"9"_s, u"--id"_s, u"0x42"_s, u"--name"_s, u"caravela-sim"_s,
                   u"--kind"_s, u"asv"_s, u"--port"_s, u"16121"_s, u"--time-factor"_s, u"30"_s});
    ASSERT_TRUE(QTest::qWaitFor([&] { return heard(console.tree(), u"caravela-sim"_s); }, 20000));
    runPlan(console, 0x42, u"caravela-sim"_s, missionFor("caravela-sim", 0, "DEPTH"));
}

// A vehicle that takes only the first transition (as DUNE does) is given a
// plan whose second maneuver may start only when another vehicle is within
// 50 m of a mark: the console carries it out, stretch by stretch. The other
// vehicle (over DDS) gets there by a plan of its own, later.
TEST(PlanExecution, AConditionalTransitionIsCarriedOutByTheConsoleForAFirstTransitionVehicle)
{
    test::SimProcess auv, usv;
    auv.start({u"--id"_s, u"0x1f"_s, u"--name"_s, u"lauv-sim-1"_s, u"--port"_s, u"16122"_s, u"--time-factor"_s, u"30"_s,
               u"--transitions"_s, u"first"_s});
    session::Console console(test::shippedSchema());
    const transport::ImcUdpConfig config = imcTo({16122});
    ASSERT_TRUE(console.startImc(config));
    ASSERT_TRUE(console.startDds({11, {}, 0x4001}));
    usv.start({u"--dds"_s, u"--dds-domain"_s, u"11"_s, u"--id"_s, u"0x42"_s, u"--name"_s, u"caravela-sim"_s,
               u"--kind"_s, u"asv"_s, u"--port"_s, u"16123"_s, u"--time-factor"_s, u"30"_s});
    ASSERT_TRUE(QTest::qWaitFor([&] { return heard(console.tree(), u"lauv-sim-1"_s) && heard(console.tree(), u"caravela-sim"_s); }, 20000));

    plans::PlanDesk desk(test::shippedSchema(), console.tree(), console.alarmGraph(),
                         [&](quint16 id, const msg::Message &m) { return console.send(id, m); },
                         [&] { return console.scripts(); });
    QObject::connect(&console, &session::Console::planMessageReceived, &desk, &plans::PlanDesk::receive);
    auto mission = mission::readMission(QByteArrayLiteral(R"X(<?xml version="1.0" encoding="UTF-8"?>
<mission format="1" id="meet" name="Meet at the buoy">
  <home lat="41.1705" lon="-8.7150" height="0"/>
  <vehicle id="lauv-sim-1"/>
  <vehicle id="caravela-sim"/>
  <map id="m"><mark id="buoy" lat="41.1700" lon="-8.7140"/></map>
  <plan id="meet" vehicle="lauv-sim-1" start="out">
    <maneuvers>
      <Goto id="out" lat="41.1710" lon="-8.7150" z="0" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"/>
      <Goto id="dive" lat="41.1712" lon="-8.7145" z="3" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"/>
    </maneuvers>
    <transition from="out" to="dive" condition="distance(&quot;caravela-sim&quot;, &quot;buoy&quot;) &lt; 50"/>
  </plan>
  <plan id="later" vehicle="caravela-sim" start="away">
    <maneuvers>
      <StationKeeping id="away" lat="41.1690" lon="-8.7165" z="0" z_units="DEPTH" speed="2" speed_units="METERS_PS" duration="300" radius="10"/>
      <Goto id="buoy" lat="41.1700" lon="-8.7140" z="0" z_units="DEPTH" speed="2" speed_units="METERS_PS"/>
    </maneuvers>
    <transition from="away" to="buoy"/>
  </plan>
</mission>
)X"), u"meet.xml"_s);
    ASSERT_TRUE(mission) << test::errorsText(mission.error()).toStdString();
    desk.setMission(*mission);
    const QString auvName = u"lauv-sim-1"_s;
    const auto log = [&] { return desk.log(auvName).join(u'\n'); };
    ASSERT_TRUE(desk.start(auvName, u"meet"_s));
    ASSERT_TRUE(QTest::qWaitFor([&] { return log().contains(u"out done: waiting for"_s); }, 30000)) << log().toStdString();

    // The other vehicle: held away for 300 simulated seconds, then to the buoy.
    ASSERT_TRUE(desk.refresh(u"caravela-sim"_s));
    ASSERT_TRUE(QTest::qWaitFor([&] { return desk.fetched(u"caravela-sim"_s); }, 10000));
    ASSERT_TRUE(desk.send(u"caravela-sim"_s, u"later"_s));
    ASSERT_TRUE(QTest::qWaitFor([&] { return desk.sync(u"caravela-sim"_s, u"later"_s) == plans::Sync::Same; }, 10000));
    ASSERT_TRUE(desk.start(u"caravela-sim"_s, u"later"_s));
    QTest::qWait(3000); // 90 simulated seconds: the other vehicle is still away
    EXPECT_FALSE(log().contains(u"decided"_s)) << log().toStdString();

    ASSERT_TRUE(QTest::qWaitFor([&] { return log().contains(u"meet completed (supervised)"_s); }, 40000)) << log().toStdString();
    EXPECT_TRUE(log().contains(u"decided out → dive: distance(\"caravela-sim\", \"buoy\") < 50 (distance(\"caravela-sim\", \"buoy\") = "_s))
        << log().toStdString();
}

// Faults injected into a simulated vehicle (from its command line, at set
// times) raise the alarms an operator expects, and comms come back.
TEST(PlanExecution, EachInjectedFaultRaisesItsAlarm)
{
    test::SimProcess vehicle;
    vehicle.start({u"--id"_s, u"0x1f"_s, u"--name"_s, u"lauv-sim-1"_s, u"--port"_s, u"16124"_s, u"--time-factor"_s, u"30"_s,
                   u"--fault"_s, u"navigation-loss@5"_s, u"--fault"_s, u"payload-failure@5"_s, u"--fault"_s,
                   u"motor-jammed@5"_s, u"--fault"_s, u"battery-drain@5"_s, u"--fault"_s, u"comms-loss@11:6"_s});
    const transport::ImcUdpConfig config = imcTo({16124});
    session::Console console(test::shippedSchema());
    ASSERT_TRUE(console.startImc(config));
    ASSERT_TRUE(QTest::qWaitFor([&] { return heard(console.tree(), u"lauv-sim-1"_s); }, 15000));
    alarms::AlarmGraph &graph = console.alarmGraph();
    const auto level = [&](const QString &path) {
        const auto node = graph.find(u"systems/lauv-sim-1"_s + path);
        return node == alarms::AlarmGraph::noNode ? alarms::Unknown : graph.ownLevel(node);
    };
    const auto message = [&](const QString &path) { return graph.message(graph.find(u"systems/lauv-sim-1"_s + path)); };
    const auto check = [&](const QString &path, alarms::Level expected, const QString &text) {
        EXPECT_TRUE(QTest::qWaitFor([&] { return level(path) == expected; }, 8000))
            << path.toStdString() << " is " << int(level(path)) << ": " << message(path).toStdString();
        EXPECT_EQ(message(path), text) << path.toStdString();
    };
    check(u"/Navigation"_s, alarms::Normal, u"active"_s); // before the faults, 5 s in
    check(u"/Navigation"_s, alarms::Error, u"navigation lost: no position fix"_s);
    check(u"/Sidescan"_s, alarms::Failure, u"sidescan not responding"_s);
    check(u"/Motor"_s, alarms::Error, u"motor jammed"_s);
    check(u"/Batteries"_s, alarms::Error, u"battery critical"_s); // drained at 30x: 3.6 V in under 3 s
    // Nothing heard for 6 s: communications lost, then back.
    EXPECT_TRUE(QTest::qWaitFor([&] { console.check(); return level({}) >= alarms::Warning; }, 10000));
    EXPECT_TRUE(message({}).startsWith(u"communications lost"_s)) << message({}).toStdString();
    EXPECT_TRUE(QTest::qWaitFor([&] { console.check(); return level({}) == alarms::Normal; }, 10000)) << message({}).toStdString();
}

// Several vehicles of several kinds from one scenario file, in one process,
// over IMC/UDP and DDS; each runs the plan it is given.
TEST(PlanExecution, AScenarioRunsSeveralVehiclesInOneProcess)
{
    QTemporaryDir dir;
    const QString file = dir.filePath(u"scenario.json"_s);
    QFile out(file);
    ASSERT_TRUE(out.open(QIODevice::WriteOnly));
    out.write(R"({"timeFactor": 30, "vehicles": [
        {"id": "0x31", "name": "auv-a", "kind": "auv", "port": 16130},
        {"id": "0x32", "name": "asv-b", "kind": "asv", "port": 16131, "dds": true, "phase": 120},
        {"id": "0x33", "name": "uav-c", "kind": "uav", "port": 16132, "phase": 240, "radius": 300, "speed": 18}]})");
    out.close();
    test::SimProcess sims;
    sims.start({u"--scenario"_s, file, u"--dds-domain"_s, u"12"_s});
    const transport::ImcUdpConfig config = imcTo({16130, 16132});
    session::Console console(test::shippedSchema());
    ASSERT_TRUE(console.startImc(config));
    ASSERT_TRUE(console.startDds({12, {}, 0x4001}));
    ASSERT_TRUE(QTest::qWaitFor([&] {
        return heard(console.tree(), u"auv-a"_s) && heard(console.tree(), u"asv-b"_s) && heard(console.tree(), u"uav-c"_s);
    }, 20000)) << console.tree().childNames(u""_s).join(u", "_s).toStdString() << "\n" << sims.output.constData();
    EXPECT_EQ(console.tree().snapshot(console.tree().find(u"asv-b"_s)).text, u"0x0032 via DDS"_s);
    EXPECT_EQ(console.tree().snapshot(console.tree().find(u"uav-c/EstimatedState/height"_s)).present, true);
    runPlan(console, 0x32, u"asv-b"_s, missionFor("asv-b", 0, "DEPTH"));
}

// Stop and Abort from a console's desk reach a separate vehicle process,
// end its plan, and are logged with the vehicle's reason.
TEST(PlanExecution, StopAndAbortEndAPlanOnAVehicleProcess)
{
    test::SimProcess vehicle;
    vehicle.start({u"--id"_s, u"0x1f"_s, u"--name"_s, u"lauv-sim-1"_s, u"--port"_s, u"16125"_s, u"--time-factor"_s, u"10"_s});
    const transport::ImcUdpConfig config = imcTo({16125});
    session::Console console(test::shippedSchema());
    ASSERT_TRUE(console.startImc(config));
    ASSERT_TRUE(QTest::qWaitFor([&] { return heard(console.tree(), u"lauv-sim-1"_s); }, 15000));
    plans::PlanDesk desk(test::shippedSchema(), console.tree(), console.alarmGraph(),
                         [&](quint16 id, const msg::Message &m) { return console.send(id, m); });
    QObject::connect(&console, &session::Console::planMessageReceived, &desk, &plans::PlanDesk::receive);
    auto mission = mission::readMission(missionFor("lauv-sim-1", 2, "DEPTH"), u"e2e.xml"_s);
    ASSERT_TRUE(mission);
    desk.setMission(*mission);
    const QString name = u"lauv-sim-1"_s;
    const auto log = [&] { return desk.log(name).join(u'\n'); };
    const auto state = [&] { return console.tree().snapshot(console.tree().find(name + u"/PlanControlState/state"_s)).text; };

    ASSERT_TRUE(desk.refresh(name));
    ASSERT_TRUE(QTest::qWaitFor([&] { return desk.fetched(name); }, 10000));
    ASSERT_TRUE(desk.send(name, u"survey"_s));
    ASSERT_TRUE(QTest::qWaitFor([&] { return desk.sync(name, u"survey"_s) == plans::Sync::Same; }, 10000)) << log().toStdString();

    ASSERT_TRUE(desk.start(name, u"survey"_s));
    ASSERT_TRUE(QTest::qWaitFor([&] { return state() == u"EXECUTING"; }, 10000)) << log().toStdString();
    ASSERT_TRUE(desk.stop(name));
    ASSERT_TRUE(QTest::qWaitFor([&] { return log().contains(u"survey stopped"_s); }, 10000)) << log().toStdString();
    EXPECT_TRUE(QTest::qWaitFor([&] { return state() == u"READY"; }, 5000));

    ASSERT_TRUE(desk.start(name, u"survey"_s));
    ASSERT_TRUE(QTest::qWaitFor([&] { return state() == u"EXECUTING"; }, 10000)) << log().toStdString();
    ASSERT_TRUE(desk.abort(name));
    ASSERT_TRUE(QTest::qWaitFor([&] { return log().contains(u"survey failed: got abort request from system"_s); }, 10000)) << log().toStdString();
    const auto node = console.alarmGraph().find(u"systems/lauv-sim-1/plan"_s);
    ASSERT_NE(node, alarms::AlarmGraph::noNode);
    EXPECT_EQ(console.alarmGraph().ownLevel(node), alarms::Warning);
    EXPECT_TRUE(vehicle.output.contains("received Abort")) << vehicle.output.constData();
}

// A Neptus CrossHatchPattern, imported, runs on a vehicle as Neptus sends it
// (a FollowPath through the pattern's points): the simulated AUV passes every
// corner of the cross hatch, in order, and the plan completes.
TEST(PlanExecution, AnImportedNeptusCrossHatchIsDrivenThroughEveryCorner)
{
    test::SimProcess vehicle;
    vehicle.start({u"--id"_s, u"0x1f"_s, u"--name"_s, u"lauv-sim-1"_s, u"--port"_s, u"16126"_s, u"--time-factor"_s, u"20"_s});
    session::Console console(test::shippedSchema());
    ASSERT_TRUE(console.startImc(imcTo({16126})));
    ASSERT_TRUE(QTest::qWaitFor([&] { return heard(console.tree(), u"lauv-sim-1"_s); }, 15000));
    // 41°10'14.52" N, 8°42'51.48" W: 25 m north-east of the simulator's reference point.
    const auto imported = mission::importNeptus(R"(<mission-def><header><id>e2e</id><name>e2e</name></header><definitions>
<vehicles><vehicle><id>lauv-sim-1</id><name>lauv-sim-1</name></vehicle></vehicles>
<home-reference><origin><latitude>41.1705</latitude><longitude>-8.7150</longitude><depth>0</depth></origin></home-reference>
</definitions><body><plan id="survey" vehicle="lauv-sim-1"><graph><node start="true"><id>cross</id><maneuver>
<CrossHatchPattern kind="automatic"><basePoint type="pointType"><point>
  <coordinate><latitude>41N10'14.52''</latitude><longitude>8W42'51.48''</longitude><height>0</height></coordinate>
  <z>2.0</z><zunits>DEPTH</zunits></point><radiusTolerance>0.0</radiusTolerance></basePoint>
  <width>40</width><hstep>20</hstep><bearing>30</bearing><curveOffset>5</curveOffset><speed unit="m/s">1.5</speed>
</CrossHatchPattern></maneuver></node></graph></plan></body></mission-def>)",
                                                  u"e2e.nmis"_s);
    ASSERT_TRUE(imported) << test::errorsText(imported.error()).toStdString();
    plans::PlanDesk desk(test::shippedSchema(), console.tree(), console.alarmGraph(),
                         [&](quint16 id, const msg::Message &m) { return console.send(id, m); });
    QObject::connect(&console, &session::Console::planMessageReceived, &desk, &plans::PlanDesk::receive);
    desk.setMission(imported->mission);
    const QString name = u"lauv-sim-1"_s;
    const auto log = [&] { return desk.log(name).join(u'\n'); };
    ASSERT_TRUE(desk.refresh(name));
    ASSERT_TRUE(QTest::qWaitFor([&] { return desk.fetched(name); }, 10000));
    ASSERT_TRUE(desk.send(name, u"survey"_s));
    ASSERT_TRUE(QTest::qWaitFor([&] { return desk.sync(name, u"survey"_s) == plans::Sync::Same; }, 10000)) << log().toStdString();
    ASSERT_TRUE(desk.start(name, u"survey"_s));

    // Where the vehicle is, as it says (EstimatedState: a reference and metres north/east of it).
    const auto number = [&](const char *field) {
        return console.tree().snapshot(console.tree().find(name + u"/EstimatedState/"_s + QLatin1StringView(field))).value.toDouble();
    };
    const mission::PlanGeometry planned = mission::planGeometry(imported->mission.plans[0]);
    ASSERT_EQ(planned.maneuvers.size(), 1);
    const QList<mission::Waypoint> corners = planned.maneuvers[0].points;
    ASSERT_EQ(corners.size(), 2 * (1 + 3 + 2));
    std::vector<double> closest(corners.size(), std::numeric_limits<double>::infinity());
    ASSERT_TRUE(QTest::qWaitFor([&] {
        const geo::Geodetic at = geo::fromNed(Eigen::Vector3d(number("x"), number("y"), 0), {number("lat"), number("lon"), 0});
        const mission::Waypoint here{geo::degrees(at.lat), geo::degrees(at.lon), 0, {}, 0, 0};
        for (qsizetype i = 0; i < corners.size(); ++i)
            closest[i] = std::min(closest[i], mission::distance(here, corners[i]));
        return log().contains(u"survey completed"_s);
    }, 60000)) << log().toStdString();
    // A point counts as reached within the simulator's arrival radius (sim::Limits::arrivalRadius:
    // 1.2 × 1.5 m/s ÷ 0.35 rad/s = 5.1 m here); a metre more for where a sample fell.
    for (qsizetype i = 0; i < corners.size(); ++i)
        EXPECT_LT(closest[i], 6.2) << "corner " << i << " of the cross hatch was missed by " << closest[i] << " m";
}
