#include "Schemas.h"
#include "qmlmodels/Variable.h"
#include "qmlmodels/VariableTreeModel.h"

#include "messages/Schema.h"

#include <QAbstractItemModelTester>
#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>

#include <gtest/gtest.h>

using namespace neptus;
using namespace neptus::tree;
using msg::Message;

namespace {

Message state(quint16 src, double depth)
{
    Message m(neptus::test::shippedSchema()->byAbbrev(u"EstimatedState"));
    m.header.src = src;
    m.setNumber(m.def()->indexOf(u"depth"), depth);
    return m;
}

Message heartbeat(quint16 src)
{
    Message m(neptus::test::shippedSchema()->byAbbrev(u"Heartbeat"));
    m.header.src = src;
    return m;
}

struct Fixture : ::testing::Test
{
    ManualClock clock{QDateTime::fromMSecsSinceEpoch(1'000'000, QTimeZone::UTC)};
    VariableTree tree{&clock};
    VariableTreeModel model{&tree};
    QAbstractItemModelTester tester{&model, QAbstractItemModelTester::FailureReportingMode::Fatal};
};

} // namespace

TEST_F(Fixture, RowsAppearAtTheNextFrame)
{
    tree.setSystemName(0x1f, QStringLiteral("lauv"));
    tree.ingest(state(0x1f, 3));
    EXPECT_EQ(model.rowCount(), 0) << "views learn of new rows at the frame, not before";
    QSignalSpy inserted(&model, &QAbstractItemModel::rowsInserted);
    model.sync();
    EXPECT_EQ(model.rowCount(), 1);
    EXPECT_EQ(inserted.count(), 3) << "system, message, and the 20 fields as one run";
    const QModelIndex system = model.index(0, 0);
    EXPECT_EQ(model.data(system).toString(), QStringLiteral("lauv"));
    const QModelIndex message = model.index(0, 0, system);
    EXPECT_EQ(model.data(message, VariableTreeModel::NameRole).toString(), QStringLiteral("EstimatedState"));
    EXPECT_EQ(model.rowCount(message), 20);
    const QModelIndex depth = model.indexOfPath(QStringLiteral("lauv/EstimatedState/depth"));
    ASSERT_TRUE(depth.isValid());
    EXPECT_EQ(model.data(depth, VariableTreeModel::ValueRole).toDouble(), 3.0);
    EXPECT_EQ(model.data(depth.siblingAtColumn(VariableTreeModel::ValueColumn)).toString(), QStringLiteral("3"));
    EXPECT_EQ(model.data(depth.siblingAtColumn(VariableTreeModel::UnitColumn)).toString(), QStringLiteral("m"));
    EXPECT_EQ(model.parent(depth), message);
    EXPECT_EQ(model.children(QStringLiteral("lauv")), QStringList{QStringLiteral("EstimatedState")});
}

TEST_F(Fixture, ManyUpdatesInOneFrameAreOneNotification)
{
    tree.ingest(state(0x1f, 0));
    model.sync();
    const QModelIndex depth = model.indexOfPath(QStringLiteral("0x001f/EstimatedState/depth"));
    QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
    for (int i = 1; i <= 1000; ++i)
        tree.ingest(state(0x1f, i));
    model.sync();
    int covering = 0;
    for (const auto &signal : changed) {
        const auto topLeft = signal[0].value<QModelIndex>();
        const auto bottomRight = signal[1].value<QModelIndex>();
        if (topLeft.parent() == depth.parent() && topLeft.row() <= depth.row() && bottomRight.row() >= depth.row())
            ++covering;
    }
    EXPECT_EQ(covering, 1);
    EXPECT_LE(changed.count(), 3) << "the 20 fields are one range, plus the message branch row";
    EXPECT_EQ(model.data(depth, VariableTreeModel::ValueRole).toDouble(), 1000.0);
    changed.clear();
    model.sync();
    EXPECT_EQ(changed.count(), 0) << "nothing new, nothing said";
}

TEST_F(Fixture, ValuesGoStaleWithoutUpdates)
{
    model.setStaleAfter(2.0);
    tree.ingest(state(0x1f, 1));
    model.sync();
    const QModelIndex depth = model.indexOfPath(QStringLiteral("0x001f/EstimatedState/depth"));
    EXPECT_FALSE(model.data(depth, VariableTreeModel::StaleRole).toBool());
    clock.advance(1500);
    EXPECT_FALSE(model.data(depth, VariableTreeModel::StaleRole).toBool());
    EXPECT_DOUBLE_EQ(model.data(depth, VariableTreeModel::AgeRole).toDouble(), 1.5);
    clock.advance(1000);
    EXPECT_TRUE(model.data(depth, VariableTreeModel::StaleRole).toBool());
    tree.ingest(state(0x1f, 2));
    model.sync();
    EXPECT_FALSE(model.data(depth, VariableTreeModel::StaleRole).toBool());
}

TEST_F(Fixture, SystemsAreAPropertyThatSaysWhenItChanges)
{
    QSignalSpy systems(&model, &VariableTreeModel::systemsChanged);
    tree.ingest(state(0x1f, 1));
    model.sync();
    EXPECT_EQ(systems.count(), 1);
    EXPECT_EQ(model.systems(), QStringList{QStringLiteral("0x001f")});
    tree.ingest(state(0x1f, 2)); // values only
    model.sync();
    EXPECT_EQ(systems.count(), 1);
    Message announce(neptus::test::shippedSchema()->byAbbrev(u"Announce"));
    announce.header.src = 0x1f;
    announce.setBytes(announce.def()->indexOf(u"sys_name"), "lauv-named");
    tree.ingest(announce); // renamed by its Announce
    model.sync();
    EXPECT_EQ(systems.count(), 2);
    EXPECT_EQ(model.systems(), QStringList{QStringLiteral("lauv-named")});
}

TEST_F(Fixture, AVariableSaysWhetherItsPathIsAValue)
{
    Variable value, branch;
    value.setTree(&model);
    branch.setTree(&model);
    value.setPath(QStringLiteral("0x001f/EstimatedState/depth"));
    branch.setPath(QStringLiteral("0x001f/EstimatedState"));
    EXPECT_FALSE(value.isField()) << "nothing there yet";
    tree.ingest(state(0x1f, 1));
    model.sync();
    EXPECT_TRUE(value.isField());
    EXPECT_FALSE(branch.isField());
}

TEST_F(Fixture, AVariableOfAnEntityFollowsItWhenASecondEntityAppears)
{
    tree.setSystemName(0x1f, QStringLiteral("lauv"));
    Variable motor;
    motor.setTree(&model);
    motor.setPath(QStringLiteral("lauv/EstimatedState@2/depth"));
    Message m = state(0x1f, 4);
    m.header.srcEnt = 2;
    tree.ingest(m);
    model.sync();
    EXPECT_DOUBLE_EQ(motor.value().toDouble(), 4) << "one entity: its path finds the shared row";

    m.header.srcEnt = 3;
    m.setNumber(m.def()->indexOf(u"depth"), 9);
    tree.ingest(m); // entity 3 joins: rows of their own, the shared row is the latest of any
    model.sync();
    EXPECT_DOUBLE_EQ(motor.value().toDouble(), 4) << "still entity 2's value, not the latest of any";
    EXPECT_EQ(motor.node(), tree.find(u"lauv/EstimatedState@2/depth"));
}

TEST_F(Fixture, VariablesFollowPathsBeforeTheyExistAndAcrossRenames)
{
    Variable depth;
    depth.setTree(&model);
    depth.setPath(QStringLiteral("lauv/EstimatedState/depth"));
    EXPECT_FALSE(depth.present());
    EXPECT_TRUE(depth.stale());
    QSignalSpy changed(&depth, &Variable::changed);

    tree.ingest(state(0x1f, 4)); // not yet named: "0x001f/..."
    model.sync();
    EXPECT_FALSE(depth.present());

    Message announce(neptus::test::shippedSchema()->byAbbrev(u"Announce"));
    announce.header.src = 0x1f;
    announce.setBytes(announce.def()->indexOf(u"sys_name"), "lauv");
    tree.ingest(announce);
    model.sync();
    EXPECT_TRUE(depth.present());
    EXPECT_DOUBLE_EQ(depth.value().toDouble(), 4);
    EXPECT_EQ(depth.unit(), QStringLiteral("m"));
    EXPECT_FALSE(depth.stale());

    changed.clear();
    for (int i = 0; i < 50; ++i)
        tree.ingest(state(0x1f, 10 + i));
    model.sync();
    EXPECT_EQ(changed.count(), 1);
    EXPECT_DOUBLE_EQ(depth.value().toDouble(), 59);

    changed.clear();
    tree.ingest(heartbeat(0x1f)); // another message of the same system
    model.sync();
    EXPECT_EQ(changed.count(), 0);

    model.setStaleAfter(1);
    clock.advance(1500);
    depth.refreshAge();
    EXPECT_TRUE(depth.stale());
    EXPECT_DOUBLE_EQ(depth.age(), 1.5);
}

TEST_F(Fixture, BranchListenersHearChangesBeneath)
{
    tree.setSystemName(0x1f, QStringLiteral("lauv"));
    tree.setSystemName(0x20, QStringLiteral("caravela"));
    int lauvCalls = 0, depthCalls = 0, caravelaCalls = 0;
    model.listen(QStringLiteral("lauv"), [&] { ++lauvCalls; });
    model.listen(QStringLiteral("lauv/EstimatedState/depth"), [&] { ++depthCalls; });
    const int id = model.listen(QStringLiteral("caravela"), [&] { ++caravelaCalls; });
    for (int i = 0; i < 10; ++i)
        tree.ingest(state(0x1f, i));
    model.sync();
    EXPECT_EQ(lauvCalls, 1);
    EXPECT_EQ(depthCalls, 1);
    EXPECT_EQ(caravelaCalls, 0);
    tree.ingest(heartbeat(0x1f));
    model.sync();
    EXPECT_EQ(lauvCalls, 2);
    EXPECT_EQ(depthCalls, 1) << "a heartbeat is not a depth";
    tree.ingest(state(0x20, 1));
    model.sync();
    EXPECT_EQ(caravelaCalls, 1);
    model.unlisten(id);
    tree.ingest(state(0x20, 2));
    model.sync();
    EXPECT_EQ(caravelaCalls, 1);
}

// Every second the model signalled a new age for every row of every branch:
// with 1,000 systems (or 400 forged ids with 254 entities each) that was
// most of a core. Views read only the rows they show, so only branches a
// view read from since the last tick are signalled.
TEST(VariableTreeModelAges, OnlyRowsAViewReadAreRefreshed)
{
    ManualClock clock{QDateTime::fromMSecsSinceEpoch(1'000'000, QTimeZone::UTC)};
    VariableTree tree{&clock};
    VariableTreeModel model{&tree};
    for (quint16 id = 1; id <= 1000; ++id)
        tree.ingest(state(id, id));
    model.sync();
    QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);

    // A view shows one system's EstimatedState: it reads those rows.
    const QModelIndex depth = model.indexOfPath(QStringLiteral("0x0001/EstimatedState/depth"));
    ASSERT_TRUE(depth.isValid());
    model.data(depth, VariableTreeModel::AgeRole);
    model.refreshAges();
    ASSERT_EQ(changed.count(), 2) << "the one branch shown (staleness, then ages)";
    EXPECT_EQ(changed[0][0].value<QModelIndex>().parent(), depth.parent());

    // The view reads again what it was told changed; one that stops reading
    // (scrolled away, closed) is dropped after the next tick.
    changed.clear();
    model.data(depth, VariableTreeModel::AgeRole);
    model.refreshAges();
    EXPECT_EQ(changed.count(), 2);
    changed.clear();
    model.refreshAges();
    EXPECT_EQ(changed.count(), 2) << "one tick of grace";
    changed.clear();
    model.refreshAges();
    EXPECT_EQ(changed.count(), 0);
    clock.advance(10'000);
    EXPECT_TRUE(model.data(depth, VariableTreeModel::StaleRole).toBool()) << "read again, it is up to date";
}

TEST_F(Fixture, AForgottenSystemsRowGoesAndViewsKeepAConsistentPicture)
{
    tree.setSystemName(0x1f, QStringLiteral("lauv"));
    tree.ingest(state(0x1f, 3));
    tree.ingest(state(0x22, 7));
    tree.ingest(state(0x33, 9));
    model.sync();
    ASSERT_EQ(model.rowCount(), 3);
    Variable depth;
    depth.setTree(&model);
    depth.setPath(QStringLiteral("0x0022/EstimatedState/depth"));
    EXPECT_EQ(depth.value().toDouble(), 7.0);
    const QPersistentModelIndex held = model.indexOfPath(QStringLiteral("0x0022/EstimatedState/depth"));
    ASSERT_TRUE(held.isValid());
    QSignalSpy systems(&model, &VariableTreeModel::systemsChanged);

    tree.forget(0x22);
    // Until the frame, views see the rows they were told of, whole.
    EXPECT_EQ(model.rowCount(), 3);
    EXPECT_EQ(model.data(model.index(1, 0)).toString(), QStringLiteral("0x0022"));
    EXPECT_EQ(model.data(model.index(2, 0)).toString(), QStringLiteral("0x0033"));
    EXPECT_FALSE(model.data(held, VariableTreeModel::PresentRole).toBool()) << "its values read as absent";

    QSignalSpy removed(&model, &QAbstractItemModel::rowsRemoved);
    model.sync();
    EXPECT_EQ(removed.count(), 1);
    EXPECT_EQ(systems.count(), 1);
    ASSERT_EQ(model.rowCount(), 2);
    EXPECT_EQ(model.data(model.index(0, 0)).toString(), QStringLiteral("lauv"));
    EXPECT_EQ(model.data(model.index(1, 0)).toString(), QStringLiteral("0x0033"));
    EXPECT_FALSE(held.isValid()) << "views' persistent indexes into it are dropped";
    EXPECT_EQ(model.indexOfPath(QStringLiteral("0x0033/EstimatedState/depth")).parent().parent().row(), 1);
    EXPECT_FALSE(depth.present()) << "a variable of it is absent, not left showing 7";

    // Heard again: a new row at the end, with the variable following it.
    tree.ingest(state(0x22, 5));
    tree.ingest(state(0x44, 1));
    model.sync();
    ASSERT_EQ(model.rowCount(), 4);
    EXPECT_EQ(model.data(model.index(2, 0)).toString(), QStringLiteral("0x0022"));
    EXPECT_EQ(model.data(model.index(3, 0)).toString(), QStringLiteral("0x0044"));
    EXPECT_EQ(model.data(model.indexOfPath(QStringLiteral("0x0022/EstimatedState/depth")), VariableTreeModel::ValueRole).toDouble(), 5.0);
    EXPECT_EQ(depth.value().toDouble(), 5.0);
    EXPECT_EQ(model.rowCount(model.indexOfPath(QStringLiteral("0x0022/EstimatedState"))), 20);
}

TEST_F(Fixture, IdsGivenToNewNodesStartWithoutChildren)
{
    // The same ids come back for other systems: the model must not think
    // the new nodes have the children the old ones had.
    for (int wave = 0; wave < 6; ++wave) {
        const quint16 id = quint16(0x100 + wave);
        tree.ingest(wave % 2 ? heartbeat(id) : state(id, wave));
        model.sync();
        ASSERT_EQ(model.rowCount(), 1);
        const QModelIndex message = model.index(0, 0, model.index(0, 0));
        EXPECT_EQ(model.rowCount(message), wave % 2 ? 0 : 20) << "wave " << wave;
        tree.forget(id);
        model.sync();
        EXPECT_EQ(model.rowCount(), 0);
    }
}

TEST_F(Fixture, ManyForgottenSystemsGoInRunsOfRows)
{
    for (quint16 id = 0x100; id < 0x100 + 60; ++id)
        tree.ingest(state(id, 1));
    model.sync();
    ASSERT_EQ(model.rowCount(), 60);
    for (quint16 id = 0x100; id < 0x100 + 60; ++id)
        if (id < 0x100 + 20 || id % 3 == 0) // rows 0..19 and every third after
            tree.forget(id);
    QSignalSpy removed(&model, &QAbstractItemModel::rowsRemoved);
    model.sync();
    EXPECT_LT(removed.count(), 16) << "one removal per run of rows, not per system";
    QStringList names;
    for (int row = 0; row < model.rowCount(); ++row)
        names << model.data(model.index(row, 0)).toString();
    QStringList expected;
    for (quint16 id = 0x100 + 20; id < 0x100 + 60; ++id)
        if (id % 3 != 0)
            expected << msg::systemLabel(id);
    EXPECT_EQ(names, expected);
    EXPECT_EQ(model.indexOfPath(expected.last() + QStringLiteral("/EstimatedState")).parent().row(), int(expected.size()) - 1);
}

// A replay going back in time forgets every system, and the age timer may
// tick before the next frame's sync: it must not reach the forgotten nodes
// (it did: a crash in parent() on a node id that no longer existed).
TEST_F(Fixture, AgesRefreshedRightAfterASystemIsForgottenSeeOnlyWhatIsThere)
{
    tree.ingest(state(0x1f, 2.5));
    tree.ingest(heartbeat(0x1f));
    model.sync();
    const QModelIndex depth = model.indexOfPath(QStringLiteral("0x001f/EstimatedState/depth"));
    ASSERT_TRUE(depth.isValid());
    model.data(depth, VariableTreeModel::AgeRole); // a view shows it
    QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
    ASSERT_TRUE(tree.forget(0x1f));
    tree.ingest(state(0x20, 1.0)); // node ids of the forgotten may be given again
    model.refreshAges();
    for (const auto &signal : changed) {
        const QModelIndex from = signal[0].value<QModelIndex>();
        EXPECT_TRUE(from.isValid());
        EXPECT_NE(model.data(from.parent()).toString(), QStringLiteral("0x001f"));
    }
    EXPECT_EQ(model.rowCount(), 1);
    EXPECT_EQ(model.data(model.index(0, 0)).toString(), QStringLiteral("0x0020"));
}

// Vehicles streaming out of step would otherwise make a frame for each of
// their messages (issue #39): while values keep changing, the model shows
// them at most `displayRate` times a second, all together.
TEST(VariableTreeModelDisplayRate, ValuesThatKeepChangingAreShownAtTheDisplayRate)
{
    VariableTree tree;
    VariableTreeModel model(&tree);
    EXPECT_EQ(model.displayRate(), 10.0) << "the rate vehicles report their state at";
    QSignalSpy synced(&model, &VariableTreeModel::synced);
    int depth = 0;
    // Changes for at least `ms`; how long it really took (a busy machine runs over).
    const auto changeFor = [&](int ms) {
        QElapsedTimer clock;
        clock.start();
        while (clock.elapsed() < ms) {
            tree.ingest(state(0x1f, ++depth));
            tree.ingest(state(0x20, depth)); // a second vehicle, in the same turn
            QTest::qWait(5);
        }
        return clock.elapsed();
    };
    const qint64 took = changeFor(1000);
    // 10 a second, and the first at once (and one more where the loop overran its second).
    EXPECT_LE(synced.count(), 2 + took / 100) << took << " ms";
    EXPECT_GE(synced.count(), 3) << "still shown while they keep changing";

    model.setDisplayRate(0);
    synced.clear();
    changeFor(1000);
    EXPECT_GT(synced.count(), 11) << "0: every frame (16 ms)";
}

// While nobody touches the console (the program says when), values that keep
// changing are shown at the resting rate; the first change after a quiet
// spell still at once, and the display rate again as soon as it is used.
// The rate's turns are cut from the wall clock's seconds, and the ages are
// refreshed on whole seconds in the same turn: a frame for each turn, not an
// extra one a second (issue #39: each frame is battery on a tablet).
TEST(VariableTreeModelDisplayRate, ARestingConsoleShowsChangesAtTheRestingRateInTurnsOfTheWallClock)
{
    VariableTree tree;
    VariableTreeModel model(&tree);
    EXPECT_EQ(model.restingRate(), 3.0);
    EXPECT_FALSE(model.resting()) << "in use until the program says otherwise";
    EXPECT_EQ(model.shownRate(), 10.0);
    model.setRestingRate(4); // quarters of a second, below
    model.setResting(true);
    EXPECT_EQ(model.shownRate(), 4.0);

    std::vector<qint64> shownAt; // wall-clock ms of each sync that showed something
    QObject::connect(&model, &VariableTreeModel::synced, [&] { shownAt.push_back(QDateTime::currentMSecsSinceEpoch()); });
    int depth = 0;
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < 2500) {
        tree.ingest(state(0x1f, ++depth));
        QTest::qWait(5);
    }
    ASSERT_GE(shownAt.size(), 8u) << "still shown while they keep changing";
    EXPECT_LE(qint64(shownAt.size()), 2 + clock.elapsed() / 250) << "4 a second, the ages' refresh included";
    for (size_t i = 1; i < shownAt.size(); ++i)
        EXPECT_NE(shownAt[i] / 250, shownAt[i - 1] / 250) << "one sync a quarter of a wall-clock second, at " << shownAt[i];

    // In use again: the display rate at once.
    model.setResting(false);
    shownAt.clear();
    clock.restart();
    while (clock.elapsed() < 1000) {
        tree.ingest(state(0x1f, ++depth));
        QTest::qWait(5);
    }
    EXPECT_GE(shownAt.size(), 8u) << "10 a second while the console is used";

    // 0: the display rate even while resting.
    model.setRestingRate(0);
    model.setResting(true);
    EXPECT_EQ(model.shownRate(), 10.0);
}
