// The console's plan desk against a simulated vehicle in-process: plans
// offered from the mission, sent, checked against the vehicle's MD5s before
// START, started, stopped, aborted; a log line for each, and the plan's end
// as an alarm event.
#include "plans/PlanDesk.h"
#include "plans/Supervisor.h"

#include "mission/ImcPlan.h"
#include "mission/MissionXml.h"
#include "sim/SimulatedVehicle.h"

#include "Missions.h"
#include "QtPrinters.h"
#include "Schemas.h"

#include <QRegularExpression>
#include <QTest>

#include <gtest/gtest.h>

using namespace neptus;
using namespace Qt::StringLiterals;

namespace {

constexpr quint16 console = 0x4001;

const char *const missionText = R"X(<?xml version="1.0" encoding="UTF-8"?>
<mission format="1" id="desk" name="Desk">
  <home lat="41.1705" lon="-8.7150" height="0"/>
  <vehicle id="lauv-sim-1"/>
  <vehicle id="x8-02"/>
  <map id="m">
    <mark id="buoy" name="Buoy" lat="41.1709" lon="-8.7155"/>
  </map>
  <plan id="survey" vehicle="lauv-sim-1" start="go">
    <maneuvers>
      <Goto id="go" lat="41.1709" lon="-8.7150" z="2" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"/>
      <Goto id="back" lat="41.1705" lon="-8.7150" z="0" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"/>
    </maneuvers>
    <transition from="go" to="back"/>
  </plan>
  <plan id="choice" vehicle="lauv-sim-1" start="a">
    <maneuvers>
      <Goto id="a" lat="41.1707" lon="-8.7150" z="0" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"/>
      <Goto id="b" lat="41.1709" lon="-8.7152" z="0" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"/>
      <Goto id="c" lat="41.1707" lon="-8.7154" z="0" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"/>
    </maneuvers>
    <transition from="a" to="b" condition="distance(&quot;caravela-sim&quot;, &quot;buoy&quot;) &lt; 50"/>
    <transition from="b" to="c"/>
  </plan>
  <plan id="other" vehicle="x8-02" start="up">
    <maneuvers><Takeoff id="up" lat="41.1700" lon="-8.7140" z="100" z_units="HEIGHT" speed="17"/></maneuvers>
  </plan>
  <plan id="own" vehicle="lauv-sim-1" start="a">
    <maneuvers>
      <Goto id="a" lat="41.1707" lon="-8.7150" z="0" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"/>
      <Goto id="b" lat="41.1705" lon="-8.7150" z="0" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"/>
    </maneuvers>
    <transition from="a" to="b" condition="sys[&quot;lauv-sim-1&quot;].EstimatedState.depth &lt; 1 &amp;&amp; $elapsed &gt; 5"/>
  </plan>
</mission>
)X";

struct Desk : ::testing::Test
{
    std::shared_ptr<const msg::Schema> schema = test::shippedSchema();
    ManualClock clock{QDateTime::fromMSecsSinceEpoch(1'700'000'000'000, QTimeZone::UTC)};
    tree::VariableTree tree{&clock};
    alarms::AlarmGraph graph{&clock};
    scripting::ScriptHost scripts{tree, graph};
    sim::SimulatedVehicle vehicle{schema, sim::SimulatedVehicle::Config{}};
    double t = 0;
    bool linkUp = true;
    int questions = 0; // GET_DSTATE requests sent
    plans::PlanDesk desk{schema, tree, graph,
                         [this](quint16 to, const msg::Message &m) -> std::expected<void, QString> {
                             if (to != 0x1f)
                                 return std::unexpected(u"no link"_s);
                             msg::Message request = m;
                             request.header.src = console;
                             if (m.abbrev() == u"PlanDB" && m.enumText(m.def()->indexOf(u"op")) == u"GET_DSTATE")
                                 ++questions;
                             request.header.dst = to;
                             if (linkUp)
                                 for (const msg::Message &reply : vehicle.answer(request, t))
                                     hear(reply);
                             return {};
                         },
                         [this] { return &scripts; }, &clock};

    Desk()
    {
        scripts.setFrameInterval(0);
        tree.setSystemName(0x1f, u"lauv-sim-1"_s);
        tree.setSystemName(0x20, u"caravela-sim"_s);
        auto m = mission::readMission(missionText, u"desk.xml"_s);
        if (m)
            desk.setMission(std::move(*m), u"desk.xml"_s);
        else
            ADD_FAILURE() << test::errorsText(m.error()).toStdString();
    }
    void hear(const msg::Message &m)
    {
        tree.ingest(m);
        if (m.abbrev() == u"PlanDB" || m.abbrev() == u"PlanControl" || m.abbrev() == u"PlanControlState")
            desk.receive(m);
    }
    // Simulated time on; conditions and supervision once a simulated second, as the console's timers do.
    void run(double seconds)
    {
        for (const double end = t + seconds; t < end;) {
            const double previous = t;
            t += 0.05;
            clock.advance(50);
            for (const msg::Message &m : vehicle.step(previous, t, 1.7e9 + t))
                hear(m);
            if (std::floor(t) > std::floor(previous)) {
                scripts.runPending();
                desk.supervise();
            }
        }
    }
    // The other vehicle, `north` metres north of the buoy.
    void other(double north)
    {
        msg::Message s(schema->byAbbrev(u"EstimatedState"));
        s.header.src = 0x20;
        s.setNumber(s.def()->indexOf(u"lat"), 41.1709 * M_PI / 180);
        s.setNumber(s.def()->indexOf(u"lon"), -8.7155 * M_PI / 180);
        s.setNumber(s.def()->indexOf(u"x"), north);
        tree.ingest(s);
    }
    QString lastLog() const
    {
        const QStringList log = desk.log(u"lauv-sim-1"_s);
        return log.isEmpty() ? QString() : log.last().mid(10); // after "HH:mm:ss  "
    }
    alarms::Level planAlarm() const
    {
        const auto node = graph.find(u"systems/lauv-sim-1/plan"_s);
        return node == alarms::AlarmGraph::noNode ? alarms::Unknown : graph.ownLevel(node);
    }
};

} // namespace

TEST_F(Desk, AMissionsPlansAreOfferedToTheirVehicles)
{
    QStringList ids;
    for (const mission::Plan *p : desk.missionPlans(u"lauv-sim-1"_s))
        ids << p->id;
    EXPECT_EQ(ids, (QStringList{u"survey"_s, u"choice"_s, u"own"_s})) << "its own, not x8-02's";
}

TEST_F(Desk, StartWaitsForTheVehiclesCopyToBeTheMissions)
{
    EXPECT_FALSE(desk.fetched(u"lauv-sim-1"_s));
    const auto early = desk.start(u"lauv-sim-1"_s, u"survey"_s);
    ASSERT_FALSE(early);
    EXPECT_TRUE(early.error().contains(u"has not said which plans it holds"_s)) << early.error().toStdString();
    EXPECT_TRUE(desk.fetched(u"lauv-sim-1"_s)) << "asking fetched them";
    const auto absent = desk.start(u"lauv-sim-1"_s, u"survey"_s);
    ASSERT_FALSE(absent);
    EXPECT_EQ(absent.error(), u"lauv-sim-1 does not hold survey: send it first"_s);

    ASSERT_TRUE(desk.send(u"lauv-sim-1"_s, u"survey"_s));
    EXPECT_EQ(desk.sync(u"lauv-sim-1"_s, u"survey"_s), plans::Sync::Same);
    ASSERT_EQ(desk.storedPlans(u"lauv-sim-1"_s).size(), 1u);
    EXPECT_EQ(desk.storedPlans(u"lauv-sim-1"_s)[0].id, u"survey"_s);

    // Edited here after sending: refused until sent again.
    mission::Mission edited = desk.mission();
    edited.plans[0].maneuvers[0].set(u"speed"_s, 1.2);
    desk.setMission(edited);
    EXPECT_EQ(desk.sync(u"lauv-sim-1"_s, u"survey"_s), plans::Sync::Differs);
    const auto differs = desk.start(u"lauv-sim-1"_s, u"survey"_s);
    ASSERT_FALSE(differs);
    EXPECT_TRUE(differs.error().contains(u"differs from the mission's"_s)) << differs.error().toStdString();
    ASSERT_TRUE(desk.send(u"lauv-sim-1"_s, u"survey"_s));
    EXPECT_EQ(desk.sync(u"lauv-sim-1"_s, u"survey"_s), plans::Sync::Same);

    ASSERT_TRUE(desk.start(u"lauv-sim-1"_s, u"survey"_s));
    EXPECT_EQ(desk.log(u"lauv-sim-1"_s).mid(desk.log(u"lauv-sim-1"_s).size() - 2).join(u'|').remove(QRegularExpression(u"\\d\\d:\\d\\d:\\d\\d  "_s)),
              u"START survey: plan loaded|survey started: go"_s)
        << "DUNE's three replies: the first answers the START, the state says it runs; no early end";
    EXPECT_TRUE(graph.activeAlarms().empty());
    EXPECT_TRUE(vehicle.plans().executing());
    run(400);
    EXPECT_FALSE(vehicle.plans().executing());
    EXPECT_EQ(lastLog(), u"survey completed"_s);
    EXPECT_EQ(planAlarm(), alarms::Info);
    EXPECT_EQ(graph.message(graph.find(u"systems/lauv-sim-1/plan"_s)), u"plan survey completed"_s);
    const auto listed = graph.activeAlarms();
    ASSERT_EQ(listed.size(), 1u) << "a completed plan is a line in the alarm window";
    EXPECT_EQ(listed[0].level, alarms::Info);
    EXPECT_EQ(listed[0].message, u"plan survey completed"_s);
    graph.acknowledge(listed[0].node);
    EXPECT_TRUE(graph.activeAlarms().empty()) << "until acknowledged";
}

TEST_F(Desk, StopIsAnInfoAbortAWarningWithTheVehiclesReason)
{
    desk.refresh(u"lauv-sim-1"_s);
    desk.send(u"lauv-sim-1"_s, u"survey"_s);
    ASSERT_TRUE(desk.start(u"lauv-sim-1"_s, u"survey"_s));
    run(5);
    ASSERT_TRUE(desk.stop(u"lauv-sim-1"_s));
    EXPECT_FALSE(vehicle.plans().executing());
    EXPECT_TRUE(desk.log(u"lauv-sim-1"_s).join(u'\n').contains(u"STOP survey: OK"_s)) << desk.log(u"lauv-sim-1"_s).join(u'\n').toStdString();
    EXPECT_EQ(lastLog(), u"survey stopped"_s);
    EXPECT_EQ(planAlarm(), alarms::Info);
    ASSERT_EQ(graph.activeAlarms().size(), 1u) << "a stopped plan is a line in the alarm window";
    EXPECT_EQ(graph.activeAlarms()[0].message, u"plan survey stopped"_s);
    graph.acknowledge(graph.activeAlarms()[0].node);

    ASSERT_TRUE(desk.start(u"lauv-sim-1"_s, u"survey"_s));
    run(5);
    ASSERT_TRUE(desk.abort(u"lauv-sim-1"_s));
    EXPECT_FALSE(vehicle.plans().executing());
    EXPECT_EQ(planAlarm(), alarms::Warning);
    // DUNE's words (Supervisors/Vehicle): this console never announced itself to the vehicle here.
    EXPECT_EQ(graph.message(graph.find(u"systems/lauv-sim-1/plan"_s)),
              u"plan survey failed: got abort request from system unknown - 0x4001 @ 0xFF"_s);
    EXPECT_EQ(graph.activeAlarms().size(), 1u) << "a line in the alarm window";
    run(3); // BLOCKED, then READY: no second end
    const QStringList log = desk.log(u"lauv-sim-1"_s);
    EXPECT_EQ(log.filter(u"survey failed"_s).size(), 1) << log.join(u'\n').toStdString();
    EXPECT_EQ(log.filter(u"survey stopped"_s).size(), 1) << log.join(u'\n').toStdString();
}

// A console started (or restarted) while a vehicle runs a plan another
// console started: it shows the plan from the vehicle's first report, draws
// it (asking the vehicle for a plan the mission lacks), and reports its end.
TEST_F(Desk, AConsoleThatJoinsMidPlanShowsThePlanAndItsEnd)
{
    const auto spec = mission::planSpecification(desk.mission().plans[0], *schema);
    ASSERT_TRUE(spec);
    msg::Message start(schema->byAbbrev(u"PlanControl"));
    start.setInteger(start.def()->indexOf(u"type"), 0); // REQUEST
    start.setInteger(start.def()->indexOf(u"op"), 0);   // START
    start.setInteger(start.def()->indexOf(u"request_id"), 77);
    start.setBytes(start.def()->indexOf(u"plan_id"), "elsewhere");
    msg::Message other = *spec;
    other.setBytes(other.def()->indexOf(u"plan_id"), "elsewhere");
    start.setInlineMessage(start.def()->indexOf(u"arg"), other);
    start.header.src = 0x4002; // another console
    start.header.dst = 0x1f;
    vehicle.answer(start, t); // its replies go to the other console; this one hears the vehicle's state
    run(2);
    EXPECT_EQ(lastLog(), u"elsewhere is running, at go (it started before this console heard lauv-sim-1)"_s);
    EXPECT_FALSE(desk.plan(u"lauv-sim-1"_s, u"elsewhere"_s)) << "not in the mission: asked of the vehicle, not known yet";
    run(400);
    EXPECT_EQ(lastLog(), u"elsewhere completed"_s);
    EXPECT_EQ(graph.message(graph.find(u"systems/lauv-sim-1/plan"_s)), u"plan elsewhere completed"_s);
}

// What the plan editor marks as an error never reaches a vehicle: a
// parameter past the vehicle's range, a leg through a no-go area.
TEST_F(Desk, APlanWithErrorsIsNotSent)
{
    mission::Mission edited = desk.mission();
    mission::Feature rock;
    rock.kind = u"circle"_s;
    rock.id = u"rock"_s;
    rock.position.lat = 41.1707;
    rock.position.lon = -8.7150;
    rock.attributes = {{u"role"_s, u"no-go"_s}, {u"radius"_s, u"5"_s}};
    edited.maps.first().features.append(rock);
    desk.setMission(edited);
    EXPECT_EQ(desk.send(u"lauv-sim-1"_s, u"survey"_s).error(),
              u"plan 'survey' is not sent: 'back' (Goto): a leg crosses the no-go area 'rock'"_s);
    EXPECT_TRUE(desk.problems().contains(u"survey: 'back' (Goto): a leg crosses the no-go area 'rock'"_s)) << "said when it opens";
    edited.maps.first().features.removeLast();
    edited.plans.first().maneuvers.first().set(u"z"_s, 500);
    desk.setMission(edited);
    EXPECT_TRUE(desk.send(u"lauv-sim-1"_s, u"survey"_s).error().startsWith(u"plan 'survey' is not sent: 'go' (Goto): z = 500 m is outside"_s));
    edited.plans.first().maneuvers.first().set(u"z"_s, 2);
    desk.setMission(edited);
    EXPECT_TRUE(desk.send(u"lauv-sim-1"_s, u"survey"_s));
}

// A check the console adds (its charts, through ConsoleSession) keeps a plan
// from being sent as the plan check's own errors do, and asked again
// (recheck: the charts were read) it lets the plan go once it passes.
TEST_F(Desk, AnExtraChecksErrorsKeepAPlanFromBeingSent)
{
    bool unsafe = true;
    desk.setExtraCheck([&](const mission::Plan &plan, const mission::PlanGeometry &geometry, const mission::VehicleDefinition *) {
        QList<mission::PlanProblem> problems;
        if (unsafe && plan.id == u"survey" && !geometry.maneuvers.isEmpty())
            problems.append({mission::PlanProblem::Severity::Error, mission::PlanProblem::Kind::ChartLand, geometry.maneuvers[0].id,
                             u"'%1' (Goto): a leg crosses land (chart XX5TEST.000)"_s.arg(geometry.maneuvers[0].id), {}, {}, 0});
        return problems;
    });
    EXPECT_EQ(desk.send(u"lauv-sim-1"_s, u"survey"_s).error(),
              u"plan 'survey' is not sent: 'go' (Goto): a leg crosses land (chart XX5TEST.000)"_s);
    EXPECT_TRUE(desk.problems().contains(u"survey: 'go' (Goto): a leg crosses land (chart XX5TEST.000)"_s));
    unsafe = false;
    desk.recheck();
    EXPECT_TRUE(desk.send(u"lauv-sim-1"_s, u"survey"_s));
}

TEST_F(Desk, SilenceAndUnknownSystemsAreSaid)
{
    desk.setTimeout(std::chrono::milliseconds(20));
    EXPECT_EQ(desk.send(u"nobody"_s, u"survey"_s).error(), u"no system is called 'nobody'"_s);
    EXPECT_EQ(desk.send(u"lauv-sim-1"_s, u"nothing"_s).error(), u"the mission has no plan 'nothing' for lauv-sim-1"_s);
    linkUp = false;
    ASSERT_TRUE(desk.refresh(u"lauv-sim-1"_s));
    desk.refresh(u"lauv-sim-1"_s); // a view looks again: no second question while one is on its way
    EXPECT_EQ(questions, 1);
    ASSERT_TRUE(QTest::qWaitFor([&] { return lastLog().contains(u"failed"_s); }, 3000));
    EXPECT_TRUE(lastLog().contains(u"no answer from 0x001f after 3 tries"_s)) << lastLog().toStdString();
}

TEST(Supervisor, APlanIsCutWhereConditionsAre)
{
    auto m = mission::readMission(missionText, u"desk.xml"_s);
    ASSERT_TRUE(m);
    const mission::Plan *survey = &m->plans[0], *choice = &m->plans[1];
    EXPECT_FALSE(plans::Supervisor::needed(*survey));
    EXPECT_EQ(plans::Supervisor::stretch(*survey, u"go"_s), (QStringList{u"go"_s, u"back"_s}));
    EXPECT_TRUE(plans::Supervisor::needed(*choice));
    EXPECT_EQ(plans::Supervisor::stretch(*choice, u"a"_s), QStringList{u"a"_s}) << "a condition ends a stretch";
    EXPECT_EQ(plans::Supervisor::stretch(*choice, u"b"_s), (QStringList{u"b"_s, u"c"_s}));
}

// A DUNE-like vehicle (first transition only) given a conditional plan: the
// console sends it a stretch at a time, keeps it waiting until the other
// vehicle is within 50 m of the buoy, then sends the rest.
TEST_F(Desk, AConditionalPlanIsCarriedOutByTheConsoleForAFirstTransitionVehicle)
{
    vehicle.plans().setTransitions(sim::PlanEngine::Transitions::FirstOnly);
    other(200);
    ASSERT_TRUE(desk.start(u"lauv-sim-1"_s, u"choice"_s)) << "no need to send it first: stretches go whole";
    EXPECT_TRUE(desk.supervising(u"lauv-sim-1"_s));
    const auto drawn = desk.plan(u"lauv-sim-1"_s, u"choice.1"_s);
    ASSERT_TRUE(drawn) << "the map draws the whole plan a stretch belongs to";
    EXPECT_EQ(drawn->id, u"choice"_s);
    run(120);
    EXPECT_EQ(vehicle.plans().currentManeuver(), u"wait"_s) << "a done, the vehicle waits for the condition";
    const QString log = desk.log(u"lauv-sim-1"_s).join(u'\n');
    EXPECT_TRUE(log.contains(u"starting choice.1: a → wait"_s)) << log.toStdString();
    EXPECT_TRUE(log.contains(u"a done: waiting for distance(\"caravela-sim\", \"buoy\") < 50 (→ b)"_s)) << log.toStdString();
    EXPECT_FALSE(log.contains(u"decided"_s));

    other(30);
    run(3);
    const QString decided = desk.log(u"lauv-sim-1"_s).join(u'\n');
    EXPECT_TRUE(decided.contains(u"decided a → b: distance(\"caravela-sim\", \"buoy\") < 50 (distance(\"caravela-sim\", \"buoy\") = 30.0 m, position heard"_s))
        << decided.toStdString();
    EXPECT_TRUE(decided.contains(u"starting choice.2: b → c"_s)) << decided.toStdString();
    run(200);
    EXPECT_FALSE(vehicle.plans().executing());
    EXPECT_TRUE(desk.log(u"lauv-sim-1"_s).join(u'\n').contains(u"choice completed (supervised)"_s))
        << desk.log(u"lauv-sim-1"_s).join(u'\n').toStdString();
    EXPECT_FALSE(desk.supervising(u"lauv-sim-1"_s));
    if (qEnvironmentVariableIsSet("NEPTUS_SHOW_LOG"))
        std::printf("%s\n", qPrintable(desk.log(u"lauv-sim-1"_s).join(u'\n')));
}

// A vehicle that says it evaluates conditions (the simulator by default)
// gets a conditional plan whole when its conditions read only its own state;
// one naming what only the console sees is still supervised.
TEST_F(Desk, AVehicleThatEvaluatesConditionsGetsTheWholePlanIfItCanSeeWhatTheyRead)
{
    EXPECT_FALSE(desk.evaluatesConditions(u"lauv-sim-1"_s)) << "not heard yet";
    for (const msg::Message &m : vehicle.introduction(1.7e9))
        hear(m);
    ASSERT_TRUE(desk.evaluatesConditions(u"lauv-sim-1"_s));

    other(200);
    ASSERT_TRUE(desk.start(u"lauv-sim-1"_s, u"choice"_s));
    EXPECT_TRUE(desk.supervising(u"lauv-sim-1"_s));
    EXPECT_TRUE(desk.log(u"lauv-sim-1"_s).join(u'\n').contains(
        u"supervising choice although lauv-sim-1 evaluates conditions: a → b measures a distance to a mark"_s))
        << desk.log(u"lauv-sim-1"_s).join(u'\n').toStdString();
    ASSERT_TRUE(desk.stop(u"lauv-sim-1"_s));

    desk.refresh(u"lauv-sim-1"_s);
    const auto absent = desk.start(u"lauv-sim-1"_s, u"own"_s);
    ASSERT_FALSE(absent) << "the whole plan goes by id: it must be on the vehicle";
    EXPECT_EQ(absent.error(), u"lauv-sim-1 does not hold own: send it first"_s);
    ASSERT_TRUE(desk.send(u"lauv-sim-1"_s, u"own"_s));
    ASSERT_TRUE(desk.start(u"lauv-sim-1"_s, u"own"_s));
    EXPECT_FALSE(desk.supervising(u"lauv-sim-1"_s));
    EXPECT_TRUE(desk.log(u"lauv-sim-1"_s).join(u'\n').contains(u"lauv-sim-1 evaluates own's conditions itself"_s));
    run(2);
    EXPECT_EQ(tree.snapshot(tree.find(u"lauv-sim-1/PlanControlState/plan_id"_s)).text, u"own"_s) << "not a stretch";
    run(300);
    EXPECT_FALSE(vehicle.plans().executing());
    EXPECT_EQ(lastLog(), u"own completed"_s);
}

TEST_F(Desk, AFirstTransitionVehicleIsSupervisedWhateverItsConditionsRead)
{
    vehicle.plans().setTransitions(sim::PlanEngine::Transitions::FirstOnly);
    for (const msg::Message &m : vehicle.introduction(1.7e9))
        hear(m);
    EXPECT_FALSE(desk.evaluatesConditions(u"lauv-sim-1"_s)) << "its Announce does not list the service";
    ASSERT_TRUE(desk.start(u"lauv-sim-1"_s, u"own"_s));
    EXPECT_TRUE(desk.supervising(u"lauv-sim-1"_s));
    run(2);
    EXPECT_EQ(tree.snapshot(tree.find(u"lauv-sim-1/PlanControlState/plan_id"_s)).text, u"own.1"_s);
}

TEST(Supervisor, WhatAConditionReadsBeyondTheVehicle)
{
    mission::Transition t;
    t.from = u"a"_s;
    t.to = u"b"_s;
    t.condition = u"sys[\"lauv\"].EstimatedState.depth < 1 && $elapsed > 5"_s;
    mission::Plan plan;
    plan.transitions = {t};
    EXPECT_EQ(plans::Supervisor::beyondVehicle(plan, u"lauv"_s), QString());
    plan.transitions[0].condition = u"lauv.EstimatedState.depth < Math.abs(-1)"_s;
    EXPECT_EQ(plans::Supervisor::beyondVehicle(plan, u"lauv"_s), QString());
    plan.transitions[0].condition = u"lauv.EstimatedState.depth < 1 || caravela.EstimatedState.depth > 3"_s;
    EXPECT_EQ(plans::Supervisor::beyondVehicle(plan, u"lauv"_s), u"a → b reads caravela"_s);
    plan.transitions[0].condition = u"sys[\"x8-02\"].EstimatedState.height > 100"_s;
    EXPECT_EQ(plans::Supervisor::beyondVehicle(plan, u"lauv"_s), u"a → b reads x8-02"_s);
    plan.transitions[0].condition = u"distance(\"lauv\", \"buoy\") < 5"_s;
    EXPECT_EQ(plans::Supervisor::beyondVehicle(plan, u"lauv"_s), u"a → b measures a distance to a mark"_s);
}

TEST_F(Desk, AConditionThatFailsIsSaidAndTheVehicleWaits)
{
    mission::Mission broken = desk.mission();
    broken.plans[1].transitions[0].condition = u"sys[\"caravela-sim\"].EstimatedState.depth <"_s;
    desk.setMission(broken);
    vehicle.plans().setTransitions(sim::PlanEngine::Transitions::FirstOnly);
    ASSERT_TRUE(desk.start(u"lauv-sim-1"_s, u"choice"_s));
    run(120);
    EXPECT_EQ(vehicle.plans().currentManeuver(), u"wait"_s);
    const QString log = desk.log(u"lauv-sim-1"_s).join(u'\n');
    EXPECT_TRUE(log.contains(u"fails"_s)) << log.toStdString();
    EXPECT_TRUE(desk.supervising(u"lauv-sim-1"_s));
    ASSERT_TRUE(desk.stop(u"lauv-sim-1"_s));
    EXPECT_FALSE(desk.supervising(u"lauv-sim-1"_s));
}

TEST_F(Desk, ConditionsThatDoNotCompileAreSaidWhenTheMissionOpens)
{
    EXPECT_TRUE(desk.problems().isEmpty()) << desk.problems().join(u'\n').toStdString();
    mission::Mission broken = desk.mission();
    broken.plans[1].transitions[0].condition = u"distance(\"caravela-sim\", \"buoy\") <"_s;
    desk.setMission(broken);
    ASSERT_EQ(desk.problems().size(), 1);
    EXPECT_EQ(neptus::plans::Supervisor::conditionProblem(u"sys[\"lauv-sim-1\"].EstimatedState.depth < 2 && $waited > 10"_s), std::nullopt);
    // Where it goes wrong, in the expression's own columns.
    const auto unfinished = neptus::plans::Supervisor::conditionProblem(u"distance(\"caravela-sim\", \"buoy\") <"_s);
    ASSERT_TRUE(unfinished) << "as one types it";
    EXPECT_EQ(unfinished->line, 1);
    EXPECT_EQ(unfinished->column, 35) << "just after the end: " << unfinished->message.toStdString();
    const auto extra = neptus::plans::Supervisor::conditionProblem(u"$elapsed > 60 &&& 1"_s);
    ASSERT_TRUE(extra);
    EXPECT_EQ(extra->column, 17) << "at the third &: " << extra->message.toStdString();
    const auto second = neptus::plans::Supervisor::conditionProblem(u"$elapsed > 60 &&\n  $waited >> > 2"_s);
    ASSERT_TRUE(second);
    EXPECT_EQ(second->line, 2);
    EXPECT_EQ(second->column, 14) << second->message.toStdString();
    EXPECT_TRUE(neptus::plans::Supervisor::conditionProblem(u"  "_s));
    EXPECT_TRUE(desk.problems()[0].startsWith(u"choice: a → b: condition 'distance(\"caravela-sim\", \"buoy\") <' does not compile: "_s))
        << desk.problems()[0].toStdString();
}
