// The simulator's plan engine, driven as a console drives a DUNE vehicle:
// PlanDB (with DUNE's MD5s), PlanControl, and plans executed maneuver by
// maneuver within the vehicle's limits, on simulated time.
#include "mission/ImcPlan.h"
#include "mission/MissionXml.h"
#include "plans/PlanDatabase.h"
#include "plans/PlanClient.h"
#include "sim/Scenario.h"
#include "sim/SimulatedVehicle.h"

#include "Fixtures.h"
#include "QtPrinters.h"
#include "Missions.h"
#include "Schemas.h"

#include <QCoreApplication>
#include <QFile>

#include <gtest/gtest.h>


using namespace neptus;
using namespace Qt::StringLiterals;

namespace {

constexpr quint16 console = 0x4001;

const char *const missionText = R"X(<?xml version="1.0" encoding="UTF-8"?>
<mission format="1" id="sim" name="Sim">
  <home lat="41.1705" lon="-8.7150" height="0"/>
  <vehicle id="lauv-sim-1"/>
  <plan id="survey" vehicle="lauv-sim-1" start="go">
    <maneuvers>
      <Goto id="go" lat="41.1715" lon="-8.7150" z="3" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"/>
      <Loiter id="circle" lat="41.1715" lon="-8.7150" z="2" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"
              duration="60" radius="20" type="CIRCULAR" direction="CLOCKW"/>
      <Rows id="rows" lat="41.1720" lon="-8.7140" z="4" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"
            width="60" length="80" hstep="30" bearing="0"/>
    </maneuvers>
    <transition from="go" to="circle"/>
    <transition from="circle" to="rows"/>
  </plan>
  <plan id="choice" vehicle="lauv-sim-1" start="a">
    <maneuvers>
      <Goto id="a" lat="41.1707" lon="-8.7150" z="0" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"/>
      <Goto id="b" lat="41.1709" lon="-8.7150" z="0" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"/>
      <Goto id="c" lat="41.1707" lon="-8.7153" z="0" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"/>
    </maneuvers>
    <transition from="a" to="b" condition="sea.EstimatedState.depth &lt; 2"/>
    <transition from="a" to="c"/>
  </plan>
</mission>
)X";

struct Sim : ::testing::Test
{
    std::shared_ptr<const msg::Schema> schema = test::shippedSchema();
    sim::SimulatedVehicle vehicle{schema, [] {
                                      sim::SimulatedVehicle::Config c;
                                      c.id = 0x1f;
                                      return c;
                                  }()};
    double t = 0;
    quint16 nextRequest = 1;
    std::vector<msg::Message> heard; // everything the vehicle said

    mission::Plan plan(const QString &id)
    {
        auto m = mission::readMission(missionText, u"sim.xml"_s);
        EXPECT_TRUE(m) << test::errorsText(m.error()).toStdString();
        for (const mission::Plan &p : m->plans)
            if (p.id == id)
                return p;
        ADD_FAILURE() << "no plan " << id.toStdString();
        return {};
    }
    msg::Message specification(const QString &id)
    {
        auto spec = mission::planSpecification(plan(id), *schema);
        EXPECT_TRUE(spec) << spec.error().toStdString();
        return *spec;
    }
    msg::Message request(const char *abbrev, const char *op, const QString &planId = {},
                         std::optional<msg::Message> arg = std::nullopt)
    {
        msg::Message m(schema->byAbbrev(QString::fromLatin1(abbrev)));
        const auto set = [&](const char *field, const char *name) {
            const int i = m.def()->indexOf(QString::fromLatin1(field));
            m.setInteger(i, *m.field(i).enumeration->parse(QString::fromLatin1(name)));
        };
        set("type", "REQUEST");
        set("op", op);
        m.setInteger(m.def()->indexOf(u"request_id"), nextRequest++);
        m.setBytes(m.def()->indexOf(u"plan_id"), planId.toUtf8());
        m.setInlineMessage(m.def()->indexOf(u"arg"), std::move(arg));
        m.header.src = console;
        m.header.dst = 0x1f;
        return m;
    }
    std::vector<msg::Message> send(const msg::Message &m)
    {
        auto replies = vehicle.answer(m, 1.7e9 + t);
        heard.insert(heard.end(), replies.begin(), replies.end());
        return replies;
    }
    // Runs simulated time on, in the 20 ms steps neptus-sim takes.
    void run(double seconds)
    {
        for (const double end = t + seconds; t < end;) {
            const double previous = t;
            t += 0.02;
            auto said = vehicle.step(previous, t, 1.7e9 + t);
            heard.insert(heard.end(), said.begin(), said.end());
        }
    }
    // Runs until `done`, at most `limit` simulated seconds; the time it took.
    double runUntil(const std::function<bool()> &done, double limit)
    {
        const double start = t;
        while (!done() && t - start < limit)
            run(1);
        return t - start;
    }
    static QString enumOf(const msg::Message &m, const char *field)
    {
        return m.enumText(m.def()->indexOf(QString::fromLatin1(field)));
    }
    // The PlanControl replies among `messages`, as "TYPE op #id info".
    static QStringList replies(const std::vector<msg::Message> &messages)
    {
        QStringList out;
        for (const msg::Message &m : messages)
            if (m.abbrev() == u"PlanControl")
                out << u"%1 %2 #%3 %4"_s.arg(enumOf(m, "type"), enumOf(m, "op")).arg(m.integer(u"request_id")).arg(m.text(u"info"));
        return out;
    }
    static QStringList states(const std::vector<msg::Message> &messages)
    {
        QStringList out;
        for (const msg::Message &m : messages)
            if (m.abbrev() == u"PlanControlState")
                out << enumOf(m, "state") + u' ' + m.text(u"plan_id");
        return out;
    }
    std::optional<msg::Message> last(const char *abbrev) const
    {
        for (auto it = heard.rbegin(); it != heard.rend(); ++it)
            if (it->abbrev() == QLatin1StringView(abbrev))
                return *it;
        return std::nullopt;
    }
    Eigen::Vector2d north(double lat, double lon) const
    {
        return {(lat - 41.1705) * 111'100, (lon + 8.7150) * 111'100 * std::cos(41.1705 * M_PI / 180)};
    }
};

} // namespace

// DUNE's plan engine (src/Plan/Engine/Task.cpp, startPlan): a START is
// answered twice at once ("plan loaded", then "<maneuver>: executing
// maneuver"), INITIALIZING first (still naming the previous plan), then
// EXECUTING; the third reply, at the end, is "plan completed" under the same
// id, then READY with last_outcome SUCCESS and the plan's id kept.
TEST_F(Sim, AStartIsAnsweredAsDuneDoesThreeRepliesAndTheStates)
{
    const auto said = send(request("PlanControl", "START", u"survey"_s, specification(u"survey"_s)));
    EXPECT_EQ(replies(said), (QStringList{u"SUCCESS START #1 plan loaded"_s, u"SUCCESS START #1 go: executing maneuver"_s}));
    EXPECT_EQ(states(said), (QStringList{u"INITIALIZING "_s, u"EXECUTING survey"_s}));
    for (const msg::Message &m : said)
        EXPECT_EQ(m.header.dst, m.abbrev() == u"PlanControl" ? console : quint16(0xFFFF));
    const auto done = runUntil([&] { return !vehicle.plans().executing(); }, 1200);
    EXPECT_LT(done, 1200);
    const auto end = last("PlanControl");
    EXPECT_EQ(replies({*end}), QStringList{u"SUCCESS START #1 plan completed"_s});
    run(1);
    EXPECT_EQ(states({*last("PlanControlState")}), QStringList{u"READY survey"_s});
    EXPECT_EQ(enumOf(*last("PlanControlState"), "last_outcome"), u"SUCCESS"_s);
    EXPECT_EQ(last("PlanControlState")->number(u"plan_progress"), -1);
    EXPECT_EQ(last("PlanControlState")->integer(u"man_type"), 0xFFFF);

    // At DUNE's rate: 3 Hz (etc/common/plans.ini, State Report Frequency).
    heard.clear();
    run(10);
    EXPECT_EQ(states(heard).size(), 30);
}

// DUNE's one reply record: its later words reuse the last request's id and
// op, so a GET during the plan makes "plan completed" a reply to that GET.
TEST_F(Sim, LaterWordsReuseTheLastRequestAsDunesDo)
{
    send(request("PlanControl", "START", u"survey"_s, specification(u"survey"_s)));
    run(5);
    const auto got = send(request("PlanControl", "GET"));
    EXPECT_EQ(replies(got), QStringList{u"SUCCESS GET #2 OK"_s});
    runUntil([&] { return !vehicle.plans().executing(); }, 1200);
    EXPECT_EQ(replies({*last("PlanControl")}), QStringList{u"SUCCESS GET #2 plan completed"_s});
    EXPECT_EQ(replies(send(request("PlanControl", "GET"))), QStringList{u"FAILURE GET #3 no plan is running"_s});
}

TEST_F(Sim, RunsGotoLoiterAndRowsToTheEndAndSaysSo)
{
    send(request("PlanControl", "START", u"survey"_s, specification(u"survey"_s)));

    std::vector<QString> maneuvers;
    double lastProgress = 0;
    bool progressFell = false;
    const double took = runUntil([&] {
        const auto state = last("PlanControlState");
        if (state && enumOf(*state, "state") == u"EXECUTING") {
            const QString man = state->text(u"man_id");
            if (maneuvers.empty() || maneuvers.back() != man)
                maneuvers.push_back(man);
            progressFell = progressFell || state->number(u"plan_progress") < lastProgress - 1e-6;
            lastProgress = state->number(u"plan_progress");
        }
        return !vehicle.plans().executing();
    }, 1200);
    EXPECT_FALSE(vehicle.plans().executing()) << "still running after " << took << " s";
    EXPECT_EQ(maneuvers, (std::vector<QString>{u"go"_s, u"circle"_s, u"rows"_s}));
    EXPECT_FALSE(progressFell);
    EXPECT_GT(lastProgress, 60);
    // Goto ~111 m + a 60 s loiter + rows (3 × 80 m + 2 × 30 m + the way there) at 1.5 m/s.
    EXPECT_GT(took, 60 + 300 / 1.5);
    EXPECT_LT(took, 60 + 700 / 1.5);

    const auto end = last("PlanControl");
    ASSERT_TRUE(end);
    EXPECT_EQ(enumOf(*end, "type"), u"SUCCESS");
    EXPECT_EQ(end->text(u"info"), u"plan completed"_s);
    EXPECT_EQ(end->integer(u"request_id"), 1) << "the START it answers";
    EXPECT_EQ(end->header.dst, console);
    run(1);
    const auto state = last("PlanControlState");
    EXPECT_EQ(enumOf(*state, "state"), u"READY");
    EXPECT_EQ(enumOf(*state, "last_outcome"), u"SUCCESS");
    EXPECT_EQ(state->text(u"plan_id"), u"survey"_s);

    // It ended where the rows end: 60 m east and 80 m north of the corner, or near it.
    const Eigen::Vector2d corner = north(41.1720, -8.7140);
    EXPECT_LT((vehicle.motion().ned.head<2>() - corner).norm(), 140);
    EXPECT_LT(vehicle.motion().ned.z(), 4.5);
}

TEST_F(Sim, ItsDepthFollowsThePlan)
{
    send(request("PlanControl", "START", u"survey"_s, specification(u"survey"_s)));
    double deepest = 0;
    runUntil([&] {
        deepest = std::max(deepest, vehicle.motion().ned.z());
        return vehicle.plans().currentManeuver() == u"circle";
    }, 600);
    EXPECT_NEAR(deepest, 3, 0.5) << "the Goto's 3 m";
    run(40);
    EXPECT_NEAR(vehicle.motion().ned.z(), 2, 0.3) << "the loiter's 2 m";
    EXPECT_LE(vehicle.motion().speed, 1.5 + 1e-9);
}

TEST_F(Sim, TheDatabaseKeepsPlansAndAnswersWithDunesMd5s)
{
    plans::PlanClient client(schema, 0x1f, [&](const msg::Message &m) {
        msg::Message request = m;
        request.header.src = console;
        for (const msg::Message &reply : send(request))
            client.receive(reply);
    });
    std::vector<plans::PlanClient::Reply> replies;
    QObject::connect(&client, &plans::PlanClient::replied, [&](const auto &r) { replies.push_back(r); });
    const msg::Message survey = specification(u"survey"_s), choice = specification(u"choice"_s);
    client.set(survey);
    client.set(choice);
    client.getState();
    client.get(u"survey"_s);
    client.remove(u"nothing"_s);
    ASSERT_EQ(replies.size(), 5u);
    EXPECT_TRUE(replies[0].ok && replies[1].ok);
    ASSERT_TRUE(replies[2].ok && replies[2].arg);
    const msg::Codec codec(schema);
    const QByteArray md5 = plans::databaseMd5({{u"survey"_s, *plans::planMd5(codec, survey)},
                                                {u"choice"_s, *plans::planMd5(codec, choice)}});
    EXPECT_EQ(replies[2].arg->bytes(replies[2].arg->def()->indexOf(u"md5")), md5);
    EXPECT_EQ(replies[2].arg->integer(u"plan_count"), 2);
    ASSERT_TRUE(replies[3].ok && replies[3].arg);
    EXPECT_EQ(*plans::planMd5(codec, *replies[3].arg), *plans::planMd5(codec, survey)) << "the very plan back";
    EXPECT_FALSE(replies[4].ok);
    EXPECT_EQ(replies[4].info, u"undefined plan 'nothing'"_s);

    // A stored plan starts by its id alone.
    const auto started = send(request("PlanControl", "START", u"choice"_s));
    EXPECT_EQ(Sim::replies(started).value(0), u"SUCCESS START #%1 plan loaded"_s.arg(nextRequest - 1));
    EXPECT_TRUE(vehicle.plans().executing());
    const auto unknown = send(request("PlanControl", "START", u"nothing"_s));
    EXPECT_EQ(Sim::replies(unknown), QStringList{u"FAILURE START #%1 undefined plan"_s.arg(nextRequest - 1)}) << "DUNE's words";
}

TEST_F(Sim, DatabaseMd5sMatchDunesForTheFixturePlans)
{
    const auto imc = test::imcSchema();
    if (!imc)
        GTEST_SKIP() << "../shared/fixtures/imc is absent (a user's clone); CI and developer machines have it";
    QFile file(test::fixturePath("imc/plans-md5.txt"));
    ASSERT_TRUE(file.open(QIODevice::ReadOnly | QIODevice::Text));
    sim::PlanEngine engine(imc, 0x1f, u"lauv"_s, sim::Limits::auv(), 41, -8);
    const msg::Codec codec(imc);
    QByteArray expected;
    int stored = 0;
    quint16 id = 1;
    while (!file.atEnd()) {
        const QByteArray line = file.readLine().trimmed();
        if (line.startsWith("# plan database md5"))
            expected = line.split(' ').last();
        const QList<QByteArray> parts = line.split(' ');
        if (line.startsWith('#') || parts.size() != 4)
            continue;
        const auto spec = codec.decode(QByteArray::fromHex(parts[3]));
        ASSERT_TRUE(spec);
        msg::Message set(imc->byAbbrev(u"PlanDB"));
        set.setInteger(set.def()->indexOf(u"op"), 0); // SET
        set.setInteger(set.def()->indexOf(u"request_id"), id++);
        set.setBytes(set.def()->indexOf(u"plan_id"), spec->bytes(spec->def()->indexOf(u"plan_id")));
        set.setInlineMessage(set.def()->indexOf(u"arg"), *spec);
        set.header.dst = 0x1f;
        const auto reply = engine.handle(set, 0);
        ASSERT_EQ(reply.size(), 1u);
        EXPECT_EQ(reply[0].enumText(reply[0].def()->indexOf(u"type")), u"SUCCESS") << reply[0].text(u"info").toStdString();
        ++stored;
    }
    EXPECT_EQ(stored, 3);
    EXPECT_EQ(engine.databaseMd5().toHex(), expected);
}

// DUNE's STOP (Plan/Engine stopPlan): the STOP is answered "OK", the START
// nothing more; READY with last_outcome FAILURE. Abort (Supervisors/Vehicle):
// a FAILURE in the supervisor's words to the last requester, BLOCKED, and
// READY again a second later.
TEST_F(Sim, StopAndAbortEndThePlanAndSayWhyInDunesWords)
{
    msg::Message announce(schema->byAbbrev(u"Announce"));
    announce.header.src = console;
    announce.setBytes(announce.def()->indexOf(u"sys_name"), "neptus-qt");
    send(announce);
    send(request("PlanControl", "START", u"survey"_s, specification(u"survey"_s)));
    run(5);
    const auto stopped = send(request("PlanControl", "STOP", u"survey"_s));
    EXPECT_EQ(replies(stopped), QStringList{u"SUCCESS STOP #2 OK"_s});
    EXPECT_EQ(states(stopped), QStringList{u"READY survey"_s});
    EXPECT_FALSE(vehicle.plans().executing());
    EXPECT_EQ(enumOf(*last("PlanControlState"), "last_outcome"), u"FAILURE");
    EXPECT_EQ(replies(send(request("PlanControl", "STOP"))), QStringList{u"FAILURE STOP #3 no plan is running, request ignored"_s});

    send(request("PlanControl", "START", u"survey"_s, specification(u"survey"_s)));
    run(5);
    msg::Message abort(schema->byAbbrev(u"Abort"));
    abort.header.src = console;
    abort.header.srcEnt = 0xFF;
    abort.header.dst = 0x1f;
    const auto aborted = send(abort);
    EXPECT_EQ(replies(aborted), QStringList{u"FAILURE START #4 got abort request from system neptus-qt - 0x4001 @ 0xFF"_s});
    EXPECT_EQ(states(aborted), QStringList{u"BLOCKED survey"_s});
    EXPECT_FALSE(vehicle.plans().executing());
    heard.clear();
    run(1.5);
    EXPECT_EQ(states(heard).back(), u"READY survey"_s);
    EXPECT_TRUE(replies(heard).isEmpty()) << "one end";
    const double depth = vehicle.motion().ned.z();
    run(10);
    EXPECT_LT(vehicle.motion().ned.z(), depth) << "an AUV with no plan floats up";
}

TEST_F(Sim, TransitionsFollowTheirConditionsOrTheFirstOneLikeDune)
{
    // Conditions honoured: "depth < 2" does not hold, so the next true one (c).
    vehicle.plans().setEvaluator([](const QString &condition) -> std::optional<bool> {
        return condition == u"sea.EstimatedState.depth < 2" ? std::optional<bool>(false) : std::nullopt;
    });
    send(request("PlanControl", "START", u"choice"_s, specification(u"choice"_s)));
    runUntil([&] { return vehicle.plans().currentManeuver() != u"a"; }, 200);
    EXPECT_EQ(vehicle.plans().currentManeuver(), u"c"_s);

    // Like DUNE: the first transition, whatever it says.
    vehicle.plans().setTransitions(sim::PlanEngine::Transitions::FirstOnly);
    send(request("PlanControl", "START", u"choice"_s, specification(u"choice"_s)));
    runUntil([&] { return vehicle.plans().currentManeuver() != u"a"; }, 200);
    EXPECT_EQ(vehicle.plans().currentManeuver(), u"b"_s);

    // A condition nobody can evaluate fails the plan, saying which.
    vehicle.plans().setTransitions(sim::PlanEngine::Transitions::Conditions);
    vehicle.plans().setEvaluator({});
    send(request("PlanControl", "START", u"choice"_s, specification(u"choice"_s)));
    runUntil([&] { return !vehicle.plans().executing(); }, 200);
    const auto end = last("PlanControl");
    EXPECT_EQ(enumOf(*end, "type"), u"FAILURE");
    EXPECT_TRUE(end->text(u"info").contains(u"sea.EstimatedState.depth < 2"_s)) << end->text(u"info").toStdString();
}

TEST_F(Sim, OneManeuverStartsAsAPlanAndUnknownManeuversAreRefused)
{
    const mission::Plan survey = plan(u"survey"_s);
    const msg::Message spec = specification(u"survey"_s);
    const msg::Message goTo = *spec.messages(spec.def()->indexOf(u"maneuvers"))[0].inlineMessage(
        schema->byAbbrev(u"PlanManeuver")->indexOf(u"data"));
    EXPECT_EQ(replies(send(request("PlanControl", "START", u"quick"_s, goTo))),
              (QStringList{u"SUCCESS START #1 plan loaded"_s, u"SUCCESS START #1 Goto: executing maneuver"_s}));
    EXPECT_EQ(vehicle.plans().currentManeuver(), u"Goto"_s) << "named after its type, as DUNE does";

    msg::Message teleop(schema->byAbbrev(u"Teleoperation"));
    const auto refused = send(request("PlanControl", "START", u"quick"_s, teleop));
    EXPECT_EQ(replies(refused), QStringList{u"FAILURE START #2 parse error: Teleoperation: maneuver is not supported (a Teleoperation)"_s});
    EXPECT_EQ(states(refused).back(), u"READY quick"_s) << "the quick plan it was running stopped, as DUNE's";
    EXPECT_EQ(replies(send(request("PlanControl", "START", u"nothing"_s))), QStringList{u"FAILURE START #3 undefined plan"_s});
}

TEST(SimKinematics, AUavNeverStallsAndABoatStaysAtTheSurface)
{
    sim::Motion uav;
    uav.speed = 18;
    const double below = 100;
    for (int i = 0; i < 600; ++i)
        sim::hold(uav, &below, 0.1, sim::Limits::uav());
    EXPECT_GE(uav.speed, sim::Limits::uav().minSpeed);
    sim::Motion boat;
    const double deep = 10;
    for (int i = 0; i < 100; ++i)
        sim::steer(boat, {100, 0}, 2, &deep, 0.1, sim::Limits::asv());
    EXPECT_EQ(boat.ned.z(), 0);
    EXPECT_GT(boat.ned.x(), 10);
}

// Each fault says what an operator's console must show.
TEST_F(Sim, FaultsSayWhatAnOperatorExpects)
{
    const auto entityState = [&](const char *label) -> std::optional<std::pair<QString, QString>> {
        const quint8 entity = QByteArray("?NavMotBatSid").indexOf(QByteArray(label).left(3)) / 3 + 1;
        for (auto it = heard.rbegin(); it != heard.rend(); ++it)
            if (it->abbrev() == u"EntityState" && it->header.srcEnt == entity)
                return std::pair(enumOf(*it, "state"), it->text(u"description"));
        return std::nullopt;
    };
    const auto estimatedStates = [&] {
        return std::count_if(heard.begin(), heard.end(), [](const msg::Message &m) { return m.abbrev() == u"EstimatedState"; });
    };
    for (const QString &text : {u"navigation-loss@2"_s, u"payload-failure@2"_s, u"motor-jammed@2"_s, u"battery-drain@2"_s,
                               u"comms-loss@75:10"_s}) {
        auto fault = sim::SimulatedVehicle::parseFault(text);
        ASSERT_TRUE(fault) << fault.error().toStdString();
        vehicle.scheduleFault(*fault);
    }
    run(1.5);
    EXPECT_EQ(entityState("Navigation")->first, u"NORMAL"_s);
    run(1.5);
    EXPECT_EQ(*entityState("Navigation"), std::pair(u"ERROR"_s, u"navigation lost: no position fix"_s));
    EXPECT_EQ(*entityState("Sidescan"), std::pair(u"FAILURE"_s, u"sidescan not responding"_s));
    EXPECT_EQ(*entityState("Motor"), std::pair(u"ERROR"_s, u"motor jammed"_s));
    const auto states = estimatedStates();
    run(2);
    EXPECT_EQ(estimatedStates(), states) << "no position without navigation";
    run(50); // 0.05 V/s from 24.6 V
    EXPECT_EQ(entityState("Batteries")->first, u"FAULT"_s);
    run(20);
    EXPECT_EQ(*entityState("Batteries"), std::pair(u"ERROR"_s, u"battery critical"_s));

    const std::size_t before = heard.size();
    run(5); // t = 80: inside the comms loss
    EXPECT_EQ(heard.size(), before) << "nothing said";
    EXPECT_TRUE(send(request("PlanControl", "GET")).empty()) << "nothing heard";
    run(10);
    EXPECT_GT(heard.size(), before) << "and back after 10 s";

    // At run time, from a console: SetEntityParameters to entity Simulation.
    msg::Message set(schema->byAbbrev(u"SetEntityParameters"));
    msg::Message parameter(schema->byAbbrev(u"EntityParameter"));
    parameter.setBytes(parameter.def()->indexOf(u"name"), "Fault");
    parameter.setBytes(parameter.def()->indexOf(u"value"), "none");
    set.setBytes(set.def()->indexOf(u"name"), "Simulation");
    set.setMessages(set.def()->indexOf(u"params"), {parameter});
    set.header.dst = 0x1f;
    send(set);
    run(2);
    EXPECT_EQ(entityState("Navigation")->first, u"NORMAL"_s);
    parameter.setBytes(parameter.def()->indexOf(u"value"), "comms-loss:5");
    set.setMessages(set.def()->indexOf(u"params"), {parameter});
    send(set);
    const std::size_t quiet = heard.size();
    run(4);
    EXPECT_EQ(heard.size(), quiet) << "comms lost for 5 s from now";
    run(3);
    EXPECT_GT(heard.size(), quiet);

    EXPECT_FALSE(sim::SimulatedVehicle::parseFault(u"gremlins"_s));
    EXPECT_FALSE(sim::SimulatedVehicle::parseFault(u"comms-loss@x"_s));
    EXPECT_FALSE(sim::SimulatedVehicle::parseFault(u"comms-loss@1:2:3"_s));
}

TEST(Scenario, SeveralVehiclesOfSeveralKindsFromOneFile)
{
    const auto scenario = sim::readScenario(R"({"timeFactor": 5, "vehicles": [
        {"id": "0x1f", "name": "lauv-sim-1", "kind": "auv", "port": 6002, "transitions": "first",
         "faults": ["battery-drain@300", "comms-loss@600:30"]},
        {"id": 32, "name": "caravela-sim", "kind": "asv", "port": 6003, "phase": 180, "dds": true},
        {"id": 33, "name": "x8-sim", "kind": "uav", "port": 6004, "radius": 400, "speed": 18, "likeDune": true}]})",
                                            u"s.json"_s);
    ASSERT_TRUE(scenario) << scenario.error().toStdString();
    EXPECT_EQ(scenario->timeFactor, 5);
    ASSERT_EQ(scenario->vehicles.size(), 3u);
    const sim::ScenarioVehicle &auv = scenario->vehicles[0], &asv = scenario->vehicles[1], &uav = scenario->vehicles[2];
    EXPECT_EQ(auv.config.id, 0x1f);
    EXPECT_TRUE(auv.firstTransitionOnly);
    ASSERT_EQ(auv.faults.size(), 2u);
    EXPECT_EQ(auv.faults[1].fault, sim::SimulatedVehicle::CommsLoss);
    EXPECT_EQ(auv.faults[1].duration, 30);
    EXPECT_EQ(auv.host, u"127.0.0.1"_s) << "loopback unless the scenario says";
    EXPECT_EQ(auv.port, 6002);
    EXPECT_TRUE(asv.dds);
    EXPECT_EQ(asv.config.kind, sim::SimulatedVehicle::Kind::Asv);
    EXPECT_NEAR(asv.config.phase, M_PI, 1e-12);
    EXPECT_EQ(uav.config.kind, sim::SimulatedVehicle::Kind::Uav);
    EXPECT_EQ(uav.config.radiusM, 400);
    EXPECT_TRUE(uav.likeDune && uav.firstTransitionOnly && !uav.config.periodicEntityList);
}

TEST(Scenario, MistakesAreNamedByFileLineOrVehicleAndKey)
{
    const auto error = [](const char *json) {
        const auto s = sim::readScenario(json, u"s.json"_s);
        return s ? QString() : s.error();
    };
    EXPECT_EQ(error("{\n\"vehicles\": [\n{\"id\": 1,,}]}"), u"s.json:3: unterminated object"_s);
    EXPECT_EQ(error("[]"), u"s.json: a scenario is a JSON object with \"vehicles\""_s);
    EXPECT_EQ(error(R"({"vehicles": []})"), u"s.json: \"vehicles\" must list one vehicle or more"_s);
    EXPECT_EQ(error(R"({"vehicles": [{"id": 1, "name": "a", "port": 1, "kind": "boat"}]})"),
              u"s.json: vehicles[0] (a): kind 'boat' is not auv, asv or uav"_s);
    EXPECT_EQ(error(R"({"vehicles": [{"id": 1, "name": "a", "port": 1}, {"id": "0x1", "name": "b", "port": 2}]})"),
              u"s.json: vehicles[1] (b): id 0x0001 is another vehicle's too"_s);
    EXPECT_EQ(error(R"({"vehicles": [{"id": 1, "name": "a", "port": 1}, {"id": 2, "name": "b", "port": 1}]})"),
              u"s.json: vehicles[1] (b): port 1 is another vehicle's too"_s);
    EXPECT_TRUE(error(R"({"vehicles": [{"id": 1, "name": "a", "port": 1, "colour": "red"}]})")
                    .startsWith(u"s.json: vehicles[0] (a): unknown key \"colour\""_s));
    EXPECT_TRUE(error(R"({"vehicles": [{"id": 1, "name": "a", "port": 1, "faults": ["gremlins"]}]})")
                    .startsWith(u"s.json: vehicles[0] (a): faults: 'gremlins' is not a fault"_s));
    EXPECT_EQ(error(R"({"vehicles": [{"id": 70000, "name": "a", "port": 1}]})"),
              u"s.json: vehicles[0] (a): id must be a number from 1 to 65534 (or \"0x1f\")"_s);
}

// Conditions it can see (its own state, $elapsed, $waited) it evaluates
// itself; one on another vehicle, or one that never ends, fails the plan
// saying why.
TEST_F(Sim, ItEvaluatesConditionsOnItsOwnStateNatively)
{
    mission::Plan p = plan(u"choice"_s);
    p.transitions.removeAt(1); // a → b only, when its condition holds
    p.transitions[0].condition = u"$waited > 20 && sys[\"lauv-sim-1\"].EstimatedState.depth < 1"_s;
    const auto specOf = [&](const mission::Plan &plan) { return *mission::planSpecification(plan, *schema); };
    send(request("PlanControl", "START", u"choice"_s, specOf(p)));
    runUntil([&] { return vehicle.plans().currentManeuver() != u"a"_s; }, 200);
    EXPECT_EQ(vehicle.plans().currentManeuver(), u"b"_s) << "a → b once it had waited 20 s at the surface";
    EXPECT_GT(t, 20 + 10) << "it waited 20 s after getting to a, 22 m away";

    p.transitions[0].condition = u"sys[\"caravela-sim\"].EstimatedState.depth < 2"_s;
    send(request("PlanControl", "START", u"choice"_s, specOf(p)));
    runUntil([&] { return !vehicle.plans().executing(); }, 200);
    auto end = last("PlanControl");
    EXPECT_EQ(enumOf(*end, "type"), u"FAILURE");
    EXPECT_TRUE(end->text(u"info").contains(u"this vehicle sees only itself"_s)) << end->text(u"info").toStdString();

    p.transitions[0].condition = u"(function () { while (true) {} })()"_s;
    send(request("PlanControl", "START", u"choice"_s, specOf(p)));
    runUntil([&] { return !vehicle.plans().executing(); }, 200);
    end = last("PlanControl");
    EXPECT_TRUE(end->text(u"info").contains(u"did not finish within 50 ms"_s)) << end->text(u"info").toStdString();
}
