#include "Schemas.h"
#include "alarms/AlarmGraph.h"
#include "qmlmodels/AlarmListModel.h"
#include "alarms/HealthMonitor.h"

#include "messages/Schema.h"

#include <QAbstractItemModelTester>
#include <QDir>
#include <QSignalSpy>

#include <gtest/gtest.h>

using namespace neptus;
using namespace neptus::alarms;

namespace {

msg::Message entityState(quint16 src, quint8 ent, int state, const char *description)
{
    msg::Message m(neptus::test::shippedSchema()->byAbbrev(u"EntityState"));
    m.header.src = src;
    m.header.srcEnt = ent;
    m.setInteger(m.def()->indexOf(u"state"), state);
    m.setBytes(m.def()->indexOf(u"description"), description);
    return m;
}

} // namespace

TEST(AlarmGraph, NodesShowTheHighestLevelBeneathThem)
{
    AlarmGraph graph;
    const auto battery = graph.ensure(QStringLiteral("systems/lauv/Batteries"));
    const auto navigation = graph.ensure(QStringLiteral("systems/lauv/Navigation"));
    const auto lauv = graph.find(QStringLiteral("systems/lauv"));
    const auto systems = graph.find(QStringLiteral("systems"));
    ASSERT_NE(lauv, AlarmGraph::noNode);
    EXPECT_EQ(graph.path(battery), QStringLiteral("systems/lauv/Batteries"));

    graph.raise(battery, Normal);
    graph.raise(navigation, Normal);
    EXPECT_EQ(graph.rootLevel(), Normal);
    graph.raise(battery, Warning, QStringLiteral("battery at 20 %"));
    EXPECT_EQ(graph.level(lauv), Warning);
    EXPECT_EQ(graph.level(systems), Warning);
    EXPECT_EQ(graph.rootLevel(), Warning);
    EXPECT_EQ(graph.ownLevel(lauv), Unknown);
    graph.raise(navigation, Failure, QStringLiteral("no fix"));
    EXPECT_EQ(graph.rootLevel(), Failure);
    graph.raise(navigation, Normal);
    EXPECT_EQ(graph.rootLevel(), Warning) << "back to the highest remaining";
    graph.raise(lauv, Error, QStringLiteral("communications lost"));
    EXPECT_EQ(graph.rootLevel(), Error);
    graph.clear(lauv);
    graph.clear(battery);
    EXPECT_EQ(graph.rootLevel(), Normal);
}

TEST(AlarmGraph, AcknowledgeAndAnnounceOnce)
{
    ManualClock clock(QDateTime::fromMSecsSinceEpoch(1000, QTimeZone::UTC));
    AlarmGraph graph(&clock);
    std::vector<AlarmGraph::Alarm> announced;
    graph.setAnnouncer([&](const AlarmGraph::Alarm &a) { announced.push_back(a); });
    const auto depth = graph.ensure(QStringLiteral("scripts/depth"));
    const auto power = graph.ensure(QStringLiteral("systems/lauv/Power"));

    graph.raise(depth, Warning, QStringLiteral("deep"));
    EXPECT_TRUE(announced.empty()) << "warnings are listed, not announced";
    clock.advance(500);
    graph.raise(depth, Error, QStringLiteral("too deep"));
    ASSERT_EQ(announced.size(), 1u);
    EXPECT_EQ(announced[0].origin, QStringLiteral("scripts/depth"));
    EXPECT_EQ(announced[0].level, Error);
    for (int i = 0; i < 10; ++i)
        graph.raise(depth, Error, QStringLiteral("too deep: %1 m").arg(20 + i));
    graph.raise(depth, Failure, QStringLiteral("way too deep"));
    EXPECT_EQ(announced.size(), 1u) << "staying at Error or worse is not announced again";

    graph.raise(power, Warning, QStringLiteral("low"));
    auto alarms = graph.activeAlarms();
    ASSERT_EQ(alarms.size(), 2u);
    EXPECT_EQ(alarms[0].node, depth) << "in the order raised";
    EXPECT_EQ(alarms[0].sinceMs, 1500);
    graph.acknowledge(depth);
    EXPECT_TRUE(graph.activeAlarms()[0].acknowledged);
    graph.raise(power, Error, QStringLiteral("critical"));
    EXPECT_EQ(announced.size(), 2u);
    graph.acknowledgeAll();
    for (const auto &a : graph.activeAlarms())
        EXPECT_TRUE(a.acknowledged);
    graph.raise(power, Failure, QStringLiteral("dead"));
    EXPECT_FALSE(graph.activeAlarms()[1].acknowledged) << "worse news needs a new acknowledgement";
    graph.clear(depth);
    graph.raise(depth, Error, QStringLiteral("again"));
    EXPECT_EQ(announced.size(), 3u) << "a new rise is announced";
}

TEST(AlarmGraph, NoticesAreListedUntilAcknowledged)
{
    AlarmGraph graph;
    const auto plan = graph.ensure(QStringLiteral("systems/lauv/plan"));
    const auto power = graph.ensure(QStringLiteral("systems/lauv/Power"));
    graph.raise(plan, Info, QStringLiteral("waiting"));
    EXPECT_TRUE(graph.activeAlarms().empty()) << "an Info level alone is not listed";
    graph.raise(power, Warning, QStringLiteral("low"));
    graph.notify(plan, QStringLiteral("plan survey completed"));
    EXPECT_EQ(graph.rootLevel(), Warning) << "a notice raises nothing";
    auto listed = graph.activeAlarms();
    ASSERT_EQ(listed.size(), 2u);
    EXPECT_EQ(listed[1].node, plan);
    EXPECT_EQ(listed[1].level, Info);
    EXPECT_EQ(listed[1].message, QStringLiteral("plan survey completed"));
    graph.notify(plan, QStringLiteral("plan survey completed"));
    EXPECT_EQ(graph.activeAlarms().size(), 2u) << "the same node, one line";
    graph.acknowledgeAll();
    listed = graph.activeAlarms();
    ASSERT_EQ(listed.size(), 1u) << "an acknowledged notice goes; an acknowledged alarm stays while it lasts";
    EXPECT_EQ(listed[0].node, power);
    graph.notify(plan, QStringLiteral("plan survey stopped"));
    graph.raise(plan, Warning, QStringLiteral("plan survey failed: aborted"));
    listed = graph.activeAlarms();
    ASSERT_EQ(listed.size(), 2u);
    EXPECT_EQ(listed[1].level, Warning);
    graph.raise(plan, Normal);
    graph.notify(plan, QStringLiteral("plan survey completed"));
    graph.forget(graph.find(QStringLiteral("systems/lauv")));
    EXPECT_TRUE(graph.activeAlarms().empty()) << "a forgotten system leaves no notice behind";
}

TEST(HealthMonitor, EntityStatesBecomeEntityAlarms)
{
    tree::VariableTree tree;
    tree.setSystemName(0x1f, QStringLiteral("lauv"));
    AlarmGraph graph;
    HealthMonitor health(graph, tree);
    msg::Message list(neptus::test::shippedSchema()->byAbbrev(u"EntityList"));
    list.header.src = 0x1f;
    list.setBytes(list.def()->indexOf(u"list"), "Batteries=12;Navigation=44");
    tree.ingest(list);

    auto feed = [&](const msg::Message &m) {
        tree.ingest(m);
        health.observe(m);
    };
    feed(entityState(0x1f, 12, 2, "battery low"));
    const auto node = graph.find(QStringLiteral("systems/lauv/Batteries"));
    ASSERT_NE(node, AlarmGraph::noNode);
    EXPECT_EQ(graph.ownLevel(node), Warning);
    EXPECT_EQ(graph.message(node), QStringLiteral("battery low"));
    feed(entityState(0x1f, 44, 4, "no fix"));
    EXPECT_EQ(graph.level(graph.find(QStringLiteral("systems/lauv"))), Failure);
    feed(entityState(0x1f, 44, 1, "active"));
    feed(entityState(0x1f, 12, 0, "booting"));
    EXPECT_EQ(graph.ownLevel(node), Info);
    EXPECT_EQ(graph.rootLevel(), Info);
    EXPECT_EQ(HealthMonitor::levelOfEntityState(3), Error);
}

TEST(HealthMonitor, CommunicationsLossIsRaisedAndCleared)
{
    ManualClock clock(QDateTime::fromMSecsSinceEpoch(0, QTimeZone::UTC));
    tree::VariableTree tree(&clock);
    tree.setSystemName(0x1f, QStringLiteral("lauv"));
    AlarmGraph graph(&clock);
    HealthMonitor health(graph, tree, &clock);
    msg::Message beat(neptus::test::shippedSchema()->byAbbrev(u"Heartbeat"));
    beat.header.src = 0x1f;
    for (int i = 0; i < 20; ++i) { // a steady 1 Hz heartbeat
        health.observe(beat);
        clock.advance(1000);
        health.check();
    }
    const auto lauv = graph.find(QStringLiteral("systems/lauv"));
    EXPECT_EQ(graph.ownLevel(lauv), Unknown) << "no alarm while it talks";
    clock.advance(1500); // 2.5 s of silence: within cadence + 2 s
    health.check();
    EXPECT_LT(graph.ownLevel(lauv), Warning);
    clock.advance(1000); // 3.5 s
    health.check();
    EXPECT_EQ(graph.ownLevel(lauv), Warning);
    EXPECT_TRUE(graph.message(lauv).startsWith(QStringLiteral("communications lost"))) << graph.message(lauv).toStdString();
    EXPECT_EQ(graph.message(lauv), QStringLiteral("communications lost: nothing heard for 3 s"));
    clock.advance(7000); // 10.5 s: more than three times the limit
    health.check();
    EXPECT_EQ(graph.ownLevel(lauv), Error);
    EXPECT_EQ(graph.message(lauv), QStringLiteral("communications lost: nothing heard for 10 s"))
        << "the text follows the silence";
    clock.advance(125000);
    health.check();
    EXPECT_EQ(graph.message(lauv), QStringLiteral("communications lost: nothing heard for 2 min 15 s"));
    health.observe(beat);
    EXPECT_EQ(graph.ownLevel(lauv), Normal) << "cleared when traffic returns";
    EXPECT_LT(graph.rootLevel(), Warning);
}

// A stock DUNE announces itself (every 10 s) about 5 s before it streams to
// a console it has just heard of (its UDP transport activates a new contact
// only at its next 5 s refresh): that wait is no silence, at discovery nor
// after the vehicle restarts. A vehicle that only ever announces is said to.
TEST(HealthMonitor, NoCommunicationsAlarmWhileAVehicleAnnouncesBeforeItStreams)
{
    ManualClock clock(QDateTime::fromMSecsSinceEpoch(0, QTimeZone::UTC));
    tree::VariableTree tree(&clock);
    tree.setSystemName(0xd1, QStringLiteral("lauv-simulator-1"));
    AlarmGraph graph(&clock);
    HealthMonitor health(graph, tree, &clock);
    const auto schema = neptus::test::shippedSchema();
    msg::Message announce(schema->byAbbrev(u"Announce")), state(schema->byAbbrev(u"EstimatedState"));
    announce.header.src = state.header.src = 0xd1;
    announce.setInteger(announce.def()->indexOf(u"sys_type"), 2); // UUV
    Level worst = Normal;
    const auto during = [&](int ms, const std::function<void(int)> &each) {
        for (int t = 0; t < ms; t += 250) {
            each(t);
            clock.advance(250);
            health.check();
            const auto node = graph.find(QStringLiteral("systems/lauv-simulator-1"));
            if (node != AlarmGraph::noNode)
                worst = std::max(worst, graph.ownLevel(node));
        }
    };
    health.observe(announce);
    during(5000, [](int) {}); // announced, not streaming yet
    during(20000, [&](int t) {
        if (t % 500 == 0)
            health.observe(state); // DUNE's EstimatedState to consoles: 2 Hz
        if (t % 10000 == 0)
            health.observe(announce);
    });
    EXPECT_LT(worst, Warning) << "no 'communications lost' at discovery";

    during(8000, [](int) {}); // it restarts: a real silence
    const auto node = graph.find(QStringLiteral("systems/lauv-simulator-1"));
    EXPECT_EQ(graph.ownLevel(node), Error);
    health.observe(announce); // back, announcing; streaming again 5 s later
    EXPECT_LT(graph.ownLevel(node), Warning);
    worst = Normal;
    during(5000, [](int) {});
    during(5000, [&](int t) {
        if (t % 500 == 0)
            health.observe(state);
    });
    EXPECT_LT(worst, Warning) << "no alarm while it takes up its stream again";

    // Announcing and nothing else, for long: said, and cleared by its stream.
    tree.setSystemName(0xd2, QStringLiteral("lauv-mute"));
    msg::Message mute = announce;
    mute.header.src = 0xd2;
    const auto count = [&] { return graph.find(QStringLiteral("systems/lauv-mute")); };
    during(35000, [&](int t) {
        if (t % 10000 == 0)
            health.observe(mute);
    });
    EXPECT_EQ(graph.ownLevel(count()), Warning);
    EXPECT_TRUE(graph.message(count()).startsWith(QStringLiteral("heard only its Announce for 3"))) << graph.message(count()).toStdString();
    health.observe(mute); // another Announce does not clear it
    EXPECT_EQ(graph.ownLevel(count()), Warning);
    msg::Message muteState = state;
    muteState.header.src = 0xd2;
    health.observe(muteState);
    EXPECT_EQ(graph.ownLevel(count()), Normal);

    // A console (CCU) streams to nobody: its Announces alone are no problem.
    tree.setSystemName(0x4002, QStringLiteral("other-console"));
    msg::Message console = announce;
    console.header.src = 0x4002;
    console.setInteger(console.def()->indexOf(u"sys_type"), 0);
    worst = Normal;
    during(40000, [&](int t) {
        if (t % 10000 == 0)
            health.observe(console);
    });
    EXPECT_LT(graph.ownLevel(graph.find(QStringLiteral("systems/other-console"))), Warning);
}

TEST(HealthMonitor, EntityAlarmsAreRenamedWhenTheirLabelIsLearned)
{
    tree::VariableTree tree;
    tree.setSystemName(0x1f, QStringLiteral("lauv"));
    AlarmGraph graph;
    HealthMonitor health(graph, tree);
    const auto feed = [&](const msg::Message &m) {
        tree.ingest(m);
        health.observe(m);
    };
    feed(entityState(0x1f, 61, 3, "no fix"));
    const auto node = graph.find(QStringLiteral("systems/lauv/61"));
    ASSERT_NE(node, AlarmGraph::noNode);
    msg::Message list(neptus::test::shippedSchema()->byAbbrev(u"EntityList"));
    list.header.src = 0x1f;
    list.setBytes(list.def()->indexOf(u"list"), "Daemon=0;Navigation=61");
    feed(list);
    health.check(); // renames without waiting for the next EntityState
    EXPECT_EQ(graph.find(QStringLiteral("systems/lauv/Navigation")), node) << "renamed in place";
    EXPECT_EQ(graph.find(QStringLiteral("systems/lauv/61")), AlarmGraph::noNode);
    EXPECT_EQ(graph.ownLevel(node), Error) << "the level stays";
    feed(entityState(0x1f, 61, 1, "active"));
    EXPECT_EQ(graph.ownLevel(node), Normal);
}

TEST(AlarmListModel, WorstThenNewestFirstAndViewsKeepTheirRows)
{
    ManualClock clock(QDateTime::fromMSecsSinceEpoch(1000, QTimeZone::UTC));
    AlarmGraph graph(&clock);
    AlarmListModel model(&graph);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    const auto old = graph.ensure(QStringLiteral("systems/a/Old"));
    const auto recent = graph.ensure(QStringLiteral("systems/a/Recent"));
    const auto bad = graph.ensure(QStringLiteral("systems/b/Bad"));
    graph.raise(old, Warning, QStringLiteral("old"));
    clock.advance(1000);
    graph.raise(recent, Warning, QStringLiteral("recent"));
    model.refresh();
    const QPersistentModelIndex kept = model.index(1);
    EXPECT_EQ(kept.data(AlarmListModel::MessageRole).toString(), QStringLiteral("old")) << "newest first within a level";
    clock.advance(1000);
    graph.raise(bad, Failure, QStringLiteral("bad"));
    model.refresh();
    QStringList order;
    for (int row = 0; row < model.rowCount(); ++row)
        order << model.index(row).data(AlarmListModel::MessageRole).toString();
    EXPECT_EQ(order, (QStringList{QStringLiteral("bad"), QStringLiteral("recent"), QStringLiteral("old")}));
    EXPECT_EQ(kept.row(), 2) << "a view's row follows its alarm";
    clock.advance(1000);
    graph.raise(old, Error, QStringLiteral("worse"));
    model.refresh();
    EXPECT_EQ(model.index(1).data(AlarmListModel::MessageRole).toString(), QStringLiteral("worse"));
    EXPECT_EQ(kept.row(), 1);
}

TEST(AlarmListModel, ListsAlarmsAndTheRootLevel)
{
    AlarmGraph graph;
    AlarmListModel model(&graph);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    QSignalSpy announced(&model, &AlarmListModel::announced);
    const auto a = graph.ensure(QStringLiteral("scripts/a"));
    const auto b = graph.ensure(QStringLiteral("systems/x/y"));
    graph.raise(a, Warning, QStringLiteral("first"));
    graph.raise(b, Error, QStringLiteral("second"));
    model.refresh();
    ASSERT_EQ(model.rowCount(), 2);
    EXPECT_EQ(model.rootLevel(), Error);
    EXPECT_EQ(model.rootLevelName(), QStringLiteral("Error"));
    EXPECT_EQ(model.data(model.index(0), AlarmListModel::OriginRole).toString(), QStringLiteral("systems/x/y")) << "worst first";
    EXPECT_EQ(model.data(model.index(0), AlarmListModel::LevelNameRole).toString(), QStringLiteral("Error"));
    EXPECT_EQ(model.data(model.index(1), AlarmListModel::OriginRole).toString(), QStringLiteral("scripts/a"));
    EXPECT_EQ(model.unacknowledged(), 2);
    model.acknowledge(0);
    EXPECT_TRUE(model.data(model.index(0), AlarmListModel::AcknowledgedRole).toBool());
    EXPECT_EQ(model.unacknowledged(), 1);
    graph.clear(a);
    model.refresh();
    ASSERT_EQ(model.rowCount(), 1);
    EXPECT_EQ(model.data(model.index(0), AlarmListModel::MessageRole).toString(), QStringLiteral("second"));
    QCoreApplication::processEvents();
    EXPECT_EQ(announced.count(), 1);
    model.acknowledgeAll();
    EXPECT_EQ(model.unacknowledged(), 0);
}
