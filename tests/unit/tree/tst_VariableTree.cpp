#include "Schemas.h"
#include "tree/VariableTree.h"

#include "messages/Schema.h"

#include <QDir>
#include <QSet>

#include <thread>

#include <gtest/gtest.h>

using namespace neptus;
using namespace neptus::tree;
using msg::Message;

namespace {

Message make(const char *abbrev, quint16 src, quint8 ent = 0xFF)
{
    Message m(neptus::test::shippedSchema()->byAbbrev(QString::fromLatin1(abbrev)));
    m.header.src = src;
    m.header.srcEnt = ent;
    m.header.timestamp = 1700000000.0;
    return m;
}

Message state(quint16 src, double depth, quint8 ent = 0xFF)
{
    Message m = make("EstimatedState", src, ent);
    m.setNumber(m.def()->indexOf(u"depth"), depth);
    return m;
}

} // namespace

TEST(VariableTree, MessagesBecomeSystemMessageFieldPaths)
{
    ASSERT_TRUE(neptus::test::shippedSchema());
    ManualClock clock(QDateTime::fromMSecsSinceEpoch(5000, QTimeZone::UTC));
    VariableTree tree(&clock);
    tree.ingest(state(0x1f, 12.5));
    const NodeId depth = tree.find(u"0x001f/EstimatedState/depth");
    ASSERT_NE(depth, noNode);
    EXPECT_EQ(tree.path(depth), QStringLiteral("0x001f/EstimatedState/depth"));
    const auto s = tree.snapshot(depth);
    EXPECT_TRUE(s.present);
    EXPECT_DOUBLE_EQ(s.value.toDouble(), 12.5);
    EXPECT_EQ(s.unit, QStringLiteral("m"));
    EXPECT_EQ(s.receivedMs, 5000);
    EXPECT_EQ(s.timestamp, 1700000000.0);
    EXPECT_EQ(s.source, 0x1f);
    EXPECT_EQ(tree.kind(depth), VariableTree::Kind::Field);
    EXPECT_EQ(tree.childNames(u"0x001f/EstimatedState").size(), 20);
    EXPECT_EQ(tree.childNames(u"").value(0), QStringLiteral("0x001f"));

    // A new value replaces the old one at the same node.
    tree.ingest(state(0x1f, 30));
    EXPECT_EQ(tree.find(u"0x001f/EstimatedState/depth"), depth);
    EXPECT_DOUBLE_EQ(tree.snapshot(depth).value.toDouble(), 30);
}

// find() gives noNode for a path not heard yet; a caller that reads it at
// once (tst_PlanExecution's wait for a state did) got memory before the
// nodes (AddressSanitizer: heap-buffer-overflow). An id that names no node reads as absent.
TEST(VariableTree, AnIdThatNamesNoNodeReadsAsAbsent)
{
    ManualClock clock(QDateTime::fromMSecsSinceEpoch(5000, QTimeZone::UTC));
    VariableTree tree(&clock);
    tree.ingest(state(0x1f, 12.5));
    const NodeId missing = tree.find(u"0x001f/PlanControlState/state");
    ASSERT_EQ(missing, noNode);
    for (const NodeId id : {missing, NodeId(tree.nodeCapacity()), NodeId(1 << 30)}) {
        const auto s = tree.snapshot(id);
        EXPECT_FALSE(s.present);
        EXPECT_TRUE(s.text.isEmpty());
        EXPECT_EQ(tree.name(id), QString());
        EXPECT_EQ(tree.path(id), QString());
        EXPECT_EQ(tree.childCount(id), 0);
        EXPECT_EQ(tree.child(id, 0), noNode);
        EXPECT_EQ(tree.parent(id), noNode);
    }
}

TEST(VariableTree, SystemsAreNamedByAnnounceOrConfiguration)
{
    VariableTree tree;
    tree.setSystemName(0x20, QStringLiteral("caravela"));
    tree.ingest(state(0x1f, 1));
    tree.ingest(state(0x20, 2));
    EXPECT_NE(tree.find(u"caravela/EstimatedState/depth"), noNode);
    const NodeId before = tree.find(u"0x001f/EstimatedState/depth");
    Message announce = make("Announce", 0x1f);
    announce.setBytes(announce.def()->indexOf(u"sys_name"), "lauv-xplore-1");
    tree.ingest(announce);
    EXPECT_EQ(tree.find(u"0x001f/EstimatedState/depth"), noNode);
    EXPECT_EQ(tree.find(u"lauv-xplore-1/EstimatedState/depth"), before) << "renamed in place";
    EXPECT_EQ(tree.systemOf(before), 0x1f);
}

TEST(VariableTree, ATypeTheDefinitionsLackIsShownAndKept)
{
    // The packet that once crashed the console: ServoPosition (281) from a
    // DUNE vehicle whose type the loaded definitions do not have.
    ManualClock clock(QDateTime::fromMSecsSinceEpoch(1000, QTimeZone::UTC));
    VariableTree tree(&clock);
    const int consumer = tree.addConsumer();
    Message servo = Message::opaque(281, QByteArray("\x01\x00\x00\x80\x3f", 5));
    servo.header.src = 0x00D1;
    servo.header.srcEnt = 37;
    servo.header.timestamp = 1700000000.0;
    for (int i = 0; i < 30; ++i) {
        tree.ingest(servo);
        clock.advance(100);
    }
    const NodeId node = tree.find(u"0x00d1/Unknown(281)");
    ASSERT_NE(node, noNode);
    EXPECT_EQ(tree.kind(node), VariableTree::Kind::Message);
    EXPECT_EQ(tree.childCount(node), 0);
    const auto s = tree.snapshot(node);
    EXPECT_TRUE(s.present);
    EXPECT_EQ(s.text, QStringLiteral("unknown type 281, 5 bytes · 30 received · 10/s")) << s.text.toStdString();
    EXPECT_EQ(s.sourceEntity, 37);
    EXPECT_EQ(tree.find(u"0x00d1/Unknown(281)@37"), node) << "one entity, one row";
    EXPECT_FALSE(tree.takeChanges(consumer).isEmpty());
}

TEST(VariableTree, ATypeFromOneEntityHasOneRow)
{
    VariableTree tree;
    tree.setSystemName(0x1f, QStringLiteral("lauv"));
    Message rpm = make("Rpm", 0x1f, 2);
    rpm.setInteger(rpm.def()->indexOf(u"value"), 1200);
    tree.ingest(rpm);
    EXPECT_EQ(tree.childNames(u"lauv"), QStringList{QStringLiteral("Rpm")}) << "no second, identical row";
    const NodeId value = tree.find(u"lauv/Rpm/value");
    EXPECT_EQ(tree.find(u"lauv/Rpm@2/value"), value) << "the entity's path finds the one row";
    EXPECT_EQ(tree.snapshot(tree.find(u"lauv/Rpm")).text, QStringLiteral("from 2"));

    Message list = make("EntityList", 0x1f);
    list.setBytes(list.def()->indexOf(u"list"), "Motor=2;Propeller=3");
    tree.ingest(list);
    EXPECT_EQ(tree.find(u"lauv/Rpm@Motor/value"), value);
    EXPECT_EQ(tree.find(u"lauv/Rpm@2/value"), noNode) << "by its label once known";
    EXPECT_EQ(tree.find(u"lauv/Rpm@Propeller/value"), noNode);
    EXPECT_TRUE(tree.snapshot(tree.find(u"lauv/Rpm")).text.startsWith(QStringLiteral("from Motor")));
}

TEST(VariableTree, ASecondEntityGivesEachEntityItsOwnRow)
{
    VariableTree tree;
    tree.setSystemName(0x1f, QStringLiteral("lauv"));
    Message list = make("EntityList", 0x1f);
    list.setBytes(list.def()->indexOf(u"list"), "Motor=2;Propeller=3");
    tree.ingest(list);
    const int consumer = tree.addConsumer();
    Message rpm = make("Rpm", 0x1f, 2);
    rpm.setInteger(rpm.def()->indexOf(u"value"), 1200);
    tree.ingest(rpm);
    const NodeId shared = tree.find(u"lauv/Rpm@Motor/value");
    EXPECT_FALSE(tree.takeChanges(consumer).relinked);

    rpm.header.srcEnt = 3;
    rpm.setInteger(rpm.def()->indexOf(u"value"), 800);
    tree.ingest(rpm);
    EXPECT_TRUE(tree.takeChanges(consumer).relinked) << "paths with an entity must be looked up again";
    const NodeId motor = tree.find(u"lauv/Rpm@Motor/value");
    EXPECT_NE(motor, shared);
    EXPECT_EQ(tree.snapshot(motor).value.toInt(), 1200) << "the first entity keeps what it said";
    EXPECT_EQ(tree.snapshot(tree.find(u"lauv/Rpm@Propeller/value")).value.toInt(), 800);
    EXPECT_EQ(tree.snapshot(shared).value.toInt(), 800) << "Rpm is the latest from any";
    EXPECT_EQ(tree.snapshot(tree.find(u"lauv/Rpm")).text, QStringLiteral("latest of 2 entities"));
}

TEST(VariableTree, EntitiesGetTheirOwnBranchNamedByLabel)
{
    VariableTree tree;
    tree.setSystemName(0x1f, QStringLiteral("lauv"));
    tree.ingest(state(0x1f, 5, 44));
    tree.ingest(state(0x1f, 7, 45));
    EXPECT_DOUBLE_EQ(tree.snapshot(tree.find(u"lauv/EstimatedState/depth")).value.toDouble(), 7) << "latest of any entity";
    EXPECT_DOUBLE_EQ(tree.snapshot(tree.find(u"lauv/EstimatedState@44/depth")).value.toDouble(), 5);
    EXPECT_DOUBLE_EQ(tree.snapshot(tree.find(u"lauv/EstimatedState@45/depth")).value.toDouble(), 7);

    Message list = make("EntityList", 0x1f);
    list.setBytes(list.def()->indexOf(u"list"), "Daemon=0;Navigation=44;Simulator=45");
    tree.ingest(list);
    EXPECT_NE(tree.find(u"lauv/EstimatedState@Navigation/depth"), noNode);
    EXPECT_NE(tree.find(u"lauv/EstimatedState@Simulator/depth"), noNode);
    EXPECT_EQ(tree.find(u"lauv/EstimatedState@44"), noNode);

    tree.ingest(state(0x1f, 9, 0)); // entity 0: the plain path only
    EXPECT_EQ(tree.find(u"lauv/EstimatedState@Daemon"), noNode);
    EXPECT_DOUBLE_EQ(tree.snapshot(tree.find(u"lauv/EstimatedState/depth")).value.toDouble(), 9);
}

TEST(VariableTree, InlineMessagesAndListsAreBranches)
{
    VariableTree tree;
    tree.setSystemName(0x1f, QStringLiteral("lauv"));
    Message plan = make("PlanSpecification", 0x1f);
    std::vector<Message> maneuvers;
    for (int i = 0; i < 3; ++i) {
        Message go(neptus::test::shippedSchema()->byAbbrev(u"Goto"));
        go.setNumber(go.def()->indexOf(u"z"), 2.0 + i);
        Message pm(neptus::test::shippedSchema()->byAbbrev(u"PlanManeuver"));
        pm.setBytes(pm.def()->indexOf(u"maneuver_id"), "m" + QByteArray::number(i));
        pm.setInlineMessage(pm.def()->indexOf(u"data"), go);
        maneuvers.push_back(pm);
    }
    plan.setMessages(plan.def()->indexOf(u"maneuvers"), maneuvers);
    tree.ingest(plan);
    EXPECT_EQ(tree.snapshot(tree.find(u"lauv/PlanSpecification/maneuvers")).value.toInt(), 3);
    EXPECT_EQ(tree.snapshot(tree.find(u"lauv/PlanSpecification/maneuvers/1")).value.toString(), QStringLiteral("PlanManeuver"));
    EXPECT_EQ(tree.snapshot(tree.find(u"lauv/PlanSpecification/maneuvers/1/maneuver_id")).value.toString(), QStringLiteral("m1"));
    EXPECT_EQ(tree.snapshot(tree.find(u"lauv/PlanSpecification/maneuvers/2/data")).value.toString(), QStringLiteral("Goto"));
    EXPECT_DOUBLE_EQ(tree.snapshot(tree.find(u"lauv/PlanSpecification/maneuvers/2/data/z")).value.toDouble(), 4.0);

    // A shorter list leaves the extra items absent, not wrong.
    maneuvers.resize(1);
    plan.setMessages(plan.def()->indexOf(u"maneuvers"), maneuvers);
    tree.ingest(plan);
    EXPECT_TRUE(tree.snapshot(tree.find(u"lauv/PlanSpecification/maneuvers/0/data/z")).present);
    EXPECT_FALSE(tree.snapshot(tree.find(u"lauv/PlanSpecification/maneuvers/2/data/z")).present);
}

TEST(VariableTree, EnumerationsShowTheirNames)
{
    VariableTree tree;
    Message entity = make("EntityState", 0x1f, 12);
    entity.setInteger(entity.def()->indexOf(u"state"), 3);
    entity.setBytes(entity.def()->indexOf(u"description"), "battery low");
    tree.ingest(entity);
    const auto s = tree.snapshot(tree.find(u"0x001f/EntityState@12/state"));
    EXPECT_EQ(s.value.toInt(), 3);
    EXPECT_EQ(s.text, QStringLiteral("ERROR"));
    EXPECT_EQ(tree.snapshot(tree.find(u"0x001f/EntityState/description")).text, QStringLiteral("battery low"));
}

TEST(VariableTree, ConsumersGetCoalescedChanges)
{
    VariableTree tree;
    const int model = tree.addConsumer();
    const int scripts = tree.addConsumer();
    tree.ingest(state(0x1f, 1));
    auto first = tree.takeChanges(model);
    EXPECT_GT(first.newNodes.size(), 20u);
    const NodeId depth = tree.find(u"0x001f/EstimatedState/depth");
    EXPECT_EQ(std::count(first.changedNodes.begin(), first.changedNodes.end(), depth), 1);

    // 100 updates between two looks: one change per node.
    for (int i = 0; i < 100; ++i)
        tree.ingest(state(0x1f, i));
    auto second = tree.takeChanges(model);
    EXPECT_TRUE(second.newNodes.empty());
    EXPECT_EQ(std::count(second.changedNodes.begin(), second.changedNodes.end(), depth), 1);
    EXPECT_TRUE(tree.takeChanges(model).isEmpty());

    // The other consumer still sees everything since its own last look.
    auto other = tree.takeChanges(scripts);
    EXPECT_EQ(std::count(other.changedNodes.begin(), other.changedNodes.end(), depth), 1);
    EXPECT_FALSE(other.newNodes.empty());
}

TEST(VariableTree, WhatWasSentIsRecordedUnderTheOutputBranch)
{
    VariableTree tree;
    tree.setSystemName(0x1f, QStringLiteral("lauv"));
    EXPECT_EQ(tree.systemId(u"lauv"), 0x1f) << "configured names count";
    EXPECT_FALSE(tree.systemId(u"nobody"));
    Message abort(neptus::test::shippedSchema()->byAbbrev(u"Abort"));
    tree.recordSent(0x1f, abort);
    tree.recordSent(0x1f, abort);
    const NodeId node = tree.find(u"lauv/out/Abort");
    ASSERT_NE(node, noNode);
    EXPECT_TRUE(tree.snapshot(node).present);
    EXPECT_EQ(tree.snapshot(node).text, QStringLiteral("2 sent"));
    EXPECT_EQ(tree.kind(tree.find(u"lauv/out")), VariableTree::Kind::Inline);
}

TEST(VariableTree, IngestFromManyThreads)
{
    VariableTree tree;
    const int consumer = tree.addConsumer();
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t) {
        threads.emplace_back([&tree, t] {
            for (int i = 0; i < 2000; ++i)
                tree.ingest(state(static_cast<quint16>(0x10 + t), i));
        });
    }
    int looks = 0;
    while (looks < 50) {
        tree.takeChanges(consumer);
        ++looks;
    }
    for (auto &thread : threads)
        thread.join();
    for (int t = 0; t < 4; ++t) {
        const QString path = QStringLiteral("0x%1/EstimatedState/depth").arg(0x10 + t, 4, 16, QLatin1Char('0'));
        EXPECT_DOUBLE_EQ(tree.snapshot(tree.find(path)).value.toDouble(), 1999);
    }
}

TEST(VariableTree, AForgottenSystemGoesWholeAndComesBackWhenHeard)
{
    ManualClock clock(QDateTime::fromMSecsSinceEpoch(5000, QTimeZone::UTC));
    VariableTree tree(&clock);
    tree.setSystemName(0x1f, QStringLiteral("lauv"));
    tree.ingest(state(0x1f, 3));
    tree.ingest(state(0x22, 7));
    tree.recordSent(0x22, make("Abort", 0));
    const int both = tree.nodeCount();
    const NodeId oldDepth = tree.find(u"0x0022/EstimatedState/depth");
    ASSERT_NE(oldDepth, noNode);

    EXPECT_TRUE(tree.forget(0x22));
    EXPECT_FALSE(tree.forget(0x22)) << "nothing left to forget";
    EXPECT_EQ(tree.find(u"0x0022"), noNode);
    EXPECT_EQ(tree.find(u"0x0022/EstimatedState/depth"), noNode);
    EXPECT_EQ(tree.systemIds(), std::vector<quint16>{0x1f});
    EXPECT_EQ(tree.childNames(u""), QStringList{QStringLiteral("lauv")});
    EXPECT_EQ(tree.row(tree.find(u"lauv")), 0);
    EXPECT_LT(tree.nodeCount(), both) << "its nodes are gone";
    EXPECT_EQ(tree.nodeCount(), both - (1 + 1 + 20 + 1 + 1)) << "system, message and its 20 fields, out, Abort";
    EXPECT_FALSE(tree.snapshot(oldDepth).present) << "an id a consumer may still hold reads as absent";
    EXPECT_EQ(tree.systemOf(oldDepth), 0xFFFF);
    EXPECT_EQ(tree.lastReceivedMs(0x22), 0);
    EXPECT_EQ(tree.snapshot(tree.find(u"lauv/EstimatedState/depth")).value.toDouble(), 3.0) << "others untouched";

    tree.ingest(state(0x22, 9));
    const NodeId depth = tree.find(u"0x0022/EstimatedState/depth");
    ASSERT_NE(depth, noNode);
    EXPECT_EQ(tree.snapshot(depth).value.toDouble(), 9.0);
    EXPECT_EQ(tree.find(u"0x0022/out"), noNode) << "met anew: nothing of before";
}

TEST(VariableTree, ConsumersHearOfARemovalAndItsIdsWaitUntilEveryConsumerIsDone)
{
    VariableTree tree;
    const int model = tree.addConsumer();
    const int scripts = tree.addConsumer();
    tree.ingest(state(0x22, 7));
    tree.takeChanges(model);
    tree.takeChanges(scripts);
    const NodeId system = tree.find(u"0x0022");
    QSet<NodeId> old;
    for (NodeId n = 0; n < tree.nodeCapacity(); ++n)
        if (n != tree.root())
            old.insert(n);

    tree.ingest(state(0x22, 8)); // a change pending when it goes: dropped with it
    ASSERT_TRUE(tree.forget(0x22));
    const auto freshIds = [&] {
        std::vector<NodeId> clash;
        for (NodeId n = 0; n < tree.nodeCapacity(); ++n)
            if (old.contains(n) && tree.systemOf(n) != 0xFFFF)
                clash.push_back(n);
        return clash;
    };

    tree.ingest(state(0x33, 1)); // new nodes while consumers may hold the old ids
    EXPECT_TRUE(freshIds().empty()) << "no id reused before any consumer heard";
    VariableTree::Changes changes = tree.takeChanges(model);
    ASSERT_EQ(changes.removed.size(), 1u);
    EXPECT_EQ(changes.removed[0].node, system);
    EXPECT_EQ(changes.removed[0].system, 0x22);
    for (NodeId n : changes.changedNodes)
        EXPECT_FALSE(old.contains(n)) << "no change names a removed node";
    EXPECT_EQ(tree.takeChanges(model).removed.size(), 0u) << "once";

    tree.forget(0x33);
    tree.ingest(state(0x44, 1));
    EXPECT_TRUE(freshIds().empty()) << "the script consumer has not taken its changes yet";
    EXPECT_EQ(tree.takeChanges(scripts).removed.size(), 1u) << "0x33 came and went unseen by it";
    tree.forget(0x44);
    tree.ingest(state(0x55, 1));
    EXPECT_TRUE(freshIds().empty()) << "taken, but not yet handled (it handles them until it takes again)";
    tree.takeChanges(scripts);
    tree.takeChanges(model);
    tree.forget(0x55);
    tree.takeChanges(scripts);
    tree.takeChanges(model);
    tree.takeChanges(scripts);
    tree.takeChanges(model);
    const int before = tree.nodeCapacity();
    tree.ingest(state(0x66, 1));
    EXPECT_EQ(tree.nodeCapacity(), before) << "every consumer done: the ids are given to new nodes";
    EXPECT_EQ(tree.snapshot(tree.find(u"0x0066/EstimatedState/depth")).value.toDouble(), 1.0);
}

TEST(VariableTree, ASystemMadeAndForgottenBetweenTwoLooksIsNeverSeen)
{
    VariableTree tree;
    const int consumer = tree.addConsumer();
    tree.ingest(state(0x1f, 1));
    tree.takeChanges(consumer);
    tree.ingest(state(0x22, 7));
    tree.forget(0x22);
    const VariableTree::Changes changes = tree.takeChanges(consumer);
    EXPECT_TRUE(changes.removed.empty());
    EXPECT_TRUE(changes.newNodes.empty());
    EXPECT_TRUE(changes.changedNodes.empty());
}

TEST(VariableTree, ForgettingKeepsMemoryBoundedUnderChangingForgedIds)
{
    // Forged ids come and go for hours: each wave is forgotten, and the
    // next one lives in the same node ids.
    VariableTree tree;
    const int consumer = tree.addConsumer();
    int peak = 0;
    for (int wave = 0; wave < 50; ++wave) {
        for (quint16 id = 0; id < 100; ++id)
            tree.ingest(state(quint16(0x1000 + wave * 100 + id), id));
        tree.takeChanges(consumer);
        if (wave == 1)
            peak = tree.nodeCapacity();
        for (quint16 id = 0; id < 100; ++id)
            tree.forget(quint16(0x1000 + wave * 100 + id));
        tree.takeChanges(consumer);
    }
    EXPECT_EQ(tree.nodeCount(), 1) << "the root only";
    EXPECT_LE(tree.nodeCapacity(), peak) << "5,000 systems in waves of 100 need the nodes of two waves";
}
