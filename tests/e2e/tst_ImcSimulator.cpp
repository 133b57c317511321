// The console (session::Console with its IMC/UDP link) against
// real neptus-sim processes on loopback, inside the test sandbox's private
// network namespace.
#include "session/Console.h"

#include "Schemas.h"
#include "SimProcess.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QTest>

#include <gtest/gtest.h>

#include <memory>

using namespace neptus;

namespace {

using Vehicle = test::SimProcess;

transport::ImcUdpConfig consoleConfig()
{
    transport::ImcUdpConfig config;
    config.port = 0;
    config.discoveryPort = 0;
    config.heartbeatMs = 200;
    return config;
}

bool hasDepth(const tree::VariableTree &tree, const char *system)
{
    const tree::NodeId node = tree.find(QString::fromLatin1(system) + QStringLiteral("/EstimatedState/depth"));
    return node != tree::noNode && tree.snapshot(node).present;
}

} // namespace

TEST(ImcSimulator, StaticDestinationStreamsAndCommandsReachOnlyTheirTarget)
{
    Vehicle a, b;
    a.start({QStringLiteral("--id"), QStringLiteral("0x1f"), QStringLiteral("--name"), QStringLiteral("lauv-a"),
             QStringLiteral("--port"), QStringLiteral("16002")});
    b.start({QStringLiteral("--id"), QStringLiteral("0x20"), QStringLiteral("--name"), QStringLiteral("lauv-b"),
             QStringLiteral("--port"), QStringLiteral("16003"), QStringLiteral("--kind"), QStringLiteral("asv")});
    transport::ImcUdpConfig config = consoleConfig();
    config.destinations = {{QHostAddress::LocalHost, 16002}, {QHostAddress::LocalHost, 16003}};
    session::Console console(test::shippedSchema());
    ASSERT_TRUE(console.startImc(config));
    // Streams start after the console's heartbeat; names come with the vehicles' Announce (every 10 s, first at once).
    ASSERT_TRUE(QTest::qWaitFor([&] { return hasDepth(console.tree(), "lauv-a") && hasDepth(console.tree(), "lauv-b"); }, 15000))
        << "systems: " << console.tree().childNames(u"").join(u',').toStdString();
    // Entities by their labels, and the paper's Motor message, within a second or two.
    EXPECT_TRUE(QTest::qWaitFor([&] {
        return console.tree().find(u"lauv-a/EntityState@Batteries/state") != tree::noNode
               && console.tree().find(u"lauv-a/Motor/speed") != tree::noNode;
    }, 5000));

    msg::Message abort(test::shippedSchema()->byAbbrev(u"Abort"));
    ASSERT_TRUE(console.send(QStringLiteral("lauv-a"), abort));
    ASSERT_TRUE(QTest::qWaitFor([&] { return a.output.contains("received Abort"); }, 5000)) << a.output.constData();
    QTest::qWait(300);
    EXPECT_FALSE(b.output.contains("received Abort")) << "only its target gets a command";
}

TEST(ImcSimulator, DiscoveredThroughAnnounceAndCommsLossIsRaisedAndCleared)
{
    transport::ImcUdpConfig config = consoleConfig();
    config.discovery = true;
    session::Console console(test::shippedSchema());
    ASSERT_TRUE(console.startImc(config));
    const QStringList arguments{QStringLiteral("--id"), QStringLiteral("0x21"), QStringLiteral("--name"),
                                QStringLiteral("lauv-c"), QStringLiteral("--port"), QStringLiteral("16004"),
                                QStringLiteral("--announce-port"), QString::number(console.imc()->discoveryPort())};
    auto vehicle = std::make_unique<Vehicle>();
    vehicle->start(arguments);
    ASSERT_TRUE(QTest::qWaitFor([&] { return hasDepth(console.tree(), "lauv-c"); }, 15000));

    // Killed: "communications lost" within 2 s plus its message interval.
    const auto node = [&] { return console.alarmGraph().find(QStringLiteral("systems/lauv-c")); };
    vehicle.reset();
    QElapsedTimer silence;
    silence.start();
    ASSERT_TRUE(QTest::qWaitFor([&] {
        console.health().check();
        return node() != alarms::AlarmGraph::noNode && console.alarmGraph().ownLevel(node()) == alarms::Warning;
    }, 10000));
    std::printf("communications lost raised %lld ms after the vehicle was killed\n", static_cast<long long>(silence.elapsed()));
    EXPECT_LT(silence.elapsed(), 3000) << "2 s + the heartbeat period";
    EXPECT_TRUE(console.alarmGraph().message(node()).startsWith(QStringLiteral("communications lost")));

    // Restarted: cleared as soon as it is heard again.
    vehicle = std::make_unique<Vehicle>();
    vehicle->start(arguments);
    ASSERT_TRUE(QTest::qWaitFor([&] { return console.alarmGraph().ownLevel(node()) == alarms::Normal; }, 15000));
}
