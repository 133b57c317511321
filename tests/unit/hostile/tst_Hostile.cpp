// What an attacker on the network, or a careless file, sends the console:
// each test here froze, fooled or exhausted the console before its fix. They
// run with a time limit (ctest TIMEOUT): a regression shows as a timeout, not
// as a flaky timing assertion.
#include "messages/Schema.h"
#include "session/Console.h"
#include "tree/VariableTree.h"
#include "transport/dds/DdsTransport.h"

#include "FakeVehicle.h"
#include "Schemas.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QElapsedTimer>
#include <QTest>
#include <QThread>
#include <QUdpSocket>

#include <memory>

#include <gtest/gtest.h>

using namespace neptus;

namespace {

transport::ImcUdpConfig unbound()
{
    transport::ImcUdpConfig config;
    config.port = 0;
    config.discovery = false;
    return config;
}

// A console on loopback, on an ephemeral port, that heartbeats only when told.
transport::ImcUdpConfig loopback()
{
    transport::ImcUdpConfig config;
    config.port = 0;
    config.discoveryPort = 0;
    config.heartbeatMs = 60'000;
    return config;
}

QByteArray packet(const char *abbrev, quint16 src)
{
    msg::Message m(test::shippedSchema()->byAbbrev(QString::fromLatin1(abbrev)));
    m.header.src = src;
    return *msg::Codec(test::shippedSchema()).encode(m);
}

QByteArray announce(quint16 src, const char *name, const QString &services)
{
    msg::Message m(test::shippedSchema()->byAbbrev(u"Announce"));
    m.header.src = src;
    m.setBytes(m.def()->indexOf(u"sys_name"), name);
    m.setBytes(m.def()->indexOf(u"services"), services.toUtf8());
    return *msg::Codec(test::shippedSchema()).encode(m);
}

msg::Message abortCommand()
{
    return msg::Message(test::shippedSchema()->byAbbrev(u"Abort"));
}

alarms::Level levelOf(alarms::AlarmGraph &graph, const QString &path)
{
    return graph.ownLevel(graph.ensure(path));
}

} // namespace

// 400 forged ids each sending from all 254 entities made 2.1 M tree nodes
// (+340 MB) that every age tick then signalled. Now only the first
// maxEntityBranches entities of a type get a branch of their own; the others
// show in the type's shared branch.
TEST(Hostile, ForgedEntitiesMakeABoundedTree)
{
    tree::VariableTree tree;
    constexpr int systems = 40;
    for (int id = 0; id < systems; ++id) {
        for (int entity = 1; entity <= 254; ++entity) {
            msg::Message state(test::shippedSchema()->byAbbrev(u"EntityState"));
            state.header.src = quint16(0x5000 + id);
            state.header.srcEnt = quint8(entity);
            tree.ingest(state);
        }
    }
    const int perBranch = 1 + int(test::shippedSchema()->byAbbrev(u"EntityState")->fields.size());
    const int perSystem = 1 + perBranch * int(1 + tree::VariableTree::maxEntityBranches);
    EXPECT_LE(tree.nodeCount(), 1 + systems * perSystem) << "was " << 1 + systems * (1 + perBranch * 255);
    EXPECT_NE(tree.find(u"0x5000/EntityState@64"), tree::noNode);
    EXPECT_EQ(tree.find(u"0x5000/EntityState@65"), tree::noNode) << "past the cap";
    EXPECT_EQ(tree.snapshot(tree.find(u"0x5000/EntityState")).sourceEntity, 254) << "the shared branch has the latest";
}

// One 64 KB PlanSpecification with 32,000 start actions froze the GUI for
// about 4 s: list items were found by name with a scan of every sibling.
TEST(Hostile, AHugeMessageListIsIngestedInLinearTime)
{
    session::Console console(test::shippedSchema());
    auto *imc = console.attachImc(std::make_unique<transport::ImcUdpTransport>(console.schemaSet(), unbound()));
    const msg::Schema &schema = *test::shippedSchema();
    msg::Message plan(schema.byAbbrev(u"PlanSpecification"));
    plan.header.src = 0x66;
    std::vector<msg::Message> actions(32'000, msg::Message(schema.byAbbrev(u"Heartbeat")));
    plan.setMessages(plan.def()->indexOf(u"start_actions"), std::move(actions));
    const auto packet = msg::Codec(test::shippedSchema()).encode(plan);
    ASSERT_TRUE(packet) << packet.error().toString().toStdString();
    EXPECT_GT(packet->size(), 64'000);
    for (int i = 0; i < 20; ++i) // one every 2 s kept it frozen for 40 s
        imc->receive(*packet, QHostAddress::LocalHost, 6002);
    const tree::VariableTree &tree = console.tree();
    EXPECT_NE(tree.find(u"0x0066/PlanSpecification/start_actions/31999"), tree::noNode);
    EXPECT_EQ(tree.snapshot(tree.find(u"0x0066/PlanSpecification/start_actions")).value.toInt(), 32'000);
}

// Definitions loaded in quadratic time (each field checked against every
// earlier one): 40,000 fields took 6.7 s; 60,000 take over 30 s in a debug build.
TEST(Hostile, DefinitionsWithManyFieldsLoadInLinearTime)
{
    QByteArray xml = "<messages name=\"Big\" version=\"1\">\n<message id=\"2000\" name=\"Big\" abbrev=\"Big\">\n";
    for (int i = 0; i < 60'000; ++i)
        xml += "<field name=\"F\" abbrev=\"f" + QByteArray::number(i) + "\" type=\"uint8_t\"/>\n";
    xml += "</message>\n</messages>\n";
    const auto schema = msg::Schema::fromData({{QStringLiteral("big.xml"), xml}});
    ASSERT_TRUE(schema) << schema.error().toString().toStdString();
    const msg::MessageDef *big = (*schema)->byAbbrev(u"Big");
    ASSERT_TRUE(big);
    EXPECT_EQ(big->fields.size(), 60'000u);
    EXPECT_EQ(big->indexOf(u"f59999"), 59'999);
    EXPECT_EQ(big->indexOf(u"nope"), -1);

    xml.replace("abbrev=\"f59999\"", "abbrev=\"f7\"");
    const auto twice = msg::Schema::fromData({{QStringLiteral("big.xml"), xml}});
    ASSERT_FALSE(twice);
    EXPECT_TRUE(twice.error().message.contains(QStringLiteral("two fields named f7"))) << twice.error().toString().toStdString();
}

// A 100 MB definitions file was refused as "the file is 64 MiB".
TEST(Hostile, AnOversizedFileIsRefusedWithItsTrueSize)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("huge.xml"));
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    ASSERT_TRUE(file.resize(qint64(100) << 20)); // sparse: nothing is written
    file.close();
    const auto schema = msg::Schema::load({path});
    ASSERT_FALSE(schema);
    EXPECT_TRUE(schema.error().toString().contains(QStringLiteral("100 MiB"))) << schema.error().toString().toStdString();
    EXPECT_TRUE(schema.error().toString().contains(QStringLiteral("64 MiB"))) << "and the limit";
}

// An Announce names where a vehicle listens. A forged one (sent as the
// vehicle, from its own address) that named another host took the
// vehicle's commands there: now only an address on the sending host counts.
TEST(Hostile, AForgedAnnounceCannotRedirectCommands)
{
    test::FakeVehicle vehicle(0x23);
    transport::ImcUdpTransport console(test::shippedSchema(), loopback());
    ASSERT_TRUE(console.start());
    vehicle.announceTo(console.port());
    ASSERT_TRUE(QTest::qWaitFor([&] { return !console.knownSystems().isEmpty(); }, 2000));
    const QString where = QStringLiteral("127.0.0.1:%1").arg(vehicle.port());
    EXPECT_EQ(console.destination(0x23), where);

    QSignalSpy ignored(&console, &transport::ImcUdpTransport::announceIgnored);
    console.receive(announce(0x23, "lauv-sim-1", QStringLiteral("imc+udp://127.0.0.66:6002/")),
                    QHostAddress::LocalHost, 30100);
    ASSERT_EQ(ignored.count(), 1);
    EXPECT_EQ(ignored[0][1].toString(), QStringLiteral("127.0.0.1"));
    EXPECT_EQ(console.destination(0x23), where) << "commands still go to the vehicle";
    ASSERT_TRUE(console.publish(0x23, abortCommand()));
    EXPECT_TRUE(QTest::qWaitFor([&] { return !vehicle.commands.empty(); }, 2000));
}

// A second host that sends (and announces) as a vehicle's id took its
// commands. Now the console holds them and says so, until the operator
// chooses a host or the impostor falls silent.
TEST(Hostile, AnImpostorHoldsCommandsUntilOneHostIsChosen)
{
    ManualClock clock(QDateTime::currentDateTimeUtc());
    session::Console session(test::shippedSchema(), &clock);
    ASSERT_TRUE(session.startImc(loopback()));
    transport::ImcUdpTransport &console = *session.imc();
    test::FakeVehicle vehicle(0x23);
    test::FakeVehicle impostor(0x23, QHostAddress(QStringLiteral("127.0.0.2")));
    vehicle.announceTo(console.port());
    ASSERT_TRUE(QTest::qWaitFor([&] { return vehicle.streaming(); }, 2000));
    impostor.announceTo(console.port());
    ASSERT_TRUE(QTest::qWaitFor([&] { return console.sources(0x23).size() == 2; }, 2000));

    EXPECT_EQ(console.sources(0x23), (QStringList{QStringLiteral("127.0.0.1"), QStringLiteral("127.0.0.2")}));
    EXPECT_EQ(console.destination(0x23), QString());
    const auto held = session.send(0x23, abortCommand());
    ASSERT_FALSE(held);
    EXPECT_TRUE(held.error().contains(QStringLiteral("held"))) << held.error().toStdString();
    // Said on the GUI thread, from the link's decoding thread.
    EXPECT_TRUE(QTest::qWaitFor([&] {
        return levelOf(session.alarmGraph(), QStringLiteral("systems/lauv-sim-1/sources")) == alarms::Warning;
    }, 2000));
    EXPECT_FALSE(impostor.streaming()) << "no heartbeat went to the impostor";

    // The operator trusts 127.0.0.1.
    ASSERT_TRUE(session.chooseSource(0x23, QStringLiteral("127.0.0.1")));
    ASSERT_TRUE(session.send(0x23, abortCommand()));
    ASSERT_TRUE(QTest::qWaitFor([&] { return !vehicle.commands.empty(); }, 2000));
    EXPECT_TRUE(impostor.commands.empty());
    EXPECT_FALSE(session.chooseSource(0x23, QStringLiteral("127.0.0.9"))) << "a host never heard";

    // Back to automatic: held again, until the impostor is silent for the
    // conflict window while the vehicle goes on.
    ASSERT_TRUE(session.chooseSource(0x23, QString()));
    EXPECT_FALSE(session.send(0x23, abortCommand()));
    clock.advance(11'000);
    vehicle.send(msg::Message(test::shippedSchema()->byAbbrev(u"Heartbeat")), console.port());
    ASSERT_TRUE(QTest::qWaitFor([&] { return console.sources(0x23).size() == 1; }, 2000));
    EXPECT_EQ(console.destination(0x23), QStringLiteral("127.0.0.1:%1").arg(vehicle.port()));
    EXPECT_TRUE(QTest::qWaitFor([&] {
        session.tick();
        return levelOf(session.alarmGraph(), QStringLiteral("systems/lauv-sim-1/sources")) == alarms::Normal;
    }, 2000));
}

// Two consoles given one system id (two programs on one machine both take
// 0x4001): each ignores what the other sends as its own, so the console says
// so, naming the other, and stops saying it when the other leaves.
TEST(Hostile, AnotherConsoleWithOurIdIsAWarningUntilItLeaves)
{
    session::Console session(test::shippedSchema());
    ASSERT_TRUE(session.startDds(transport::DdsConfig{27, {}, 0x4001, QStringLiteral("console-a")}));
    auto twin = std::make_unique<transport::DdsTransport>(test::shippedSchema(),
                                                          transport::DdsConfig{27, {}, 0x4001, QStringLiteral("console-b")});
    ASSERT_TRUE(twin->start());
    const QString link = QStringLiteral("links/DDS");
    ASSERT_TRUE(QTest::qWaitFor([&] { return levelOf(session.alarmGraph(), link) == alarms::Warning; }, 8000));
    const QString said = session.alarmGraph().message(session.alarmGraph().find(link));
    EXPECT_TRUE(said.contains(QStringLiteral("console-b")) && said.contains(QStringLiteral("0x4001"))) << said.toStdString();
    twin.reset();
    EXPECT_TRUE(QTest::qWaitFor([&] { return levelOf(session.alarmGraph(), link) == alarms::Normal; }, 8000))
        << "cleared when the other console left";
}

// Over DDS an impostor with a vehicle's id made its position jump between
// two places and took 3 of 6 Aborts, with no warning. Now two participants
// sending as one id raise a Warning and hold commands until the operator
// picks one; from then on the other's samples for that id are dropped.
TEST(Hostile, ADdsImpostorHoldsCommandsAndIsDroppedOnceOneIsChosen)
{
    session::Console session(test::shippedSchema());
    ASSERT_TRUE(session.startDds(transport::DdsConfig{11, {}, 0x4001}));
    transport::DdsTransport vehicle(test::shippedSchema(), transport::DdsConfig{11, {}, 0x23, QStringLiteral("auv")});
    transport::DdsTransport impostor(test::shippedSchema(), transport::DdsConfig{11, {}, 0x23, QStringLiteral("auv")});
    ASSERT_TRUE(vehicle.start());
    ASSERT_TRUE(impostor.start());
    QSignalSpy atVehicle(&vehicle, &transport::DdsTransport::received);
    const auto stateAt = [](double depth) {
        msg::Message state(test::shippedSchema()->byAbbrev(u"EstimatedState"));
        state.setNumber(state.def()->indexOf(u"depth"), depth);
        return state;
    };
    const auto depth = [&] {
        return session.tree().snapshot(session.tree().find(u"0x0023/EstimatedState/depth")).value.toDouble();
    };
    ASSERT_TRUE(QTest::qWaitFor([&] {
        vehicle.broadcast(stateAt(10));
        return depth() == 10;
    }, 10000));
    EXPECT_TRUE(session.send(0x23, abortCommand())) << "one participant: commands flow";
    ASSERT_TRUE(QTest::qWaitFor([&] {
        impostor.broadcast(stateAt(500));
        return session.dds()->sources(0x23).size() == 2;
    }, 10000));
    const auto held = session.send(0x23, abortCommand());
    ASSERT_FALSE(held);
    EXPECT_TRUE(held.error().contains(QStringLiteral("held"))) << held.error().toStdString();
    ASSERT_TRUE(QTest::qWaitFor([&] {
        return levelOf(session.alarmGraph(), QStringLiteral("systems/0x0023/sources")) == alarms::Warning;
    }, 2000));

    // The operator trusts the vehicle's participant.
    ASSERT_TRUE(session.chooseSource(0x23, vehicle.participantName()));
    ASSERT_TRUE(session.send(0x23, abortCommand()));
    ASSERT_TRUE(QTest::qWaitFor([&] { return atVehicle.count() >= 2; }, 5000)) << "the two Aborts sent";
    vehicle.broadcast(stateAt(11));
    ASSERT_TRUE(QTest::qWaitFor([&] { return depth() == 11; }, 5000));
    for (int i = 0; i < 5; ++i) {
        impostor.broadcast(stateAt(500));
        QTest::qWait(50);
    }
    EXPECT_EQ(depth(), 11) << "the impostor's samples no longer reach the tree";
    EXPECT_FALSE(session.chooseSource(0x23, QStringLiteral("dds:000000000000000000000000"))) << "never heard";
}

// A flood from one host was decoded to the last datagram, and starved
// everything else. Now each host gets its budget a second; the rest is
// dropped unread and the operator sees which host overloads the link.
TEST(Hostile, AFloodingHostIsCutToItsBudgetAndNamed)
{
    ManualClock clock(QDateTime::currentDateTimeUtc());
    session::Console session(test::shippedSchema(), &clock);
    transport::ImcUdpConfig config = unbound();
    config.maxDatagramsPerSecond = 1000;
    config.clock = &clock;
    auto *imc = session.attachImc(std::make_unique<transport::ImcUdpTransport>(session.schemaSet(), config));
    const QByteArray flood = packet("EstimatedState", 0x66);
    const QHostAddress flooder(QStringLiteral("127.0.0.3"));
    for (int i = 0; i < 50'000; ++i)
        imc->receive(flood, flooder, 6002);
    // Another vehicle, from another host, in the same second.
    for (int i = 0; i < 10; ++i)
        imc->receive(packet("EstimatedState", 0x23), QHostAddress::LocalHost, 6002);
    EXPECT_EQ(session.linkStatistics().system(0x66).messages, 1000u);
    EXPECT_EQ(session.linkStatistics().system(0x23).messages, 10u);

    clock.advance(1000);
    imc->forgetSilent(); // what the heartbeat does each second
    const QString node = QStringLiteral("links/127.0.0.3");
    EXPECT_EQ(levelOf(session.alarmGraph(), node), alarms::Warning);
    const QString text = session.alarmGraph().message(session.alarmGraph().ensure(node));
    EXPECT_TRUE(text.contains(QStringLiteral("49000 dropped"))) << text.toStdString();
    clock.advance(1000);
    imc->forgetSilent();
    EXPECT_EQ(levelOf(session.alarmGraph(), node), alarms::Normal) << "quiet for a second";
}

// The socket was read on the GUI thread: while it was busy (half-second
// frames under a flood) the kernel's buffer overflowed and dropped datagrams
// unread, the vehicle's with the flood's (4-5 % of a vehicle's arrived). Now
// a thread of its own reads them into a queue per host; a busy GUI thread
// delays the vehicle's messages but loses none, and the flood loses its own.
TEST(Hostile, AVehicleLosesNothingToAFloodWhileTheGuiThreadIsBusy)
{
    session::Console session(test::shippedSchema());
    ASSERT_TRUE(session.startImc(loopback()));
    const quint16 port = session.imc()->port();
    test::FakeVehicle vehicle(0x23);
    vehicle.announceTo(port);
    // (Its Announce counted first: the console may greet it before the GUI thread has counted it.)
    ASSERT_TRUE(QTest::qWaitFor([&] { return vehicle.streaming() && session.linkStatistics().system(0x23).messages >= 1; }, 2000));
    const quint64 before = session.linkStatistics().system(0x23).messages;

    // The GUI thread is busy (no event is processed) while a second host
    // floods and the vehicle sends 50 states among 20,000 datagrams.
    QUdpSocket flooder;
    ASSERT_TRUE(flooder.bind(QHostAddress(QStringLiteral("127.0.0.3")), 0));
    const QByteArray flood = packet("EstimatedState", 0x66);
    for (int i = 0; i < 20'000; ++i) {
        flooder.writeDatagram(flood, QHostAddress::LocalHost, port);
        if (i % 400 == 0)
            vehicle.streamState(i / 1000.0);
        if (i % 100 == 0)
            QThread::usleep(1000); // ~100,000 datagrams/s: what one flooder on this machine keeps up
    }
    QThread::msleep(200);

    ASSERT_TRUE(QTest::qWaitFor([&] { return session.linkStatistics().system(0x23).messages - before >= 50; }, 5000))
        << "the vehicle's states heard: " << session.linkStatistics().system(0x23).messages - before << " of 50";
    EXPECT_EQ(session.linkStatistics().system(0x23).messages - before, 50u);
    EXPECT_GE(session.imc()->droppedDatagrams(), 10'000u) << "the flood is cut to its host's budget and queue";
    EXPECT_LE(session.linkStatistics().system(0x66).messages, 20'000u - session.imc()->droppedDatagrams());
}

// Every system id ever heard was kept and heartbeated forever: 65,000
// forged ids made the console a reflector. Now at most maxSystems are kept,
// and one not heard for forgetAfterMs is forgotten.
TEST(Hostile, ForgedSystemIdsAreCappedAndForgotten)
{
    ManualClock clock(QDateTime::currentDateTimeUtc());
    transport::ImcUdpConfig config = unbound();
    config.clock = &clock;
    config.maxDatagramsPerSecond = 0;
    transport::ImcUdpTransport imc(test::shippedSchema(), config);
    for (quint16 id = 1; id <= 5000; ++id)
        imc.receive(packet("Heartbeat", id), QHostAddress::LocalHost, 6002);
    EXPECT_EQ(imc.knownSystems().size(), config.maxSystems);
    clock.advance(config.forgetAfterMs + 1);
    imc.forgetSilent();
    EXPECT_TRUE(imc.knownSystems().isEmpty());
    imc.receive(packet("Heartbeat", 0x4000), QHostAddress::LocalHost, 6002);
    EXPECT_EQ(imc.knownSystems(), QList<quint16>{0x4000}) << "room again";
}

namespace {

// A console on a clock the test moves, whose IMC/UDP link is fed by hand
// with no budget: what reaches the health monitor is exactly what was sent.
struct ClockedConsole : ::testing::Test
{
    static transport::ImcUdpConfig config(const Clock *clock)
    {
        transport::ImcUdpConfig c = unbound();
        c.clock = clock;
        c.maxDatagramsPerSecond = 0;
        return c;
    }

    ManualClock clock{QDateTime::currentDateTimeUtc()};
    session::Console session{test::shippedSchema(), &clock};
    transport::ImcUdpTransport *imc
        = session.attachImc(std::make_unique<transport::ImcUdpTransport>(session.schemaSet(), config(&clock)));
};

} // namespace

// Every forged id left a "communications lost" Error of its own: 1,000 of
// them buried the real vehicle's alarm under 1,000 rows. Now systems never
// named and heard for under 5 s share one Warning, and are forgotten.
TEST_F(ClockedConsole, ForgedIdsThatFallSilentShareOneAlarm)
{
    // The real vehicle: named, talking at 1 Hz for 10 s.
    imc->receive(announce(0x1f, "lauv-real", QStringLiteral("imc+udp://127.0.0.1:6002/")), QHostAddress::LocalHost, 6002);
    for (int i = 0; i < 10; ++i) {
        imc->receive(packet("Heartbeat", 0x1f), QHostAddress::LocalHost, 6002);
        if (i == 5) { // a burst of forged ids, one datagram each
            for (quint16 id = 0x3000; id < 0x3000 + 1000; ++id)
                imc->receive(packet("EstimatedState", id), QHostAddress(QStringLiteral("127.0.0.5")), 6002);
        }
        clock.advance(1000);
        session.check();
    }
    clock.advance(20'000); // all silent now
    session.check();

    const auto alarms = session.alarmGraph().activeAlarms();
    EXPECT_EQ(alarms.size(), 2u) << "the real vehicle's, and one for the forged ids";
    const alarms::AlarmGraph &graph = session.alarmGraph();
    const auto real = graph.find(QStringLiteral("systems/lauv-real"));
    EXPECT_EQ(graph.ownLevel(real), alarms::Error);
    const auto summary = graph.find(QStringLiteral("links/short-lived systems"));
    ASSERT_NE(summary, alarms::AlarmGraph::noNode);
    EXPECT_EQ(graph.ownLevel(summary), alarms::Warning);
    EXPECT_TRUE(graph.message(summary).startsWith(QStringLiteral("1000 unnamed system(s)"))) << graph.message(summary).toStdString();
    EXPECT_TRUE(graph.message(summary).contains(QStringLiteral("0x3000, 0x3001"))) << graph.message(summary).toStdString();

    EXPECT_EQ(session.tree().systemIds().size(), 1001u);
    const int flooded = session.tree().nodeCount();
    clock.advance(10 * 60 * 1000); // forgotten after 10 min
    session.check();
    EXPECT_EQ(graph.ownLevel(summary), alarms::Normal);
    EXPECT_EQ(graph.ownLevel(real), alarms::Error) << "the real vehicle is not forgotten";
    // Forgotten everywhere: the tree, the link statistics, their alarms.
    EXPECT_EQ(session.tree().systemIds(), std::vector<quint16>{0x1f});
    EXPECT_LT(session.tree().nodeCount() * 100, flooded) << "from " << flooded << " nodes";
    EXPECT_EQ(session.linkStatistics().systems().size(), 1u);
    EXPECT_EQ(graph.level(graph.find(QStringLiteral("systems/0x3000"))), alarms::Unknown);
    EXPECT_NE(session.tree().find(u"lauv-real/Heartbeat"), tree::noNode);
}

// Systems named or long heard are kept while silent (an AUV dives for
// hours), unless the console is told to forget after a time.
TEST_F(ClockedConsole, SilentSystemsAreForgottenAfterTheConfiguredTimeAndMetAnewWhenHeard)
{
    session.health().setForgetAfter(3600);
    imc->receive(announce(0x1f, "lauv-real", QStringLiteral("imc+udp://127.0.0.1:6002/")), QHostAddress::LocalHost, 6002);
    for (int i = 0; i < 10; ++i) {
        imc->receive(packet("Heartbeat", 0x1f), QHostAddress::LocalHost, 6002);
        imc->receive(packet("EstimatedState", 0x22), QHostAddress::LocalHost, 6003); // long heard, never named
        clock.advance(1000);
        session.check();
    }
    const alarms::AlarmGraph &graph = session.alarmGraph();
    clock.advance(59 * 60 * 1000);
    session.check();
    EXPECT_EQ(graph.activeAlarms().size(), 2u) << "both lost, both still known after 59 min";
    EXPECT_EQ(session.tree().systemIds().size(), 2u);

    clock.advance(2 * 60 * 1000);
    session.check();
    EXPECT_TRUE(graph.activeAlarms().empty()) << "their alarms go with them";
    EXPECT_EQ(graph.rootLevel(), alarms::Unknown);
    EXPECT_TRUE(session.tree().systemIds().empty());
    EXPECT_TRUE(session.linkStatistics().systems().empty());
    const auto refused = session.send(0x1f, abortCommand());
    ASSERT_FALSE(refused);
    EXPECT_TRUE(refused.error().contains(QStringLiteral("never heard"))) << refused.error().toStdString();

    imc->receive(packet("Heartbeat", 0x1f), QHostAddress::LocalHost, 6002);
    session.check();
    EXPECT_EQ(session.tree().systemIds(), std::vector<quint16>{0x1f});
    const auto sent = session.send(0x1f, abortCommand()); // this link is not started: it gets as far as the link
    ASSERT_FALSE(sent);
    EXPECT_FALSE(sent.error().contains(QStringLiteral("never heard"))) << "met anew: " << sent.error().toStdString();
    clock.advance(10'000);
    session.check();
    EXPECT_EQ(graph.activeAlarms().size(), 1u) << "and watched anew";
}

// Forged ids that reported an entity failure before falling silent left one
// Failure per id behind: their entity alarms now go quiet with them.
TEST_F(ClockedConsole, ForgedEntityFailuresGoQuietWithTheirSystems)
{
    msg::Codec codec(test::shippedSchema());
    for (int i = 0; i < 10; ++i) {
        imc->receive(packet("Heartbeat", 0x1f), QHostAddress::LocalHost, 6002);
        if (i == 5) {
            for (quint16 id = 0x3000; id < 0x3000 + 300; ++id) {
                msg::Message failure(test::shippedSchema()->byAbbrev(u"EntityState"));
                failure.header.src = id;
                failure.header.srcEnt = 7;
                failure.setInteger(failure.def()->indexOf(u"state"), 4); // FAILURE
                failure.setBytes(failure.def()->indexOf(u"description"), "forged");
                imc->receive(*codec.encode(failure), QHostAddress(QStringLiteral("127.0.0.5")), 6002);
            }
            EXPECT_EQ(session.alarmGraph().rootLevel(), alarms::Failure) << "while they talk, their failures show";
        }
        clock.advance(1000);
        session.check();
    }
    imc->receive(packet("Heartbeat", 0x1f), QHostAddress::LocalHost, 6002);
    clock.advance(500);
    session.check(); // the forged ids are silent; the real vehicle is not

    const alarms::AlarmGraph &graph = session.alarmGraph();
    EXPECT_EQ(graph.activeAlarms().size(), 1u) << "only the summary of the forged ids";
    EXPECT_EQ(graph.rootLevel(), alarms::Warning);
    EXPECT_NE(graph.find(QStringLiteral("links/short-lived systems")), alarms::AlarmGraph::noNode);
}

namespace {

// A console's script host, its scripts run only when the test asks.
struct ScriptedConsole
{
    ScriptedConsole()
    {
        scripts.setFrameInterval(0);
        console.tree().setSystemName(0x1f, QStringLiteral("lauv"));
    }
    void set(const char *name, const char *source)
    {
        ASSERT_TRUE(scripts.setScript(QString::fromLatin1(name), QString::fromLatin1(source))) << source;
        scripts.runPending();
    }
    alarms::Level level(const char *name) { return levelOf(console.alarmGraph(), QStringLiteral("scripts/") + QLatin1StringView(name)); }
    QString message(const char *name)
    {
        return console.alarmGraph().message(console.alarmGraph().find(QStringLiteral("scripts/") + QLatin1StringView(name)));
    }

    session::Console console{test::shippedSchema()};
    scripting::ScriptHost &scripts = *console.scripts();
};

} // namespace

// `let a = []; while (true) a.push(new Array(1e6))` crashed the console
// (SIGSEGV, 10 of 10) inside the script thread; a shared layout with it
// killed every console that opened it. Now it ends its own host process.
TEST(Hostile, AScriptThatEatsMemoryEndsOnlyItsHost)
{
    ScriptedConsole c;
    c.scripts.setTimeLimit(1000);
    c.scripts.setMemoryLimit(256);
    c.set("before", "return Info(\"fine\");");
    // The engine keeps these arrays sparse, so it is stopped by time, or
    // the engine crashes while stopping it (it did in the console's thread).
    c.set("bomb", "let a = []; while (true) a.push(new Array(1e6)); return Normal;");
    EXPECT_EQ(c.level("bomb"), alarms::Error);
    EXPECT_TRUE(c.message("bomb").contains(QStringLiteral("script stopped"))) << c.message("bomb").toStdString();
    // Memory the engine does fill is stopped at the cap, before the time limit.
    c.set("hoard", "let a = []; for (;;) a.push(String(a.length).repeat(1 << 20)); return Normal;");
    EXPECT_EQ(c.level("hoard"), alarms::Error);
    EXPECT_TRUE(c.message("hoard").contains(QStringLiteral("more than 256 MB"))) << c.message("hoard").toStdString();
    // The other scripts go on in a new host, and new ones run too.
    EXPECT_EQ(c.level("before"), alarms::Info);
    c.set("after", "return Warning(\"still here\");");
    EXPECT_EQ(c.level("after"), alarms::Warning);
    EXPECT_EQ(c.message("after"), QStringLiteral("still here"));
    // The bomb stays stopped, whatever changes.
    c.console.tree().ingest(msg::Message(test::shippedSchema()->byAbbrev(u"Heartbeat")));
    c.scripts.runPending();
    EXPECT_EQ(c.level("bomb"), alarms::Error);
}

// `new Array(2**27).fill(0)` ran 16.8 s past a 50 ms limit with the GUI
// frozen: a built-in does not check for interruption.
TEST(Hostile, ASlowBuiltInIsStoppedSoonAfterTheLimit)
{
    ScriptedConsole c;
    c.scripts.setTimeLimit(50);
    c.scripts.setMemoryLimit(4096);
    QElapsedTimer timer;
    timer.start();
    c.set("slow", "new Array(2**27).fill(0); return Normal;");
    const qint64 elapsed = timer.elapsed();
    std::printf("slow built-in stopped after %lld ms (limit 50 ms)\n", static_cast<long long>(elapsed));
    EXPECT_LT(elapsed, 2000);
    EXPECT_EQ(c.level("slow"), alarms::Error);
    EXPECT_TRUE(c.message("slow").contains(QStringLiteral("time limit"))) << c.message("slow").toStdString();
    c.set("after", "return Normal;");
    EXPECT_EQ(c.level("after"), alarms::Normal);
}

// The GUI thread waited on the script thread to install or test a script,
// so a slow script froze the console.
TEST(Hostile, TheGuiThreadNeverWaitsOnAScript)
{
    ScriptedConsole c;
    c.scripts.setTimeLimit(1500);
    QElapsedTimer timer;
    timer.start();
    ASSERT_TRUE(c.scripts.setScript(QStringLiteral("spin"), QStringLiteral("while (true) {}")));
    ASSERT_TRUE(c.scripts.setScript(QStringLiteral("next"), QStringLiteral("return Normal;")));
    const QVariantMap installed = c.scripts.install(QStringLiteral("third"), QStringLiteral("return Info;"));
    const qint64 elapsed = timer.elapsed();
    std::printf("three scripts installed in %lld ms while one spins for 1500 ms\n", static_cast<long long>(elapsed));
    EXPECT_TRUE(installed.value(QStringLiteral("ok")).toBool());
    EXPECT_LT(elapsed, 1000);
    c.scripts.runPending();
    EXPECT_GE(timer.elapsed(), 1500);
    EXPECT_EQ(c.level("spin"), alarms::Error);
    EXPECT_EQ(c.level("next"), alarms::Normal);
    EXPECT_EQ(c.level("third"), alarms::Info);
}

// All scripts shared one engine: a __level on Object.prototype in one made
// another's Error read as Normal.
TEST(Hostile, AScriptCannotChangeWhatAnotherSees)
{
    ScriptedConsole c;
    c.set("poison", "Object.defineProperty(Object.prototype, \"__level\", { get() { return 1; } });\nreturn Normal;");
    c.set("victim", "return Error(\"the real state\");");
    EXPECT_EQ(c.level("poison"), alarms::Error) << c.message("poison").toStdString();
    EXPECT_EQ(c.level("victim"), alarms::Error);
    EXPECT_EQ(c.message("victim"), QStringLiteral("the real state"));
    // Nor through other built-ins or the global object.
    c.set("tamper", "Array.prototype.includes = () => true; Math.max = () => 0; globalThis.shared = 1;\n"
                    "Error.prototype.toString = () => 'fine'; return Normal;");
    c.set("reader", "if ([1].includes(2) || Math.max(1, 2) !== 2 || 'shared' in globalThis)\n"
                    "    return Failure(\"tampered\");\nreturn Info(String(new Error('x')));");
    EXPECT_EQ(c.level("reader"), alarms::Info) << c.message("reader").toStdString();
    EXPECT_EQ(c.message("reader"), QStringLiteral("Error: x"));
}
