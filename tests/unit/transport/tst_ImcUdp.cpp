// The IMC/UDP transport against a vehicle that behaves like a DUNE vehicle:
// it streams only to consoles it has heard a Heartbeat from, and obeys
// commands addressed to its own id. All on loopback, ephemeral ports.
#include "ImcUdpTransport.h"

#include "Schemas.h"

#include <QNetworkDatagram>
#include <QSignalSpy>
#include <QTest>

#include <gtest/gtest.h>

using namespace neptus;
using namespace neptus::transport;

namespace {

class FakeVehicle : public QObject
{
public:
    explicit FakeVehicle(quint16 id)
        : m_codec(test::shippedSchema())
        , m_id(id)
    {
        m_socket.bind(QHostAddress::LocalHost, 0);
        connect(&m_socket, &QUdpSocket::readyRead, this, [this] {
            while (m_socket.hasPendingDatagrams()) {
                const QNetworkDatagram datagram = m_socket.receiveDatagram();
                auto message = m_codec.decode(datagram.data());
                if (!message)
                    continue;
                if (message->abbrev() == u"Heartbeat") {
                    m_console = {datagram.senderAddress(), static_cast<quint16>(datagram.senderPort())};
                    ++heartbeats;
                } else if (message->header.dst == m_id) {
                    commands.push_back(*message);
                }
            }
        });
    }

    quint16 port() const { return m_socket.localPort(); }
    bool streaming() const { return heartbeats > 0; }

    void send(msg::Message message, quint16 toPort)
    {
        message.header.src = m_id;
        m_socket.writeDatagram(*m_codec.encode(message), QHostAddress::LocalHost, toPort);
    }
    // A DUNE vehicle streams to the consoles it heard from, and only to them.
    void streamState(double depth)
    {
        if (!streaming())
            return;
        msg::Message state(test::shippedSchema()->byAbbrev(u"EstimatedState"));
        state.setNumber(state.def()->indexOf(u"depth"), depth);
        send(state, m_console.second);
    }
    void announceTo(quint16 port)
    {
        msg::Message announce(test::shippedSchema()->byAbbrev(u"Announce"));
        announce.setBytes(announce.def()->indexOf(u"sys_name"), "lauv-sim-1");
        announce.setInteger(announce.def()->indexOf(u"sys_type"), 2);
        announce.setBytes(announce.def()->indexOf(u"services"),
                          QStringLiteral("dune://0.0.0.0/uid/1/;imc+udp://127.0.0.1:%1/").arg(this->port()).toUtf8());
        send(announce, port);
    }

    int heartbeats = 0;
    std::vector<msg::Message> commands;

private:
    msg::Codec m_codec;
    quint16 m_id;
    QUdpSocket m_socket;
    std::pair<QHostAddress, quint16> m_console;
};

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
