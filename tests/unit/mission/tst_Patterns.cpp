// Survey patterns from what the operator draws: rows over a polygon
// (coverage, alternation, overshoot, cross-hatch), a path along a line, and
// clear errors for shapes that make no pattern.
#include "geo/Geodesy.h"
#include "mission/PlanCheck.h"
#include "mission/Patterns.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace neptus;
using namespace neptus::mission;
using namespace Qt::StringLiterals;

namespace {

const geo::Geodetic origin{geo::radians(41.0), geo::radians(-8.0), 0};

LatLon at(double north, double east)
{
    const geo::Geodetic g = geo::fromNed({north, east, 0}, origin);
    return {geo::degrees(g.lat), geo::degrees(g.lon)};
}

// The path's points in metres north/east of the origin.
std::vector<Eigen::Vector2d> pathOf(const Maneuver &m)
{
    const Eigen::Vector3d start = geo::toNed({geo::radians(m.number(u"lat"_s)), geo::radians(m.number(u"lon"_s)), 0}, origin);
    std::vector<Eigen::Vector2d> out;
    for (const PathPoint &p : m.points)
        out.emplace_back(start.x() + p.x, start.y() + p.y);
    return out;
}

double distanceToSegment(const Eigen::Vector2d &p, const Eigen::Vector2d &a, const Eigen::Vector2d &b)
{
    const Eigen::Vector2d d = b - a;
    const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    return (a + t * d - p).norm();
}

} // namespace

TEST(Patterns, RowsOverASquareAlternateHalfASpacingIn)
{
    const auto m = rowsOver({at(0, 0), at(100, 0), at(100, 100), at(0, 100)}, {20, 0, 0, false}, {3, u"DEPTH"_s, 1.5, u"METERS_PS"_s},
                            u"survey"_s);
    ASSERT_TRUE(m.has_value()) << m.error().toStdString();
    EXPECT_EQ(m->type, u"FollowPath"_s);
    EXPECT_EQ(m->id, u"survey"_s);
    EXPECT_EQ(m->text(u"z_units"_s), u"DEPTH"_s);
    EXPECT_EQ(m->number(u"z"_s), 3);
    const auto path = pathOf(*m);
    ASSERT_EQ(path.size(), 10u) << "5 rows, 2 ends each";
    for (int r = 0; r < 5; ++r) {
        const double east = 10 + 20 * r;
        const bool north = r % 2 == 0;
        EXPECT_NEAR(path[size_t(2 * r)].y(), east, 0.01);
        EXPECT_NEAR(path[size_t(2 * r + 1)].y(), east, 0.01);
        EXPECT_NEAR(path[size_t(2 * r)].x(), north ? 0 : 100, 0.01) << "row " << r;
        EXPECT_NEAR(path[size_t(2 * r + 1)].x(), north ? 100 : 0, 0.01) << "row " << r;
    }
    // 5 rows of 100 m and 4 steps of 20 m.
    const ManeuverGeometry g = maneuverGeometry(*m);
    EXPECT_NEAR(g.length, 580, 0.5);
}

// A pentagon at 37°: every point inside lies within half a spacing of a row
// (slanted edges included), and no row ends further out than the overshoot
// plus the half spacing its band reaches past its own line.
TEST(Patterns, RowsCoverAnyPolygonAtAnyAngle)
{
    const QList<LatLon> pentagon{at(0, 0), at(120, -30), at(250, 60), at(180, 220), at(20, 160)};
    const double spacing = 25, overshoot = 15;
    const auto m = rowsOver(pentagon, {spacing, 37, overshoot, false}, {}, u"p"_s);
    ASSERT_TRUE(m.has_value()) << m.error().toStdString();
    const auto path = pathOf(*m);
    std::vector<Eigen::Vector2d> corners;
    for (const LatLon &c : pentagon) {
        const Eigen::Vector3d v = geo::toNed({geo::radians(c.lat), geo::radians(c.lon), 0}, origin);
        corners.emplace_back(v.x(), v.y());
    }
    const auto inside = [&](const Eigen::Vector2d &p) {
        bool in = false;
        for (size_t i = 0, j = corners.size() - 1; i < corners.size(); j = i++) {
            const auto &a = corners[i], &b = corners[j];
            if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
                in = !in;
        }
        return in;
    };
    int sampled = 0;
    for (double n = -40; n <= 260; n += 3) {
        for (double e = -40; e <= 230; e += 3) {
            const Eigen::Vector2d p(n, e);
            if (!inside(p))
                continue;
            ++sampled;
            double nearest = 1e9;
            for (size_t i = 0; i + 1 < path.size(); i += 2) // the rows, not the steps between them
                nearest = std::min(nearest, distanceToSegment(p, path[i], path[i + 1]));
            ASSERT_LE(nearest, spacing / 2 + 0.01) << "uncovered at " << n << ", " << e;
        }
    }
    EXPECT_GT(sampled, 2000);
    for (const auto &end : path) {
        double toEdge = 1e9;
        for (size_t i = 0, j = corners.size() - 1; i < corners.size(); j = i++)
            toEdge = std::min(toEdge, distanceToSegment(end, corners[j], corners[i]));
        EXPECT_LE(inside(end) ? 0 : toEdge, overshoot + spacing / 2 + 0.01) << "a row end " << toEdge << " m out";
    }
}

TEST(Patterns, CrossHatchAddsTheRowsAtRightAngles)
{
    const QList<LatLon> square{at(0, 0), at(100, 0), at(100, 100), at(0, 100)};
    const auto once = rowsOver(square, {20, 0, 0, false}, {}, u"a"_s);
    const auto twice = rowsOver(square, {20, 0, 0, true}, {}, u"b"_s);
    ASSERT_TRUE(once && twice);
    EXPECT_EQ(twice->points.size(), 2 * once->points.size());
    const auto path = pathOf(*twice);
    // The second pass runs east-west: its rows keep their north.
    EXPECT_NEAR(path[10].x(), path[11].x(), 0.01);
    EXPECT_NEAR(std::abs(path[10].y() - path[11].y()), 100, 0.01);
}

// The pattern over a survey area inside the operating area passes the
// editor's check; the same rows with a long overshoot leave it.
TEST(Patterns, ASurveyInsideTheOperatingAreaPassesTheCheck)
{
    Mission mission;
    mission.home = {41, -8, 0};
    Feature ops;
    ops.kind = u"polygon"_s;
    ops.id = u"ops"_s;
    ops.attributes = {{u"role"_s, u"operating-area"_s}};
    for (const auto &[n, e] : std::initializer_list<std::pair<double, double>>{{-20, -20}, {120, -20}, {120, 120}, {-20, 120}}) {
        Feature::Point p;
        p.north = n;
        p.east = e;
        ops.points.append(p);
    }
    mission.maps.append({u"m"_s, {}, {ops}});
    const QList<LatLon> square{at(0, 0), at(100, 0), at(100, 100), at(0, 100)};
    Plan plan;
    plan.id = u"survey"_s;
    plan.start = u"rows"_s;
    plan.maneuvers = {*rowsOver(square, {20, 30, 10, true}, {}, u"rows"_s)};
    EXPECT_TRUE(checkPlan(plan, mission, planGeometry(plan), nullptr).isEmpty());
    plan.maneuvers = {*rowsOver(square, {20, 30, 40, false}, {}, u"rows"_s)};
    const auto problems = checkPlan(plan, mission, planGeometry(plan), nullptr);
    ASSERT_EQ(problems.size(), 1);
    EXPECT_EQ(problems[0].kind, PlanProblem::Kind::OutsideOperatingArea);
}

TEST(Patterns, APathAlongADrawnLine)
{
    const auto m = pathAlong({at(0, 0), at(50, 0), at(50, 80)}, {0, u"DEPTH"_s, 2, u"METERS_PS"_s}, u"line"_s);
    ASSERT_TRUE(m.has_value());
    ASSERT_EQ(m->points.size(), 3);
    EXPECT_EQ(m->points[0].x, 0);
    EXPECT_NEAR(m->points[2].x, 50, 0.01);
    EXPECT_NEAR(m->points[2].y, 80, 0.01);
    EXPECT_NEAR(maneuverGeometry(*m).length, 130, 0.1);
}

TEST(Patterns, ShapesThatMakeNoPatternAreSaid)
{
    const auto error = [](const std::expected<Maneuver, QString> &m) { return m ? std::string("(made)") : m.error().toStdString(); };
    EXPECT_EQ(error(rowsOver({at(0, 0), at(10, 0)}, {}, {}, u"x"_s)), "a survey area needs at least three corners (it has 2)");
    EXPECT_EQ(error(rowsOver({at(0, 0), at(10, 0), at(10, 10)}, {0, 0, 0, false}, {}, u"x"_s)),
              "the spacing between rows must be more than 0 m");
    EXPECT_TRUE(error(rowsOver({at(0, 0), at(0, 100000), at(100000, 0)}, {1, 90, 0, false}, {}, u"x"_s))
                    .ends_with(" m across at 1 m spacing would be more than 10,000 rows"));
    EXPECT_EQ(error(rowsOver({at(0, 0), at(10, 0), at(20, 0)}, {5, 0, 0, false}, {}, u"x"_s)),
              "the survey area has no inside (its corners are in a line)");
    EXPECT_EQ(error(rowsOver({at(0, 0), at(10, 0), LatLon{NAN, 0}}, {}, {}, u"x"_s)), "a corner of the survey area is not a position");
    EXPECT_EQ(error(pathAlong({at(0, 0)}, {}, u"x"_s)), "a path needs at least two points (it has 1)");
}
