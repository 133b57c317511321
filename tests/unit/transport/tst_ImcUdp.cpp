// The IMC/UDP transport against a vehicle that behaves like a DUNE vehicle:
// it streams only to consoles it has heard a Heartbeat from, and obeys
// commands addressed to its own id. All on loopback, ephemeral ports.
#include "transport/imc/ImcUdpTransport.h"

#include "FakeVehicle.h"
#include "Schemas.h"

#include <QNetworkDatagram>
#include <QSignalSpy>
#include <QTest>

#include <gtest/gtest.h>

using namespace neptus;
using namespace neptus::transport;
using neptus::test::FakeVehicle;

namespace {

ImcUdpConfig loopbackConfig()
{
    ImcUdpConfig config;
    config.port = 0;
    config.discoveryPort = 0;
    config.heartbeatMs = 100;
    return config;
}

} // namespace

TEST(ImcUdpTransport, StaticDestinationStreamsAfterTheConsolesHeartbeat)
{
    FakeVehicle vehicle(0x1f);
    ImcUdpConfig config = loopbackConfig();
    config.destinations.append({QHostAddress::LocalHost, vehicle.port()});
    ImcUdpTransport console(test::shippedSchema(), config);
    QSignalSpy received(&console, &ImcUdpTransport::received);

    vehicle.streamState(1);
    QTest::qWait(50);
    EXPECT_EQ(received.count(), 0) << "a vehicle does not stream before it hears the console";

    ASSERT_TRUE(console.start());
    ASSERT_TRUE(QTest::qWaitFor([&] { return vehicle.streaming(); }, 2000)) << "the console's heartbeat reaches it";
    vehicle.streamState(12.5);
    ASSERT_TRUE(QTest::qWaitFor([&] { return received.count() > 0; }, 2000));
    const auto message = received.last().at(0).value<msg::Message>();
    EXPECT_EQ(message.abbrev(), QStringLiteral("EstimatedState"));
    EXPECT_EQ(message.header.src, 0x1f);
    EXPECT_DOUBLE_EQ(message.number(u"depth"), 12.5);
    EXPECT_EQ(console.knownSystems(), QList<quint16>{0x1f});

    // Commands go to the vehicle's own id.
    console.publish(0x1f, msg::Message(test::shippedSchema()->byAbbrev(u"Abort")));
    ASSERT_TRUE(QTest::qWaitFor([&] { return !vehicle.commands.empty(); }, 2000));
    EXPECT_EQ(vehicle.commands.front().abbrev(), QStringLiteral("Abort"));
    EXPECT_EQ(vehicle.commands.front().header.dst, 0x1f);
    EXPECT_EQ(vehicle.commands.front().header.src, config.systemId);
}

TEST(ImcUdpTransport, VehiclesAreDiscoveredThroughAnnounce)
{
    FakeVehicle vehicle(0x22);
    ImcUdpConfig config = loopbackConfig();
    config.discovery = true;
    ImcUdpTransport console(test::shippedSchema(), config);
    QSignalSpy discovered(&console, &ImcUdpTransport::systemDiscovered);
    ASSERT_TRUE(console.start());
    EXPECT_FALSE(vehicle.streaming());

    vehicle.announceTo(console.discoveryPort());
    ASSERT_TRUE(QTest::qWaitFor([&] { return discovered.count() == 1; }, 2000));
    EXPECT_EQ(discovered.first().at(0).toUInt(), 0x22u);
    EXPECT_EQ(discovered.first().at(1).toString(), QStringLiteral("lauv-sim-1"));
    ASSERT_TRUE(QTest::qWaitFor([&] { return vehicle.streaming(); }, 2000)) << "heartbeats follow discovery";
}

TEST(ImcUdpTransport, OwnMessagesAndGarbageAreDropped)
{
    ImcUdpConfig config = loopbackConfig();
    ImcUdpTransport console(test::shippedSchema(), config);
    QSignalSpy received(&console, &ImcUdpTransport::received);
    ASSERT_TRUE(console.start());

    FakeVehicle relay(config.systemId); // as if a vehicle relayed our own message back
    relay.send(msg::Message(test::shippedSchema()->byAbbrev(u"Heartbeat")), console.port());
    QUdpSocket raw;
    raw.writeDatagram(QByteArray("not an IMC packet at all"), QHostAddress::LocalHost, console.port());
    ASSERT_TRUE(QTest::qWaitFor([&] { return console.decodeErrors() == 1; }, 2000));
    QTest::qWait(50);
    EXPECT_EQ(received.count(), 0);
}

TEST(ImcUdpTransport, ABusyPortIsAClearError)
{
    QUdpSocket squatter;
    ASSERT_TRUE(squatter.bind(QHostAddress::LocalHost, 0));
    ImcUdpConfig config = loopbackConfig();
    config.port = squatter.localPort();
    ImcUdpTransport console(test::shippedSchema(), config);
    const auto started = console.start();
    ASSERT_FALSE(started);
    EXPECT_TRUE(started.error().contains(QStringLiteral("127.0.0.1:%1").arg(config.port))) << started.error().toStdString();
}

TEST(ImcUdpTransport, DiscoveryTakesTheFirstFreePortAndAnnouncesToAllOfThem)
{
    // A range of three ports whose first is taken, as by another console.
    QUdpSocket first;
    ASSERT_TRUE(first.bind(QHostAddress::LocalHost, 0));
    const quint16 base = first.localPort();
    QUdpSocket third;
    if (!third.bind(QHostAddress::LocalHost, static_cast<quint16>(base + 2)))
        GTEST_SKIP() << "port " << base + 2 << " is taken: the test needs two free ports after " << base;
    ImcUdpConfig config = loopbackConfig();
    config.discoveryPort = base;
    config.discoveryPortCount = 3;
    ImcUdpTransport console(test::shippedSchema(), config);
    ASSERT_TRUE(console.start());
    EXPECT_EQ(console.discoveryPort(), base + 1) << "the first free one";

    // Its Announce reaches every port of the range (here the two others).
    const msg::Codec codec(test::shippedSchema());
    const auto announceAt = [&](QUdpSocket &socket) -> std::optional<msg::Message> {
        if (!QTest::qWaitFor([&] { return socket.hasPendingDatagrams(); }, 2000))
            return std::nullopt;
        auto m = codec.decode(socket.receiveDatagram().data());
        return m ? std::optional(*m) : std::nullopt;
    };
    for (QUdpSocket *socket : {&first, &third}) {
        const auto announce = announceAt(*socket);
        ASSERT_TRUE(announce);
        EXPECT_EQ(announce->abbrev(), QStringLiteral("Announce"));
        EXPECT_EQ(announce->header.src, config.systemId);
        EXPECT_EQ(announce->enumText(announce->def()->indexOf(u"sys_type")), QStringLiteral("CCU"));
        const QString services = announce->text(u"services");
        EXPECT_TRUE(services.contains(QStringLiteral("imc+udp://127.0.0.1:%1/").arg(console.port()))) << services.toStdString();
        EXPECT_TRUE(services.contains(QStringLiteral("imc+info://0.0.0.0/version/5.4.31"))) << services.toStdString();
    }

    // All taken: a clear error naming the range.
    ImcUdpTransport another(test::shippedSchema(), config);
    QUdpSocket second;
    ASSERT_FALSE(second.bind(QHostAddress::LocalHost, static_cast<quint16>(base + 1))) << "the console holds it";
    const auto started = another.start();
    ASSERT_FALSE(started);
    EXPECT_TRUE(started.error().contains(QStringLiteral("ports %1-%2").arg(base).arg(base + 2))) << started.error().toStdString();
}

TEST(ImcUdpTransport, AnAnnouncedVehicleIsGreetedAtOnceOnTheServiceItSentFrom)
{
    FakeVehicle vehicle(0x23);
    ImcUdpConfig config = loopbackConfig();
    config.heartbeatMs = 60000; // no timer-driven heartbeat: the greeting must do
    ImcUdpTransport console(test::shippedSchema(), config);
    ASSERT_TRUE(console.start());
    // Two services; the vehicle sends from 127.0.0.1, so that is where it is reached.
    msg::Message announce(test::shippedSchema()->byAbbrev(u"Announce"));
    announce.header.src = 0x23;
    announce.setBytes(announce.def()->indexOf(u"sys_name"), "twin-homed");
    announce.setBytes(announce.def()->indexOf(u"services"),
                      QStringLiteral("imc+udp://127.0.0.2:%1/;imc+udp://127.0.0.1:%1/").arg(vehicle.port()).toUtf8());
    console.receive(*msg::Codec(test::shippedSchema()).encode(announce), QHostAddress::LocalHost, vehicle.port());
    ASSERT_TRUE(QTest::qWaitFor([&] { return vehicle.streaming(); }, 2000)) << "a heartbeat right away";
    ASSERT_TRUE(console.publish(0x23, msg::Message(test::shippedSchema()->byAbbrev(u"Abort"))));
    ASSERT_TRUE(QTest::qWaitFor([&] { return !vehicle.commands.empty(); }, 2000));
}

TEST(ImcUdpTransport, APacketThatDoesNotDecodeIsReportedWithItsSenderAndReason)
{
    ImcUdpTransport console(test::shippedSchema(), loopbackConfig());
    QSignalSpy failed(&console, &ImcUdpTransport::decodeFailed);
    msg::Message state(test::shippedSchema()->byAbbrev(u"EstimatedState"));
    state.header.src = 0x31;
    QByteArray packet = *msg::Codec(test::shippedSchema()).encode(state);
    packet.chop(1);
    console.receive(packet, QHostAddress::LocalHost, 6007);
    ASSERT_EQ(failed.count(), 1);
    EXPECT_EQ(failed[0][0].toUInt(), 0x31u) << "from the header, though the packet is short";
    EXPECT_EQ(failed[0][1].toString(), QStringLiteral("127.0.0.1:6007"));
    EXPECT_FALSE(failed[0][2].toString().isEmpty());
    console.receive(QByteArray("?"), QHostAddress::LocalHost, 6007);
    EXPECT_EQ(failed[1][0].toUInt(), 0xFFFFu) << "no header, no sender";
}
