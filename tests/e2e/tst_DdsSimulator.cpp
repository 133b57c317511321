// Simulated vehicles as separate processes over Cyclone DDS on loopback
// (inside the test sandbox's private network namespace), seen by a console.
#include "session/Console.h"

#include "Schemas.h"
#include "SimProcess.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QTest>

#include <gtest/gtest.h>

using namespace neptus;

namespace {

using Vehicle = test::SimProcess;

bool hasDepth(const tree::VariableTree &tree, const char *system)
{
    const tree::NodeId node = tree.find(QString::fromLatin1(system) + QStringLiteral("/EstimatedState/depth"));
    return node != tree::noNode && tree.snapshot(node).present;
}

} // namespace

TEST(DdsSimulator, TwoConsolesAndTwoVehiclesManyToMany)
{
    session::Console first(test::shippedSchema()), second(test::shippedSchema());
    ASSERT_TRUE(first.startDds({7, {}, 0x4001}));
    ASSERT_TRUE(second.startDds({7, {}, 0x4002}));
    Vehicle a, b;
    a.start({QStringLiteral("--dds"), QStringLiteral("--dds-domain"), QStringLiteral("7"), QStringLiteral("--id"),
             QStringLiteral("0x41"), QStringLiteral("--name"), QStringLiteral("dds-x"), QStringLiteral("--port"),
             QStringLiteral("16112")});
    b.start({QStringLiteral("--dds"), QStringLiteral("--dds-domain"), QStringLiteral("7"), QStringLiteral("--id"),
             QStringLiteral("0x42"), QStringLiteral("--name"), QStringLiteral("dds-y"), QStringLiteral("--port"),
             QStringLiteral("16113"), QStringLiteral("--kind"), QStringLiteral("uav")});
    for (session::Console *console : {&first, &second}) {
        ASSERT_TRUE(QTest::qWaitFor([&] { return hasDepth(console->tree(), "dds-x") && hasDepth(console->tree(), "dds-y"); }, 20000))
            << "systems: " << console->tree().childNames(u"").join(u',').toStdString();
    }
    // Each console's commands reach only their target, whichever console sent them.
    ASSERT_TRUE(first.send(QStringLiteral("dds-x"), msg::Message(test::shippedSchema()->byAbbrev(u"Abort"))));
    ASSERT_TRUE(second.send(QStringLiteral("dds-y"), msg::Message(test::shippedSchema()->byAbbrev(u"PlanControl"))));
    ASSERT_TRUE(QTest::qWaitFor([&] {
        return a.output.contains("received Abort from 0x4001") && b.output.contains("received PlanControl from 0x4002");
    }, 5000)) << a.output.constData() << b.output.constData();
    QTest::qWait(300);
    EXPECT_FALSE(a.output.contains("PlanControl"));
    EXPECT_FALSE(b.output.contains("Abort"));
}

TEST(DdsSimulator, VehiclesAreSeenCommandedAndMissed)
{
    session::Console side(test::shippedSchema());
    ASSERT_TRUE(side.startDds({7, {}, 0x4001}));
    tree::VariableTree &tree = side.tree();
    alarms::AlarmGraph &graph = side.alarmGraph();
    alarms::HealthMonitor &health = side.health();
    transport::DdsTransport &console = *side.dds();

    auto a = std::make_unique<Vehicle>();
    Vehicle b;
    const QStringList aArguments{QStringLiteral("--dds"), QStringLiteral("--dds-domain"), QStringLiteral("7"),
                                 QStringLiteral("--id"), QStringLiteral("0x31"), QStringLiteral("--name"),
                                 QStringLiteral("dds-a"), QStringLiteral("--port"), QStringLiteral("16102")};
    a->start(aArguments);
    // Started after the console: discovered all the same.
    b.start({QStringLiteral("--dds"), QStringLiteral("--dds-domain"), QStringLiteral("7"), QStringLiteral("--id"),
             QStringLiteral("0x32"), QStringLiteral("--name"), QStringLiteral("dds-b"), QStringLiteral("--port"),
             QStringLiteral("16103"), QStringLiteral("--kind"), QStringLiteral("asv")});
    // Names arrive with the Announce every 10 s; ids at once.
    ASSERT_TRUE(QTest::qWaitFor([&] { return hasDepth(tree, "0x0031") || hasDepth(tree, "dds-a"); }, 20000))
        << "systems: " << tree.childNames(u"").join(u',').toStdString();
    ASSERT_TRUE(QTest::qWaitFor([&] { return hasDepth(tree, "0x0032") || hasDepth(tree, "dds-b"); }, 20000));

    ASSERT_TRUE(console.publish(0x31, msg::Message(test::shippedSchema()->byAbbrev(u"Abort"))));
    ASSERT_TRUE(QTest::qWaitFor([&] { return a->output.contains("received Abort"); }, 5000)) << a->output.constData();
    QTest::qWait(300);
    EXPECT_FALSE(b.output.contains("received Abort")) << "only its target acts on a command";

    a.reset(); // killed
    QElapsedTimer silence;
    silence.start();
    const auto node = [&] { return graph.find(QStringLiteral("systems/") + tree.systemName(0x31)); };
    ASSERT_TRUE(QTest::qWaitFor([&] {
        health.check();
        return node() != alarms::AlarmGraph::noNode && graph.ownLevel(node()) == alarms::Warning;
    }, 10000));
    std::printf("DDS: communications lost raised %lld ms after the vehicle was killed\n",
                static_cast<long long>(silence.elapsed()));
    EXPECT_LT(silence.elapsed(), 3000);
    EXPECT_LT(graph.ownLevel(graph.find(QStringLiteral("systems/") + tree.systemName(0x32))), alarms::Warning);
}
