// Checking a plan while it is drawn: its graph, its legs against the
// mission's no-go and operating areas, and what its vehicle can do.
#include "Paths.h"
#include "mission/PlanCheck.h"
#include "mission/Vehicle.h"

#include <gtest/gtest.h>

using namespace neptus::mission;
using namespace Qt::StringLiterals;

namespace {

constexpr double home[2] = {41.0, -8.0};
constexpr double metreLat = 1 / 111052.0, metreLon = 1 / 84146.0; // degrees per metre at 41° N

// A Goto `north`, `east` metres from home, at `depth`.
Maneuver gotoAt(const QString &id, double north, double east, double depth = 2)
{
    Maneuver m;
    m.id = id;
    m.type = u"Goto"_s;
    m.set(u"lat"_s, home[0] + north * metreLat);
    m.set(u"lon"_s, home[1] + east * metreLon);
    m.set(u"z"_s, depth);
    m.parameters.insert(u"z_units"_s, u"DEPTH"_s);
    m.set(u"speed"_s, 1.5);
    m.parameters.insert(u"speed_units"_s, u"METERS_PS"_s);
    return m;
}

// A linear plan through the maneuvers, in order.
Plan linear(QList<Maneuver> maneuvers)
{
    Plan p;
    p.id = u"p"_s;
    p.maneuvers = std::move(maneuvers);
    p.start = p.maneuvers.isEmpty() ? QString() : p.maneuvers.first().id;
    for (qsizetype i = 1; i < p.maneuvers.size(); ++i)
        p.transitions.append({p.maneuvers[i - 1].id, p.maneuvers[i].id, u"ManeuverIsDone"_s, {}, {}});
    return p;
}

Feature::Point offset(double north, double east)
{
    Feature::Point p;
    p.north = north;
    p.east = east;
    return p;
}

Feature circle(const QString &id, const QString &role, double north, double east, double radius)
{
    Feature f;
    f.kind = u"circle"_s;
    f.id = id;
    f.position = offset(north, east);
    f.attributes = {{u"role"_s, role}, {u"radius"_s, QString::number(radius)}};
    return f;
}

Feature polygon(const QString &id, const QString &role, std::initializer_list<std::pair<double, double>> points)
{
    Feature f;
    f.kind = u"polygon"_s;
    f.id = id;
    f.attributes = {{u"role"_s, role}};
    for (const auto &[n, e] : points)
        f.points.append(offset(n, e));
    return f;
}

Mission missionWith(QList<Feature> features)
{
    Mission m;
    m.id = u"m"_s;
    m.home = {home[0], home[1], 0};
    m.maps.append({u"map"_s, {}, std::move(features)});
    return m;
}

QList<PlanProblem> check(const Plan &plan, const Mission &mission, const VehicleDefinition *vehicle = nullptr)
{
    return checkPlan(plan, mission, planGeometry(plan), vehicle);
}

QList<PlanProblem::Kind> kinds(const QList<PlanProblem> &problems)
{
    QList<PlanProblem::Kind> k;
    for (const auto &p : problems)
        k << p.kind;
    return k;
}

} // namespace

TEST(PlanCheck, AGoodPlanHasNoProblems)
{
    const Mission m = missionWith({polygon(u"ops"_s, u"operating-area"_s, {{-500, -500}, {500, -500}, {500, 500}, {-500, 500}}),
                                   circle(u"rock"_s, u"no-go"_s, 300, 300, 40)});
    EXPECT_TRUE(check(linear({gotoAt(u"a"_s, 0, 0), gotoAt(u"b"_s, 200, 0), gotoAt(u"c"_s, 200, 100)}), m).isEmpty());
}

TEST(PlanCheck, TheGraphNeedsAStartAWayToEveryManeuverAndAWayOut)
{
    const Mission m = missionWith({});
    Plan p = linear({gotoAt(u"a"_s, 0, 0), gotoAt(u"b"_s, 100, 0)});
    p.start.clear();
    auto problems = check(p, m);
    ASSERT_EQ(problems.size(), 1) << "nothing is reachable without a start: said once";
    EXPECT_EQ(problems[0].kind, PlanProblem::Kind::NoStart);
    EXPECT_EQ(problems[0].message, u"plan 'p' has no start maneuver"_s);

    p.start = u"nowhere"_s;
    EXPECT_EQ(check(p, m)[0].message, u"plan 'p' starts at 'nowhere', which it does not have"_s);

    // c is not reached; a transition names a maneuver the plan lacks.
    p = linear({gotoAt(u"a"_s, 0, 0), gotoAt(u"b"_s, 100, 0), gotoAt(u"c"_s, 200, 0)});
    p.transitions.removeLast();
    p.transitions.append({u"b"_s, u"ghost"_s, u"ManeuverIsDone"_s, {}, {}});
    problems = check(p, m);
    ASSERT_EQ(problems.size(), 2);
    EXPECT_EQ(problems[0].severity, PlanProblem::Severity::Error) << "errors first";
    EXPECT_EQ(problems[0].kind, PlanProblem::Kind::UnknownManeuver);
    EXPECT_EQ(problems[0].maneuver, u"b"_s);
    EXPECT_EQ(problems[1].kind, PlanProblem::Kind::Unreachable);
    EXPECT_EQ(problems[1].severity, PlanProblem::Severity::Warning);
    EXPECT_EQ(problems[1].message, u"'c' (Goto) cannot be reached from the start 'a'"_s);
    EXPECT_TRUE(problems[1].lat && problems[1].lon) << "marked where c is";

    // a → b → c → b with no way out of b ⇄ c; a loop with an exit is fine.
    p = linear({gotoAt(u"a"_s, 0, 0), gotoAt(u"b"_s, 100, 0), gotoAt(u"c"_s, 200, 0), gotoAt(u"d"_s, 300, 0)});
    p.transitions.removeLast();
    p.transitions.append({u"c"_s, u"b"_s, u"ManeuverIsDone"_s, {}, {}});
    problems = check(p, m);
    ASSERT_EQ(kinds(problems), (QList{PlanProblem::Kind::EndlessLoop, PlanProblem::Kind::Unreachable})) << "in plan order";
    EXPECT_EQ(problems[0].message, u"b → c lead only to each other: the plan never ends by itself"_s);
    EXPECT_EQ(problems[1].maneuver, u"d"_s);
    p.transitions.append({u"c"_s, u"d"_s, u"$elapsed > 600"_s, {}, {}});
    EXPECT_TRUE(check(p, m).isEmpty());
    // A maneuver that leads only to itself.
    p = linear({gotoAt(u"a"_s, 0, 0)});
    p.transitions.append({u"a"_s, u"a"_s, u"ManeuverIsDone"_s, {}, {}});
    EXPECT_EQ(kinds(check(p, m)), QList{PlanProblem::Kind::EndlessLoop});
}

// Both waypoints are clear of the rock; the leg between them is not.
TEST(PlanCheck, ALegThroughANoGoAreaIsFlaggedWhereItEnters)
{
    const Mission m = missionWith({circle(u"rock"_s, u"no-go"_s, 200, 0, 30)});
    const auto problems = check(linear({gotoAt(u"a"_s, 0, 0), gotoAt(u"b"_s, 400, 0)}), m);
    ASSERT_EQ(problems.size(), 1);
    EXPECT_EQ(problems[0].kind, PlanProblem::Kind::NoGo);
    EXPECT_EQ(problems[0].maneuver, u"b"_s);
    EXPECT_EQ(problems[0].message, u"'b' (Goto): a leg crosses the no-go area 'rock'"_s);
    ASSERT_TRUE(problems[0].lat);
    EXPECT_NEAR((*problems[0].lat - home[0]) / metreLat, 170, 1.5) << "marked where the leg enters the circle";
    EXPECT_NEAR((*problems[0].lon - home[1]) / metreLon, 0, 1.5);
    // Passing 40 m beside it is fine.
    EXPECT_TRUE(check(linear({gotoAt(u"a"_s, 0, 40), gotoAt(u"b"_s, 400, 40)}), m).isEmpty());
    // A polygon too, and a rotated box.
    const Mission wreck = missionWith({polygon(u"wreck"_s, u"no-go"_s, {{190, -20}, {210, -20}, {210, 20}, {190, 20}})});
    EXPECT_EQ(kinds(check(linear({gotoAt(u"a"_s, 0, 0), gotoAt(u"b"_s, 400, 0)}), wreck)), QList{PlanProblem::Kind::NoGo});
    Feature box;
    box.kind = u"box"_s;
    box.id = u"cage"_s;
    box.position = offset(200, 60);
    box.attributes = {{u"role"_s, u"no-go"_s}, {u"width"_s, u"10"_s}, {u"length"_s, u"200"_s}, {u"bearing"_s, u"90"_s}};
    EXPECT_EQ(kinds(check(linear({gotoAt(u"a"_s, 0, 0), gotoAt(u"b"_s, 400, 0)}), missionWith({box}))), QList{PlanProblem::Kind::NoGo})
        << "200 m long turned east-west: it reaches the leg";
    box.attributes[u"bearing"_s] = u"0"_s;
    EXPECT_TRUE(check(linear({gotoAt(u"a"_s, 0, 0), gotoAt(u"b"_s, 400, 0)}), missionWith({box})).isEmpty());
}

// A no-go area from 0 to 5 m deep does not bar a leg at 10 m.
TEST(PlanCheck, ANoGoAreaHoldsOnlyItsDepthRange)
{
    Feature shallows = circle(u"shallows"_s, u"no-go"_s, 200, 0, 30);
    shallows.attributes.insert(u"z-min"_s, u"0"_s);
    shallows.attributes.insert(u"z-max"_s, u"5"_s);
    shallows.attributes.insert(u"z-units"_s, u"DEPTH"_s);
    const Mission m = missionWith({shallows});
    EXPECT_TRUE(check(linear({gotoAt(u"a"_s, 0, 0, 10), gotoAt(u"b"_s, 400, 0, 10)}), m).isEmpty());
    EXPECT_EQ(kinds(check(linear({gotoAt(u"a"_s, 0, 0, 2), gotoAt(u"b"_s, 400, 0, 2)}), m)), QList{PlanProblem::Kind::NoGo});
}

// A U-shaped operating area: both ends inside, the leg across the notch is not.
TEST(PlanCheck, ALegThatLeavesTheOperatingAreaIsFlagged)
{
    const Mission m = missionWith({polygon(u"ops"_s, u"operating-area"_s,
                                           {{0, 0}, {300, 0}, {300, 100}, {100, 100}, {100, 200}, {300, 200}, {300, 300}, {0, 300}})});
    EXPECT_TRUE(check(linear({gotoAt(u"a"_s, 50, 50), gotoAt(u"b"_s, 50, 250), gotoAt(u"c"_s, 250, 250)}), m).isEmpty());
    const auto problems = check(linear({gotoAt(u"a"_s, 250, 50), gotoAt(u"b"_s, 250, 250)}), m);
    ASSERT_EQ(problems.size(), 1);
    EXPECT_EQ(problems[0].kind, PlanProblem::Kind::OutsideOperatingArea);
    EXPECT_EQ(problems[0].message, u"'b' (Goto): a leg leaves the operating area 'ops'"_s);
    EXPECT_EQ(problems[0].verdict(), u"unsafe"_s);
    EXPECT_NEAR((*problems[0].lon - home[1]) / metreLon, 100, 1.5) << "marked where it leaves";
    // A waypoint outside every operating area.
    EXPECT_EQ(kinds(check(linear({gotoAt(u"a"_s, 50, 50), gotoAt(u"b"_s, 500, 50)}), m)),
              QList{PlanProblem::Kind::OutsideOperatingArea});
}

TEST(PlanCheck, WhatTheVehicleCannotDoAndHowLongItCanGo)
{
    VehicleDefinition v;
    v.id = u"lauv"_s;
    v.limits.maxDepth = 50;
    v.limits.endurance = 600; // 10 minutes
    v.maneuvers.append({u"Goto"_s, {}});
    const Mission m = missionWith({});
    Maneuver deep = gotoAt(u"deep"_s, 100, 0, 80);
    Maneuver loiter;
    loiter.id = u"wait"_s;
    loiter.type = u"Loiter"_s;
    loiter.parameters = gotoAt(u"x"_s, 100, 0).parameters;
    auto problems = check(linear({gotoAt(u"a"_s, 0, 0), deep, loiter}), m, &v);
    ASSERT_EQ(kinds(problems), (QList{PlanProblem::Kind::Vehicle, PlanProblem::Kind::Vehicle}));
    EXPECT_EQ(problems[0].message, u"'deep' (Goto): depth 80 m is past lauv's 50 m"_s);
    EXPECT_EQ(problems[0].verdict(), u"impossible"_s);
    EXPECT_TRUE(problems[1].message.startsWith(u"'wait' (Loiter): lauv cannot do Loiter"_s)) << problems[1].message.toStdString();
    // 2 km at 1.5 m/s: 22 minutes, past 10.
    problems = check(linear({gotoAt(u"a"_s, 0, 0), gotoAt(u"far"_s, 2000, 0)}), m, &v);
    ASSERT_EQ(kinds(problems), QList{PlanProblem::Kind::Endurance});
    EXPECT_EQ(problems[0].severity, PlanProblem::Severity::Warning) << "the duration is an estimate: past a soft limit warns";
    EXPECT_EQ(problems[0].verdict(), QString());
    EXPECT_EQ(problems[0].message, u"plan 'p' lasts 22 min, past lauv's endurance of 10 min"_s);
}

// The shipped example, against the shipped vehicles: nothing wrong.
TEST(PlanCheck, TheLeixoesExampleIsClean)
{
    const auto mission = loadMission(neptus::test::sourcePath(u"docs/examples/leixoes.xml"_s));
    ASSERT_TRUE(mission.has_value());
    const VehicleCatalog vehicles = loadVehicles({neptus::test::sourcePath(u"vehicles"_s)});
    for (const Plan &plan : mission->plans) {
        const VehicleDefinition *v = vehicles.find(plan.vehicle);
        ASSERT_TRUE(v) << plan.vehicle.toStdString();
        for (const PlanProblem &p : checkPlan(plan, *mission, planGeometry(plan, v->speeds()), v))
            ADD_FAILURE() << plan.id.toStdString() << ": " << p.message.toStdString();
    }
}
