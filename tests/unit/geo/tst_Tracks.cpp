// Tracks: the console's record of where each system has been, fed by the tree.
#include "geo/Geodesy.h"
#include "Schemas.h"
#include "qmlmodels/Tracks.h"
#include "qmlmodels/VariableTreeModel.h"

#include <QAbstractItemModelTester>
#include <QSignalSpy>
#include <QTest>

#include <gtest/gtest.h>

using namespace neptus;
using namespace neptus::geo;

namespace {

msg::Message state(quint16 src, double latDeg, double lonDeg, double x, double y, double depth, double psi = 0)
{
    msg::Message m(neptus::test::shippedSchema()->byAbbrev(u"EstimatedState"));
    m.header.src = src;
    m.header.timestamp = 1000;
    auto set = [&](const char16_t *name, double v) { m.setNumber(m.def()->indexOf(name), v); };
    set(u"lat", radians(latDeg));
    set(u"lon", radians(lonDeg));
    set(u"x", x);
    set(u"y", y);
    set(u"z", depth);
    set(u"depth", depth);
    set(u"psi", psi);
    return m;
}

struct TrackRecording : ::testing::Test
{
    ManualClock clock;
    tree::VariableTree tree{&clock};
    tree::VariableTreeModel model{&tree};
    Tracks tracks{&model};
};

} // namespace

TEST_F(TrackRecording, EachSystemGetsATrailOfAbsolutePositions)
{
    tree.setSystemName(0x1f, QStringLiteral("lauv"));
    QSignalSpy updated(&tracks, &Tracks::updated);
    for (int i = 0; i < 5; ++i) {
        tree.ingest(state(0x1f, 41.18, -8.70, 10.0 * i, 0, 2, 0.5));
        model.sync(); // one frame per message: each is a fix
    }
    tree.ingest(state(0x20, 41.0, -8.0, 0, 0, 0));
    model.sync();

    EXPECT_EQ(tracks.systems(), (QStringList{QStringLiteral("lauv"), QStringLiteral("0x0020")}));
    const auto *t = tracks.track(QStringLiteral("lauv"));
    ASSERT_TRUE(t);
    ASSERT_EQ(t->fixes.size(), 5u);
    EXPECT_GE(updated.count(), 5);
    // The last fix is the reference moved 40 m north, 2 m down.
    const auto g = inverse(radians(41.18), radians(-8.70), t->fixes.back().lat, t->fixes.back().lon);
    ASSERT_TRUE(g);
    EXPECT_NEAR(g->distance, 40, 0.01);
    EXPECT_NEAR(g->initialAzimuth, 0, 1e-6);
    EXPECT_NEAR(t->fixes.back().depth, 2, 1e-6);

    const auto latest = tracks.latest(QStringLiteral("lauv"));
    EXPECT_NEAR(latest.value(QStringLiteral("heading")).toDouble(), degrees(0.5), 1e-4);
    EXPECT_EQ(latest.value(QStringLiteral("count")).toInt(), 5);
    EXPECT_TRUE(tracks.latest(QStringLiteral("nobody")).isEmpty());
    // Home: the first system's reference.
    EXPECT_NEAR(tracks.home().value(QStringLiteral("lat")).toDouble(), 41.18, 1e-12);
}

// A stock DUNE announces itself (with where it is: its Announce's lat/lon
// come from its EstimatedState) seconds before it streams to a console it has
// just met: it is on the map from that Announce, until its own state comes.
TEST_F(TrackRecording, AVehicleIsPlacedFromItsAnnounceUntilItsFirstState)
{
    tree.setSystemName(0xd1, QStringLiteral("lauv-simulator-1"));
    msg::Message announce(neptus::test::shippedSchema()->byAbbrev(u"Announce"));
    announce.header.src = 0xd1;
    announce.setNumber(announce.def()->indexOf(u"lat"), radians(41.185));
    announce.setNumber(announce.def()->indexOf(u"lon"), radians(-8.706));
    tree.ingest(announce);
    model.sync();
    auto latest = tracks.latest(QStringLiteral("lauv-simulator-1"));
    ASSERT_FALSE(latest.isEmpty()) << "on the map from its Announce";
    EXPECT_NEAR(latest.value(QStringLiteral("lat")).toDouble(), 41.185, 1e-9);
    EXPECT_TRUE(latest.value(QStringLiteral("announced")).toBool());
    tree.ingest(announce); // again, 10 s later: still one point
    model.sync();
    EXPECT_EQ(tracks.track(QStringLiteral("lauv-simulator-1"))->fixes.size(), 1u);

    tree.ingest(state(0xd1, 41.18, -8.70, 10, 0, 0));
    model.sync();
    latest = tracks.latest(QStringLiteral("lauv-simulator-1"));
    EXPECT_FALSE(latest.value(QStringLiteral("announced")).toBool());
    EXPECT_EQ(latest.value(QStringLiteral("count")).toInt(), 1) << "the announced place is no part of its trail";
    tree.ingest(announce); // its Announce no longer moves it
    model.sync();
    EXPECT_NEAR(tracks.latest(QStringLiteral("lauv-simulator-1")).value(QStringLiteral("lat")).toDouble(), 41.18009, 1e-4);

    // No position in an Announce (0, 0): not placed at all.
    msg::Message nowhere(neptus::test::shippedSchema()->byAbbrev(u"Announce"));
    nowhere.header.src = 0x4002;
    tree.ingest(nowhere);
    model.sync();
    EXPECT_TRUE(tracks.latest(QStringLiteral("0x4002")).isEmpty());
}

TEST_F(TrackRecording, StandingStillAddsNoFixesButKeepsTheLatestState)
{
    for (int i = 0; i < 10; ++i) {
        tree.ingest(state(0x1f, 41.18, -8.70, 0, 0, 0, 0.1 * i));
        model.sync();
    }
    EXPECT_EQ(tracks.count(QStringLiteral("0x001f")), 1);
    EXPECT_NEAR(tracks.latest(QStringLiteral("0x001f")).value(QStringLiteral("heading")).toDouble(), degrees(0.9), 1e-4);
}

TEST_F(TrackRecording, ATrackKeepsItsPointsWhenTheSystemIsNamedLater)
{
    tree.ingest(state(0x1f, 41.18, -8.70, 0, 0, 0));
    model.sync();
    ASSERT_EQ(tracks.systems(), QStringList{QStringLiteral("0x001f")});
    tree.setSystemName(0x1f, QStringLiteral("lauv"));
    tree.ingest(state(0x1f, 41.18, -8.70, 10, 0, 0));
    model.sync();
    EXPECT_EQ(tracks.systems(), QStringList{QStringLiteral("lauv")});
    EXPECT_EQ(tracks.count(QStringLiteral("lauv")), 2);
}

TEST_F(TrackRecording, InvalidPositionsAreNotDrawnAnywhere)
{
    tree.ingest(state(0x1f, 91, 0, 0, 0, 0));
    model.sync();
    EXPECT_EQ(tracks.count(QStringLiteral("0x001f")), 0);
}

// A full trail thins its older half to every other fix: the whole of it is
// still drawn (the past coarser), and it never holds more than its capacity.
TEST_F(TrackRecording, AFullTrackThinsItsOlderHalf)
{
    tracks.setCapacity(100);
    for (int i = 0; i < 150; ++i) // 11 m apart: every one kept
        tracks.append(QStringLiteral("sim"), Tracks::Fix{double(i), radians(41 + i * 1e-4), radians(-8), 0, 0, 0, 0, 0});
    const auto *t = tracks.track(QStringLiteral("sim"));
    ASSERT_TRUE(t);
    EXPECT_LE(t->fixes.size(), 100u);
    EXPECT_EQ(t->fixes.size() + t->dropped, 150u);
    EXPECT_EQ(t->fixes.front().time, 0) << "where it began is still drawn";
    EXPECT_GT(t->fixes[1].time, 1) << "the older part thinned";
    EXPECT_EQ(t->fixes[t->fixes.size() - 2].time, 148) << "the newer part whole";
    EXPECT_EQ(t->fixes.back().time, 149);
    tracks.clear(QStringLiteral("sim"));
    EXPECT_EQ(tracks.count(QStringLiteral("sim")), 0);
}

// Memory over hours: a trail keeps a fix every few metres along a straight
// leg and enough of a turn to keep its shape within 0.2 m, not every fix
// (10 a second, each 0.15 m on: most of a console's growth over hours).
TEST_F(TrackRecording, StraightLegsCostFewFixesAndTurnsKeepTheirShape)
{
    const double metre = 1.0 / 6'371'000; // rad of latitude
    for (int i = 0; i <= 1000; ++i) // 150 m north, a fix each 0.15 m
        tracks.append(QStringLiteral("leg"), Tracks::Fix{1000 + i * 0.1, radians(41) + i * 0.15 * metre, radians(-8), 0, 0, 0, 0, 0});
    const auto *leg = tracks.track(QStringLiteral("leg"));
    EXPECT_LE(leg->fixes.size(), 32u) << "one each 5 m";
    EXPECT_GE(leg->fixes.size(), 29u);

    // A 20 m circle: every fix of it within 0.2 m of the trail kept.
    std::vector<Eigen::Vector2d> all;
    for (int i = 0; i <= 838; ++i) { // 0.15 m steps round the circle
        const double a = i * 0.15 / 20;
        all.emplace_back(20 * std::cos(a), 20 * std::sin(a));
        tracks.append(QStringLiteral("circle"), Tracks::Fix{1000 + i * 0.1, radians(41) + all.back().x() * metre,
                                                            radians(-8) + all.back().y() * metre / std::cos(radians(41)), 0, 0, 0, 0, 0});
    }
    const auto *circle = tracks.track(QStringLiteral("circle"));
    EXPECT_LT(circle->fixes.size(), 120u) << "not 839 fixes";
    std::vector<Eigen::Vector2d> kept; // the trail, then the vehicle where it is now (the map draws it there)
    for (const auto &f : circle->fixes)
        kept.emplace_back((f.lat - radians(41)) / metre, (f.lon - radians(-8)) * std::cos(radians(41)) / metre);
    kept.emplace_back((circle->latest.lat - radians(41)) / metre, (circle->latest.lon - radians(-8)) * std::cos(radians(41)) / metre);
    double worst = 0;
    for (const Eigen::Vector2d &p : all) {
        double nearest = 1e9;
        for (std::size_t k = 0; k + 1 < kept.size(); ++k) {
            const Eigen::Vector2d d = kept[k + 1] - kept[k];
            const double along = std::clamp((p - kept[k]).dot(d) / std::max(1e-12, d.squaredNorm()), 0.0, 1.0);
            nearest = std::min(nearest, (p - kept[k] - along * d).norm());
        }
        worst = std::max(worst, nearest);
    }
    EXPECT_LT(worst, 0.21) << "the circle's shape kept";
}

TEST_F(TrackRecording, HomeIsSetAndBadHomesAreRefused)
{
    tracks.setHome({{QStringLiteral("lat"), 41.5}, {QStringLiteral("lon"), -8.5}});
    EXPECT_TRUE(tracks.home().value(QStringLiteral("valid")).toBool());
    EXPECT_EQ(tracks.home().value(QStringLiteral("lat")).toDouble(), 41.5);
    tracks.setHome({{QStringLiteral("lat"), 123}, {QStringLiteral("lon"), 0}});
    EXPECT_EQ(tracks.home().value(QStringLiteral("lat")).toDouble(), 41.5) << "refused";
    // A home set by hand is not replaced by the first vehicle.
    tree.ingest(state(0x1f, 40, -8, 0, 0, 0));
    model.sync();
    EXPECT_EQ(tracks.home().value(QStringLiteral("lat")).toDouble(), 41.5);
}

TEST_F(TrackRecording, AListModelOfSystemsWhereAMoveChangesOnlyItsRow)
{
    QAbstractItemModelTester tester(&tracks, QAbstractItemModelTester::FailureReportingMode::Fatal);
    QSignalSpy inserted(&tracks, &QAbstractItemModel::rowsInserted);
    QSignalSpy changed(&tracks, &QAbstractItemModel::dataChanged);
    tree.ingest(state(0x1f, 41.14, -8.61, 0, 0, 2, 0.5));
    tree.ingest(state(0x20, 41.14, -8.61, 100, 0, 0));
    model.sync();
    ASSERT_EQ(tracks.rowCount(), 2);
    EXPECT_EQ(inserted.count(), 2) << "a row per new system, nothing rebuilt";
    const QModelIndex first = tracks.index(0);
    EXPECT_EQ(first.data(Tracks::SystemRole).toString(), QStringLiteral("0x001f"));
    EXPECT_TRUE(first.data(Tracks::ValidRole).toBool());
    EXPECT_NEAR(first.data(Tracks::DepthRole).toDouble(), 2, 1e-6);
    EXPECT_NEAR(first.data(Tracks::HeadingRole).toDouble(), degrees(0.5), 1e-4);
    EXPECT_NEAR(tracks.index(1).data(Tracks::NorthRole).toDouble(), 100, 0.01) << "metres from home (the first reference)";

    changed.clear();
    tree.ingest(state(0x20, 41.14, -8.61, 150, 0, 0));
    model.sync();
    ASSERT_EQ(changed.count(), 1);
    EXPECT_EQ(changed[0][0].value<QModelIndex>().row(), 1) << "only the system that moved";
    EXPECT_EQ(changed[0][1].value<QModelIndex>().row(), 1);
    EXPECT_EQ(tracks.roleNames().value(Tracks::NorthRole), QByteArray("north"));
}

// 1,000 new systems in one frame froze the console for seconds: each brought
// a marker, a trail and a 3D model at once, and every binding on the list of
// systems read it again per system. Now a few join per frame, the list
// changes once per frame, and none is lost.
TEST_F(TrackRecording, AFloodOfNewSystemsJoinsAFewPerFrame)
{
    QSignalSpy systemsChanged(&tracks, &Tracks::systemsChanged);
    for (int i = 0; i < 100; ++i)
        tree.ingest(state(quint16(0x4000 + i), 41.0, -8.0, i, 0, 0));
    model.sync();
    EXPECT_GT(tracks.rowCount(), 0);
    EXPECT_LE(tracks.rowCount(), 10) << "a few per frame";
    EXPECT_EQ(systemsChanged.count(), 1);
    // The others join on the next frames, without new data.
    QTRY_COMPARE_WITH_TIMEOUT(tracks.systems().size(), 100, 5000);
    EXPECT_LE(systemsChanged.count(), 100 / 8 + 2);
    const auto *last = tracks.track(QStringLiteral("0x4063"));
    ASSERT_TRUE(last);
    EXPECT_EQ(last->fixes.size(), 1u);
}

// With 1,000 systems alive the console drew 1,000 markers, trails and 3D
// models a frame (half-second frames, +600 MB). Now at most maxDrawn have a
// row, and at most maxUnnamedDrawn of them were never named; named systems
// take them first, so forged ids that came first cannot push the real vehicle
// off the map, and the rest are counted.
TEST_F(TrackRecording, AtMostMaxDrawnSystemsAreDrawnNamedOnesFirst)
{
    QAbstractItemModelTester tester(&tracks, QAbstractItemModelTester::FailureReportingMode::Fatal);
    tracks.setMaxDrawn(20);
    tracks.setMaxUnnamedDrawn(20);
    for (int i = 0; i < 30; ++i) {
        tree.ingest(state(quint16(0x4000 + i), 41.0, -8.0, i, 0, 0));
        model.sync();
    }
    QTRY_COMPARE_WITH_TIMEOUT(tracks.systems().size(), 30, 5000);
    EXPECT_EQ(tracks.rowCount(), 20);
    EXPECT_EQ(tracks.hidden(), 10);
    EXPECT_EQ(tracks.index(0).data(Tracks::SystemRole).toString(), QStringLiteral("0x4000")) << "first heard first";

    // A vehicle that announced itself comes after them, and is drawn.
    tree.setSystemName(0x1f, QStringLiteral("lauv-xplore-1"));
    tree.ingest(state(0x1f, 41.0, -8.0, 500, 0, 3));
    model.sync();
    EXPECT_EQ(tracks.rowCount(), 20);
    EXPECT_EQ(tracks.hidden(), 11);
    QStringList drawn;
    for (int row = 0; row < tracks.rowCount(); ++row)
        drawn << tracks.index(row).data(Tracks::SystemRole).toString();
    EXPECT_TRUE(drawn.contains(QStringLiteral("lauv-xplore-1"))) << drawn.join(u' ').toStdString();
    EXPECT_FALSE(drawn.contains(QStringLiteral("0x4013"))) << "the last unnamed one drawn gave its row";

    tracks.setMaxDrawn(100);
    EXPECT_EQ(tracks.rowCount(), 21) << "20 unnamed at most";
    tracks.setMaxUnnamedDrawn(5);
    EXPECT_EQ(tracks.rowCount(), 6);
    EXPECT_EQ(tracks.hidden(), 25);
    EXPECT_EQ(tracks.index(0).data(Tracks::SystemRole).toString(), QStringLiteral("0x4000"));
}

// Systems never named that fall silent are forgotten (their rows and
// trails too); a named vehicle keeps its last position however long silent.
TEST_F(TrackRecording, SilentUnnamedSystemsAreForgottenNamedOnesStay)
{
    QAbstractItemModelTester tester(&tracks, QAbstractItemModelTester::FailureReportingMode::Fatal);
    tracks.setForgetAfter(60);
    tree.setSystemName(0x1f, QStringLiteral("lauv-xplore-1"));
    tree.ingest(state(0x1f, 41.0, -8.0, 0, 0, 3));
    tree.ingest(state(0x4000, 41.0, -8.0, 10, 0, 0));
    tree.ingest(state(0x4001, 41.0, -8.0, 20, 0, 0));
    model.sync();
    ASSERT_EQ(tracks.rowCount(), 3);

    clock.advance(30'000);
    tree.ingest(state(0x4001, 41.0, -8.0, 25, 0, 0)); // still talking
    model.sync();
    clock.advance(31'000);
    tracks.forgetSilent();
    EXPECT_EQ(tracks.systems(), (QStringList{QStringLiteral("lauv-xplore-1"), QStringLiteral("0x4001")}));
    EXPECT_EQ(tracks.rowCount(), 2);
    EXPECT_EQ(tracks.track(QStringLiteral("0x4000")), nullptr);

    clock.advance(3600'000);
    tracks.forgetSilent();
    EXPECT_EQ(tracks.systems(), QStringList{QStringLiteral("lauv-xplore-1")});
    EXPECT_EQ(tracks.latest(QStringLiteral("lauv-xplore-1")).value(QStringLiteral("depth")).toDouble(), 3);

    // One that comes back starts a new track.
    tree.ingest(state(0x4000, 41.0, -8.0, 10, 0, 0));
    model.sync();
    EXPECT_EQ(tracks.rowCount(), 2);
    EXPECT_EQ(tracks.count(QStringLiteral("0x4000")), 1);
}

// A system the console forgets (silent past the configured time) leaves the
// map too, named or not; heard again, it starts a new track.
TEST_F(TrackRecording, SystemsTheTreeForgetsLeaveTheMap)
{
    QAbstractItemModelTester tester(&tracks, QAbstractItemModelTester::FailureReportingMode::Fatal);
    tree.setSystemName(0x1f, QStringLiteral("lauv-xplore-1"));
    tree.ingest(state(0x1f, 41.0, -8.0, 0, 0, 3));
    tree.ingest(state(0x20, 41.0, -8.0, 50, 0, 0));
    model.sync();
    ASSERT_EQ(tracks.rowCount(), 2);
    tree.ingest(state(0x1f, 41.0, -8.0, 100, 0, 3)); // pending when it is forgotten
    tree.forget(0x1f);
    model.sync();
    EXPECT_EQ(tracks.systems(), QStringList{QStringLiteral("0x0020")});
    EXPECT_EQ(tracks.rowCount(), 1);
    tree.ingest(state(0x1f, 41.0, -8.0, 200, 0, 3));
    model.sync();
    EXPECT_EQ(tracks.count(QStringLiteral("lauv-xplore-1")), 1) << "a new track";
}
