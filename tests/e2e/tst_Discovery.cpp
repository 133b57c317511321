// IMC discovery the standard way, against a simulated vehicle as strict as a
// stock DUNE vehicle: it announces only to the IMC discovery ports
// (127.0.0.1:30100-30104), streams only to systems that announced themselves
// and ignores everyone else. The console side is the real session with its
// IMC/UDP link on the default discovery ports.
#include "session/Console.h"

#include "Schemas.h"
#include "SimProcess.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QTest>
#include <QUdpSocket>

#include <gtest/gtest.h>

using namespace neptus;

TEST(Discovery, AStockImcVehicleIsFoundOnTheDiscoveryPortsAndItsEntitiesNamed)
{
    session::Console session(test::shippedSchema());
    transport::ImcUdpConfig config;
    config.port = 0; // discovery on its standard ports, the link on any
    ASSERT_TRUE(session.startImc(config));
    ASSERT_GE(session.imc()->discoveryPort(), 30100);
    ASSERT_LE(session.imc()->discoveryPort(), 30104);

    QElapsedTimer clock;
    clock.start();
    test::SimProcess vehicle;
    vehicle.start({QStringLiteral("--id"), QStringLiteral("0xd1"), QStringLiteral("--name"),
                   QStringLiteral("lauv-simulator-1"), QStringLiteral("--port"), QStringLiteral("16020"),
                   QStringLiteral("--like-dune")});
    const tree::VariableTree &tree = session.tree();
    const bool found = QTest::qWaitFor([&] {
        const auto depth = tree.find(u"lauv-simulator-1/EstimatedState/depth");
        return depth != tree::noNode && tree.snapshot(depth).present
               && tree.find(u"lauv-simulator-1/EntityState@Navigation/state") != tree::noNode
               && tree.entityLabel(0xd1, 3) == QStringLiteral("Batteries");
    }, 10000);
    const qint64 elapsed = clock.elapsed();
    ASSERT_TRUE(found) << "not discovered and named within 10 s; tree:\n"
                       << session.dumpTree().left(2000).toStdString() << "\nvehicle:\n" << vehicle.output.constData();
    std::printf("discovered, streaming and entities named %lld ms after the vehicle started\n",
                static_cast<long long>(elapsed));
    EXPECT_TRUE(vehicle.output.contains("received EntityList from 0x4001")) << "the console asked for the names";
    EXPECT_EQ(tree.snapshot(tree.find(u"lauv-simulator-1/out/EntityList/op")).text, QStringLiteral("QUERY"));
    // The entities' alarms carry their labels too.
    EXPECT_TRUE(QTest::qWaitFor([&] {
        return session.alarmGraph().find(QStringLiteral("systems/lauv-simulator-1/Navigation")) != alarms::AlarmGraph::noNode;
    }, 3000));

    // Someone who never announced itself is ignored by such a vehicle: the
    // reason the console must announce on the discovery ports.
    msg::Message beat(test::shippedSchema()->byAbbrev(u"Heartbeat"));
    beat.header.src = 0x4444;
    QUdpSocket stranger;
    stranger.writeDatagram(*msg::Codec(test::shippedSchema()).encode(beat), QHostAddress::LocalHost, 16020);
    EXPECT_TRUE(QTest::qWaitFor([&] { return vehicle.output.contains("ignoring 0x4444"); }, 3000)) << vehicle.output.constData();
}

// A stock DUNE (Transports.Discovery, Transports.UDP) takes a console as a
// node only from an Announce on its discovery port, and streams to it from
// its next contact refresh (every 5 s) once the console's packets reach its
// own port. The console greets a vehicle at once on hearing its Announce —
// on its discovery ports too — so its first position (the Announce's, which
// DUNE fills from its EstimatedState) is there at once and its stream within
// one refresh; and again when the vehicle restarts and announces anew.
TEST(Discovery, AStockDuneVehicleStreamsWithinOneContactRefreshOfItsFirstAnnounce)
{
    session::Console session(test::shippedSchema());
    transport::ImcUdpConfig config;
    config.port = 0;
    ASSERT_TRUE(session.startImc(config));
    const tree::VariableTree &tree = session.tree();
    const auto present = [&](const char16_t *path) {
        const auto node = tree.find(QString::fromUtf16(path));
        return node != tree::noNode && tree.snapshot(node).present;
    };
    for (int life = 0; life < 2; ++life) {
        qint64 announcedMs = QDateTime::currentMSecsSinceEpoch();
        test::SimProcess vehicle;
        vehicle.start({QStringLiteral("--id"), QStringLiteral("0xd1"), QStringLiteral("--name"),
                       QStringLiteral("lauv-simulator-1"), QStringLiteral("--port"), QStringLiteral("16021"),
                       QStringLiteral("--like-dune")});
        ASSERT_TRUE(QTest::qWaitFor([&] {
            const auto node = tree.find(u"lauv-simulator-1/Announce/lat");
            if (node == tree::noNode || tree.snapshot(node).receivedMs <= announcedMs)
                return false;
            announcedMs = tree.snapshot(node).receivedMs;
            return true;
        }, 5000)) << vehicle.output.constData();
        EXPECT_NE(tree.snapshot(tree.find(u"lauv-simulator-1/Announce/lat")).value.toDouble(), 0.0)
            << "its Announce says where it is";
        const auto streamed = [&] {
            const auto node = tree.find(u"lauv-simulator-1/EstimatedState/depth");
            return node != tree::noNode && tree.snapshot(node).receivedMs > announcedMs;
        };
        ASSERT_TRUE(QTest::qWaitFor(streamed, 8000)) << vehicle.output.constData();
        const qint64 waited = tree.snapshot(tree.find(u"lauv-simulator-1/EstimatedState/depth")).receivedMs - announcedMs;
        std::printf("%s: first EstimatedState %lld ms after its first Announce\n", life == 0 ? "met" : "restarted",
                    static_cast<long long>(waited));
        EXPECT_LE(waited, 5500) << "within one contact refresh (5 s)";
        EXPECT_TRUE(QTest::qWaitFor([&] { return vehicle.output.contains("activating transmission to node 0x4001"); }, 2000))
            << vehicle.output.constData();
        EXPECT_TRUE(present(u"lauv-simulator-1/PlanControlState/state"));
    }
}
