#include "mission/PlanGeometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace neptus::mission;
using namespace Qt::StringLiterals;

namespace {

Maneuver maneuver(const QString &type, std::initializer_list<std::pair<const char *, double>> numbers,
                  std::initializer_list<std::pair<const char *, const char *>> texts = {})
{
    Maneuver m;
    m.id = type.toLower();
    m.type = type;
    m.set(u"lat"_s, 41.0);
    m.set(u"lon"_s, -8.0);
    for (const auto &[name, value] : numbers)
        m.set(QString::fromLatin1(name), value);
    for (const auto &[name, value] : texts)
        m.parameters.insert(QString::fromLatin1(name), QString::fromLatin1(value));
    return m;
}

// One metre of latitude at 41° N, in degrees (WGS84 meridian arc: 111,052 m per degree).
constexpr double degreesPerMetreNorth = 1 / 111052.0;

} // namespace

TEST(PlanGeometry, GotoIsItsTransit)
{
    const Waypoint from{41.0 - 1000 * degreesPerMetreNorth, -8.0, 0, u"DEPTH"_s, 0, 0};
    const auto g = maneuverGeometry(maneuver(u"Goto"_s, {{"speed", 2}, {"z", 3}}, {{"z_units", "DEPTH"}}), &from);
    ASSERT_EQ(g.points.size(), 1);
    EXPECT_NEAR(g.transit, 1000, 1.0);
    EXPECT_EQ(g.length, 0);
    EXPECT_NEAR(*g.duration, 500, 0.5);
    EXPECT_EQ(g.maxZ, 3);
}

TEST(PlanGeometry, RowsMakeALawnmower)
{
    // 50 m wide in 10 m steps: 6 rows of 100 m plus 5 m curve offsets at both ends, 5 steps between.
    const auto g = maneuverGeometry(maneuver(u"Rows"_s, {{"bearing", 0}, {"width", 50}, {"length", 100}, {"hstep", 10},
                                                         {"coff", 5}, {"speed", 1}}));
    ASSERT_EQ(g.points.size(), 12);
    EXPECT_NEAR(g.length, 6 * 110 + 5 * 10, 0.05);
    EXPECT_NEAR(*g.duration, 710, 0.05);
    // First row northwards from 5 m south of the start; the first turn is to the left (west).
    EXPECT_NEAR((g.points[1].lat - g.points[0].lat) / degreesPerMetreNorth, 110, 0.1);
    EXPECT_LT(g.points[2].lon, g.points[1].lon);
    EXPECT_NEAR(g.points[2].lat, g.points[1].lat, 1e-9);
    // CURVE_RIGHT turns east instead.
    const auto right = maneuverGeometry(maneuver(u"Rows"_s, {{"width", 50}, {"length", 100}, {"hstep", 10}},
                                                 {{"flags", "CURVE_RIGHT"}}));
    EXPECT_GT(right.points[2].lon, right.points[1].lon);
    // Alternating steps of 50 % and 150 % cover the same width in the same rows.
    const auto alternating = maneuverGeometry(maneuver(u"Rows"_s, {{"width", 50}, {"length", 100}, {"hstep", 10},
                                                                   {"alternation", 50}}));
    EXPECT_NEAR(alternating.length, 6 * 100 + 3 * 5 + 2 * 15, 0.05);
}

TEST(PlanGeometry, LoitersLastTheirDurationOrForEver)
{
    const auto timed = maneuverGeometry(maneuver(u"Loiter"_s, {{"radius", 20}, {"duration", 300}, {"speed", 1.5}}));
    EXPECT_EQ(timed.points.size(), 37); // a closed circle
    EXPECT_NEAR(timed.length, 450, 1e-9);
    EXPECT_NEAR(*timed.duration, 300, 1e-9);
    EXPECT_NEAR(distance(timed.points[0], timed.points[18]), 40, 0.01); // a diameter
    const auto endless = maneuverGeometry(maneuver(u"Loiter"_s, {{"radius", 20}, {"speed", 1.5}}));
    EXPECT_FALSE(endless.duration);
    EXPECT_NEAR(endless.length, 2 * std::numbers::pi * 20, 0.2); // one lap, as 36 chords
    const auto keeping = maneuverGeometry(maneuver(u"StationKeeping"_s, {{"duration", 60}, {"speed", 1}}));
    EXPECT_NEAR(*keeping.duration, 60, 1e-9);
    EXPECT_FALSE(maneuverGeometry(maneuver(u"StationKeeping"_s, {})).duration);
}

TEST(PlanGeometry, PathsSquaresAndProfiles)
{
    Maneuver path = maneuver(u"FollowPath"_s, {{"z", 2}, {"speed", 1}}, {{"z_units", "DEPTH"}});
    path.points = {{0, 0, 0, {}}, {30, 0, 1, {}}, {30, 40, 4, {}}};
    const auto p = maneuverGeometry(path);
    EXPECT_NEAR(p.length, 70, 0.01);
    EXPECT_EQ(p.minZ, 2);
    EXPECT_EQ(p.maxZ, 6);

    // Legs 10, 10, 20, 20, 30, 30.
    const auto square = maneuverGeometry(maneuver(u"ExpandingSquare"_s, {{"width", 30}, {"hstep", 10}, {"speed", 1}}));
    EXPECT_EQ(square.points.size(), 7);
    EXPECT_NEAR(square.length, 120, 0.01);

    const auto cross = maneuverGeometry(maneuver(u"CrossHatch"_s, {{"width", 100}, {"hstep", 50}, {"coff", 10}, {"speed", 1}},
                                                 {{"flags", "SQUARE_CURVE"}}));
    EXPECT_EQ(cross.points.size(), 12);
    EXPECT_NEAR(cross.length, 2 * (3 * 120 + 2 * 50) + std::hypot(110, 10), 0.01);

    const auto yoyo = maneuverGeometry(maneuver(u"YoYo"_s, {{"z", 10}, {"amplitude", 4}}, {{"z_units", "DEPTH"}}));
    EXPECT_EQ(yoyo.minZ, 6);
    EXPECT_EQ(yoyo.maxZ, 14);
    const auto shallow = maneuverGeometry(maneuver(u"YoYo"_s, {{"z", 5}, {"amplitude", 10}}, {{"z_units", "DEPTH"}}));
    EXPECT_EQ(shallow.minZ, 0); // not 5 m above the surface
    EXPECT_EQ(shallow.maxZ, 15);
    const auto elevator = maneuverGeometry(maneuver(u"Elevator"_s, {{"start_z", 2}, {"end_z", 20}},
                                                    {{"end_z_units", "DEPTH"}}));
    EXPECT_EQ(elevator.zUnits, u"DEPTH"_s);
    EXPECT_EQ(elevator.maxZ, 20);
    EXPECT_EQ(elevator.minZ, 2);
    const auto popup = maneuverGeometry(maneuver(u"PopUp"_s, {{"duration", 45}, {"speed", 1}}));
    EXPECT_NEAR(*popup.duration, 45, 1e-9);
}

TEST(PlanGeometry, SpeedsInRpmAndPercentUseTheVehicleFigures)
{
    const Waypoint from{41.0 - 100 * degreesPerMetreNorth, -8.0, 0, {}, 0, 0};
    SpeedModel speeds;
    speeds.metresPerSecondPerRpm = 1.0 / 500;
    speeds.maxSpeed = 4;
    const auto rpm = maneuverGeometry(maneuver(u"Goto"_s, {{"speed", 1000}}, {{"speed_units", "RPM"}}), &from, speeds);
    EXPECT_DOUBLE_EQ(rpm.speed, 2);
    const auto percent = maneuverGeometry(maneuver(u"Goto"_s, {{"speed", 25}}, {{"speed_units", "PERCENTAGE"}}), &from, speeds);
    EXPECT_DOUBLE_EQ(percent.speed, 1);
    EXPECT_DOUBLE_EQ(maneuverGeometry(maneuver(u"Goto"_s, {}), &from, speeds).speed, speeds.defaultSpeed);
}

TEST(PlanGeometry, APlanFollowsItsTransitionsFromTheStart)
{
    Plan plan;
    plan.start = u"b"_s;
    Maneuver a = maneuver(u"Goto"_s, {{"speed", 1}, {"z", 5}}, {{"z_units", "DEPTH"}});
    a.id = u"a"_s;
    Maneuver b = maneuver(u"Goto"_s, {{"speed", 1}, {"z", 12}}, {{"z_units", "DEPTH"}});
    b.id = u"b"_s;
    b.set(u"lat"_s, 41.0 - 200 * degreesPerMetreNorth);
    Maneuver c = maneuver(u"Loiter"_s, {{"speed", 1}, {"radius", 10}, {"z", 50}}, {{"z_units", "HEIGHT"}});
    c.id = u"c"_s;
    plan.maneuvers = {a, b, c};
    Transition ba;
    ba.from = u"b"_s;
    ba.to = u"a"_s;
    Transition ac = ba;
    ac.from = u"a"_s;
    ac.to = u"c"_s;
    plan.transitions = {ba, ac};
    const auto g = planGeometry(plan);
    ASSERT_EQ(g.maneuvers.size(), 3);
    EXPECT_EQ(g.maneuvers[0].id, u"b"_s);
    EXPECT_EQ(g.maneuvers[1].id, u"a"_s);
    EXPECT_NEAR(g.maneuvers[1].transit, 200, 0.2);
    EXPECT_FALSE(g.duration); // the loiter never ends
    EXPECT_EQ(g.maxDepth, 12.0);
    EXPECT_EQ(g.maxHeight, 50.0);
    EXPECT_FALSE(g.maxAltitude);
    plan.transitions.removeLast();
    plan.maneuvers.removeLast();
    const auto bounded = planGeometry(plan);
    ASSERT_TRUE(bounded.duration);
    EXPECT_NEAR(*bounded.duration, 200, 0.2);
    EXPECT_NEAR(bounded.length, 200, 0.2);
}

// Every maneuver type from 100 m south of its position: its points, length
// (transit apart) and duration at 1 m/s.
TEST(PlanGeometry, EveryManeuverTypeHasItsGeometry)
{
    const Waypoint from{41.0 - 100 * degreesPerMetreNorth, -8.0, 0, u"DEPTH"_s, 0, 0};
    struct Case
    {
        Maneuver maneuver;
        qsizetype points;
        double length;
        std::optional<double> seconds; // after the 100 s transit; empty: never ends
    };
    Maneuver path = maneuver(u"FollowPath"_s, {{"speed", 1}});
    path.points = {{0, 0, 0, {}}, {0, 50, 0, {}}};
    Maneuver trajectory = maneuver(u"FollowTrajectory"_s, {{"speed", 1}});
    trajectory.points = {{0, 0, 0, 0.0}, {30, 40, 0, 60.0}};
    const QList<Case> cases{
        {maneuver(u"Goto"_s, {{"speed", 1}}), 1, 0, 0},
        {maneuver(u"PopUp"_s, {{"speed", 1}, {"duration", 30}}), 1, 0, 30},
        {maneuver(u"Loiter"_s, {{"speed", 1}, {"radius", 10}, {"duration", 120}}), 37, 120, 120},
        {maneuver(u"Loiter"_s, {{"speed", 1}, {"radius", 10}}), 37, 2 * 36 * 10 * std::sin(std::numbers::pi / 36), std::nullopt},
        {maneuver(u"StationKeeping"_s, {{"speed", 1}, {"duration", 90}}), 1, 0, 90},
        {maneuver(u"YoYo"_s, {{"speed", 1}, {"z", 10}, {"amplitude", 2}}), 1, 0, 0},
        {maneuver(u"Rows"_s, {{"speed", 1}, {"width", 20}, {"length", 50}, {"hstep", 10}}), 6, 3 * 50 + 2 * 10, 170},
        {path, 2, 50, 50},
        {trajectory, 2, 50, 50},
        {maneuver(u"Elevator"_s, {{"speed", 1}, {"start_z", 0}, {"end_z", 10}}), 1, 0, 0},
        {maneuver(u"ExpandingSquare"_s, {{"speed", 1}, {"width", 20}, {"hstep", 10}}), 5, 10 + 10 + 20 + 20, 60},
        {maneuver(u"CompassCalibration"_s, {{"speed", 1}, {"radius", 15}, {"duration", 600}}), 37, 600, 600},
        {maneuver(u"ScheduledGoto"_s, {{"arrival_time", 1.8e9}}), 1, 0, 0},
        {maneuver(u"Launch"_s, {{"speed", 1}}), 1, 0, 0},
        {maneuver(u"Takeoff"_s, {{"speed", 1}, {"z", 100}}, {{"z_units", "HEIGHT"}}), 1, 0, 0},
        {maneuver(u"Land"_s, {{"speed", 1}}, {{"z_units", "HEIGHT"}}), 1, 0, 0},
    };
    for (const Case &c : cases) {
        const auto g = maneuverGeometry(c.maneuver, &from);
        const std::string type = c.maneuver.type.toStdString();
        EXPECT_EQ(g.points.size(), c.points) << type;
        // (A circle begins on its north side, its radius beyond the position.)
        EXPECT_NEAR(g.transit, 100 + c.maneuver.number(u"radius"_s) * (c.points == 37), 0.2) << type;
        EXPECT_NEAR(g.length, c.length, 0.01) << type;
        ASSERT_EQ(g.duration.has_value(), c.seconds.has_value()) << type;
        if (c.seconds) {
            EXPECT_NEAR(*g.duration - g.transit, *c.seconds, 0.01) << type;
        }
        // Legs add up to the length (a timed loiter goes round more than once).
        double legs = 0;
        for (qsizetype i = 1; i < g.points.size(); ++i)
            legs += g.points[i].leg;
        if (c.maneuver.type != u"Loiter" && c.maneuver.type != u"CompassCalibration") {
            EXPECT_NEAR(legs, g.length, 1e-6) << type;
        }
        EXPECT_NEAR(g.points.first().leg, g.transit, 1e-9) << type;
    }
}

// Neptus's CrossHatchPattern (ManeuversUtil.calcCrossHatchPatternPoints, worked
// by hand for a 100 m square, rows 50 m apart, run on 10 m): rows north and
// south from the square's south-west corner, stepping east, then rows west and
// east from its south-east corner, stepping north; each row 10 m past the square.
TEST(PlanGeometry, CrossHatchIsNeptusCrossHatchPattern)
{
    const auto offsets = [](const Maneuver &m) {
        QList<std::pair<double, double>> out;
        for (const PathPoint &p : crossHatchOffsets(m))
            out.append({std::round(p.x * 1e6) / 1e6 + 0.0, std::round(p.y * 1e6) / 1e6 + 0.0});
        return out;
    };
    using Points = QList<std::pair<double, double>>;
    const Maneuver square = maneuver(u"CrossHatch"_s, {{"width", 100}, {"hstep", 50}, {"coff", 10}}, {{"flags", "SQUARE_CURVE"}});
    EXPECT_EQ(offsets(square), (Points{{-60, -50}, {60, -50}, {60, 0}, {-60, 0}, {-60, 50}, {60, 50},
                                       {-50, 60}, {-50, -60}, {0, -60}, {0, 60}, {50, 60}, {50, -60}}));
    EXPECT_TRUE(isWorkedPattern(u"CrossHatch"_s));
    EXPECT_FALSE(isWorkedPattern(u"Rows"_s));

    // Without square turns the step is cut diagonally, ending the run-on at the next row.
    const Maneuver cut = maneuver(u"CrossHatch"_s, {{"width", 100}, {"hstep", 50}, {"coff", 10}});
    EXPECT_EQ(offsets(cut).mid(0, 6), (Points{{-60, -50}, {60, -50}, {50, 0}, {-60, 0}, {-50, 50}, {60, 50}}));

    // Turned with its bearing, about its centre.
    const Maneuver east = maneuver(u"CrossHatch"_s, {{"width", 100}, {"hstep", 50}, {"coff", 10}, {"bearing", 90}},
                                   {{"flags", "SQUARE_CURVE"}});
    EXPECT_EQ(offsets(east).mid(0, 2), (Points{{50, -60}, {50, 60}}));

    // A hostile step does not hang: at most 10,000 rows each way.
    const Maneuver dense = maneuver(u"CrossHatch"_s, {{"width", 1e9}, {"hstep", 0}});
    EXPECT_LE(crossHatchOffsets(dense).size(), 2 * (1 + 2 * 10000));

    // What the IMC FollowPath carries so that Neptus recognises its pattern: RowsPattern.serializeToIMC's
    // keys in its order, sRange included (its parseIMCMessage throws without it), Neptus's 30 m by default...
    EXPECT_EQ(patternCustom(square), u"Pattern=CrossHatchPattern;bearingRad=0;width=100;hstep=50;sRange=30;curvOff=10;squareCurve=true"_s);
    // ...the maneuver's own sRange in its place, its other settings after, the pattern's own figures once.
    Maneuver named = square;
    named.parameters.insert(u"custom"_s, u"Pattern=CrossHatchPattern;width=1;sRange=45;Formation=line"_s);
    EXPECT_EQ(patternCustom(named),
              u"Pattern=CrossHatchPattern;bearingRad=0;width=100;hstep=50;sRange=45;curvOff=10;squareCurve=true;Formation=line"_s);
    // Only the pattern's shape parameters stay out of the FollowPath; its speed and depth go in.
    EXPECT_FALSE(patternShapeParameters(u"CrossHatch"_s).contains(u"speed"_s));
    EXPECT_FALSE(patternShapeParameters(u"CrossHatch"_s).contains(u"z"_s));
}

// A Rows' alternation as DUNE's RowsStages steps it (alt_frac_up = alternation %,
// alt_frac_down = 200 − alternation %): none is 100 (even rows), 0 drives each
// row twice and steps 2·hstep on, 50 alternates half and one and a half steps.
TEST(PlanGeometry, RowsAlternationIsDunes)
{
    const auto across = [](const Maneuver &m) { // the rows' east offsets, north-going rows at bearing 0
        QList<double> out;
        const auto g = maneuverGeometry(m);
        const auto origin = g.points.first();
        for (qsizetype i = 0; i < g.points.size(); i += 2)
            out.append(std::round(distance(Waypoint{origin.lat, origin.lon, 0, {}, 0, 0},
                                           Waypoint{origin.lat, g.points[i].lon, 0, {}, 0, 0})));
        return out;
    };
    const auto rows = [](std::optional<double> alternation) {
        Maneuver m = maneuver(u"Rows"_s, {{"width", 40}, {"length", 50}, {"hstep", 10}, {"speed", 1}}, {{"flags", "CURVE_RIGHT"}});
        if (alternation)
            m.set(u"alternation"_s, *alternation);
        return m;
    };
    EXPECT_EQ(rowsAlternation(rows({})), 100);
    EXPECT_EQ(across(rows({})), (QList<double>{0, 10, 20, 30, 40}));
    EXPECT_EQ(across(rows(100)), (QList<double>{0, 10, 20, 30, 40}));
    EXPECT_EQ(across(rows(50)), (QList<double>{0, 5, 20, 25, 40}));
    EXPECT_EQ(across(rows(0)), (QList<double>{0, 0, 20, 20, 40}));
}

// The editor's cache: after each edit the plan worked out with it is the plan
// worked out from scratch, and a maneuver nobody touched is not worked out again.
TEST(PlanGeometry, TheCacheGivesWhatAFreshWorkingOutGives)
{
    Plan plan;
    plan.id = u"p"_s;
    for (int i = 0; i < 5; ++i) {
        Maneuver m = maneuver(u"Goto"_s, {{"speed", 1.5}, {"z", 2}}, {{"z_units", "DEPTH"}});
        m.id = u"m%1"_s.arg(i);
        m.set(u"lat"_s, 41.0 + i * 0.001);
        plan.maneuvers.append(m);
        if (i > 0)
            plan.transitions.append(Transition{u"m%1"_s.arg(i - 1), m.id, u"ManeuverIsDone"_s, {}, {}});
    }
    plan.start = u"m0"_s;
    const auto same = [](const PlanGeometry &a, const PlanGeometry &b) {
        if (a.maneuvers.size() != b.maneuvers.size() || a.length != b.length || a.duration != b.duration)
            return false;
        for (qsizetype i = 0; i < a.maneuvers.size(); ++i) {
            const ManeuverGeometry &x = a.maneuvers[i], &y = b.maneuvers[i];
            if (x.id != y.id || x.transit != y.transit || x.points.size() != y.points.size() || x.points.first().lat != y.points.first().lat
                || x.points.first().heading != y.points.first().heading || x.duration != y.duration)
                return false;
        }
        return true;
    };
    PlanGeometryCache cache;
    SpeedModel speeds;
    EXPECT_TRUE(same(planGeometry(plan, speeds, &cache), planGeometry(plan, speeds)));
    // One moved: it and the transit of the one after change.
    plan.maneuvers[2].set(u"lon"_s, -8.001);
    const PlanGeometry edited = planGeometry(plan, speeds, &cache);
    EXPECT_TRUE(same(edited, planGeometry(plan, speeds)));
    // Untouched maneuvers came from the cache: their paths are the cached lists themselves.
    const PlanGeometry again = planGeometry(plan, speeds, &cache);
    EXPECT_TRUE(again.maneuvers[0].points.isSharedWith(edited.maneuvers[0].points));
    EXPECT_TRUE(again.maneuvers[4].points.isSharedWith(edited.maneuvers[4].points));
    // Other speeds: everything again.
    speeds.defaultSpeed = 0.5;
    plan.maneuvers[1].parameters.remove(u"speed"_s);
    EXPECT_TRUE(same(planGeometry(plan, speeds, &cache), planGeometry(plan, speeds)));
    // Removed and reordered maneuvers.
    plan.maneuvers.removeAt(1);
    plan.transitions = {Transition{u"m0"_s, u"m3"_s, u"ManeuverIsDone"_s, {}, {}}, Transition{u"m3"_s, u"m2"_s, u"ManeuverIsDone"_s, {}, {}},
                        Transition{u"m2"_s, u"m4"_s, u"ManeuverIsDone"_s, {}, {}}};
    EXPECT_TRUE(same(planGeometry(plan, speeds, &cache), planGeometry(plan, speeds)));
}
