// The console's receive path as a whole (IMC/UDP transport → definitions per
// sender → session: tree, health, statistics, alarms), fed without sockets:
// a real DUNE vehicle's log, packets that do not decode, types the
// definitions lack, and a vehicle built from another IMC revision.
#include "Paths.h"
#include "core/Gzip.h"
#include "log/LogFile.h"
#include "log/Recorder.h"
#include "session/Console.h"

#include "Fixtures.h"
#include "Schemas.h"

#include <QCoreApplication>
#include <QTemporaryDir>
#include <QTest>
#include <QUdpSocket>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <map>
#include <thread>

using namespace neptus;

namespace {

// The packets of an IMC log (Data.lsf): one after another, each as long as
// its header says.
std::vector<QByteArrayView> packetsOf(const QByteArray &log)
{
    std::vector<QByteArrayView> packets;
    qsizetype at = 0;
    while (at + msg::Codec::headerSize + msg::Codec::footerSize <= log.size()) {
        const auto byte = [&](qsizetype i) { return static_cast<quint8>(log[at + i]); };
        const bool little = byte(0) == 0x54 && byte(1) == 0xFE;
        const int payload = little ? byte(4) | (byte(5) << 8) : (byte(4) << 8) | byte(5);
        const qsizetype length = msg::Codec::headerSize + payload + msg::Codec::footerSize;
        if (at + length > log.size())
            break;
        packets.emplace_back(log.constData() + at, length);
        at += length;
    }
    EXPECT_EQ(at, log.size()) << "the log ends inside a packet";
    return packets;
}

transport::ImcUdpConfig unboundConfig(quint16 systemId = 0x4001)
{
    transport::ImcUdpConfig config;
    config.port = 0;
    config.discovery = false;
    config.systemId = systemId;
    config.maxDatagramsPerSecond = 0; // a log replay, not a network
    return config;
}

msg::Message make(const char *abbrev, quint16 src, quint8 ent = 0xFF)
{
    msg::Message m(test::shippedSchema()->byAbbrev(QString::fromLatin1(abbrev)));
    m.header.src = src;
    m.header.srcEnt = ent;
    m.header.timestamp = 1700000000.0;
    return m;
}

QByteArray encode(const msg::Message &m)
{
    return *msg::Codec(test::shippedSchema()).encode(m);
}

} // namespace

TEST(ReceivePath, EveryPacketOfARealDuneLogIsDecodedIntoTheTree)
{
    NEPTUS_REQUIRE_FIXTURE(logPath, "dune-log/Data.lsf.gz");
    NEPTUS_REQUIRE_FIXTURE(definitions, "dune-log/IMC.xml.gz");
    const auto log = readFileMaybeGzip(logPath, qsizetype(64) << 20);
    ASSERT_TRUE(log) << log.error().toStdString();
    EXPECT_EQ(log->size(), 8'008'290);
    const std::vector<QByteArrayView> packets = packetsOf(*log);
    ASSERT_EQ(packets.size(), 179'142u);

    // The console as it would be with the vehicle's and the recording
    // console's definitions given (--defs-for 0x00d1 IMC.xml.gz, and 0x4001);
    // our own id is another, so the recording console's packets are not "ours".
    session::Console session(test::shippedSchema());
    ASSERT_TRUE(session.setDefinitionsFor(QStringLiteral("0x00d1"), definitions));
    ASSERT_TRUE(session.setDefinitionsFor(QStringLiteral("0x4001"), definitions));
    auto *imc = session.attachImc(
        std::make_unique<transport::ImcUdpTransport>(session.schemaSet(), unboundConfig(0x4ffe)));
    for (QByteArrayView packet : packets)
        imc->receive(packet, QHostAddress::LocalHost, 6002);

    EXPECT_EQ(imc->decodeErrors(), 0);
    const auto vehicle = session.linkStatistics().system(0x00D1);
    const auto console = session.linkStatistics().system(0x4001);
    EXPECT_EQ(vehicle.messages, 179'003u);
    EXPECT_EQ(console.messages, 139u);
    EXPECT_EQ(vehicle.decodeErrors + console.decodeErrors, 0u);
    EXPECT_EQ(vehicle.bytes + console.bytes, 8'008'290u);

    // Counts per type, as the log's README gives them.
    std::map<QString, quint64> counts;
    for (const auto &system : {vehicle, console}) {
        for (const auto &type : system.types) {
            EXPECT_TRUE(type.known) << type.abbrev.toStdString();
            counts[type.abbrev] += type.count;
        }
    }
    EXPECT_EQ(counts.size(), 61u);
    const std::map<QString, quint64> expected{
        {QStringLiteral("ServoPosition"), 55'098}, {QStringLiteral("SimulatedState"), 13'775},
        {QStringLiteral("EulerAngles"), 13'775},   {QStringLiteral("AngularVelocity"), 13'775},
        {QStringLiteral("Acceleration"), 13'775},  {QStringLiteral("ControlParcel"), 10'981},
        {QStringLiteral("SetServoPosition"), 9'408}, {QStringLiteral("EntityState"), 6'713},
        {QStringLiteral("CpuUsage"), 6'165},       {QStringLiteral("EstimatedState"), 2'755},
        {QStringLiteral("PlanControlState"), 395}, {QStringLiteral("Heartbeat"), 275},
        {QStringLiteral("GpsFix"), 139},           {QStringLiteral("Announce"), 28},
        {QStringLiteral("LogBookEntry"), 16},      {QStringLiteral("PlanControl"), 2},
        {QStringLiteral("PlanDB"), 1},             {QStringLiteral("PlanSpecification"), 1},
        {QStringLiteral("Goto"), 1},               {QStringLiteral("StationKeeping"), 1},
    };
    for (const auto &[abbrev, count] : expected)
        EXPECT_EQ(counts[abbrev], count) << abbrev.toStdString();

    // In the tree, named as the vehicle announces itself, entities by their labels.
    tree::VariableTree &tree = session.tree();
    EXPECT_EQ(tree.systemName(0x00D1), QStringLiteral("lauv-simulator-1"));
    EXPECT_TRUE(tree.snapshot(tree.find(u"lauv-simulator-1/EstimatedState/depth")).present);
    EXPECT_TRUE(tree.snapshot(tree.find(u"lauv-simulator-1/PlanControlState/plan_id")).present);
    EXPECT_EQ(tree.snapshot(tree.find(u"lauv-simulator-1/PlanControlState/plan_id")).text, QStringLiteral("goto-and-wait"));
    EXPECT_TRUE(tree.snapshot(tree.find(u"lauv-simulator-1/PlanControl/type")).present);
}

TEST(ReceivePath, UndecodablePacketsAreCountedPerSystemAndRaiseALinkWarning)
{
    session::Console session(test::shippedSchema());
    auto *imc = session.attachImc(std::make_unique<transport::ImcUdpTransport>(session.schemaSet(), unboundConfig()));
    imc->receive(encode(make("Announce", 0x1f)), QHostAddress::LocalHost, 6002);
    session.tree().setSystemName(0x1f, QStringLiteral("lauv"));
    QByteArray damaged = encode(make("EstimatedState", 0x1f));
    damaged[30] = static_cast<char>(damaged[30] ^ 0x40); // the CRC no longer matches
    imc->receive(damaged, QHostAddress::LocalHost, 6002);
    imc->receive(QByteArray("not an IMC packet"), QHostAddress(QStringLiteral("127.0.0.9")), 7000);
    EXPECT_EQ(imc->decodeErrors(), 2);

    const auto lauv = session.linkStatistics().system(0x1f);
    EXPECT_EQ(lauv.decodeErrors, 1u);
    EXPECT_EQ(lauv.peer, QStringLiteral("127.0.0.1:6002"));
    EXPECT_TRUE(lauv.lastError.contains(QStringLiteral("CRC"), Qt::CaseInsensitive)) << lauv.lastError.toStdString();
    const auto stranger = session.linkStatistics().system(transport::LinkStatistics::unknownSystem);
    EXPECT_EQ(stranger.decodeErrors, 1u) << "no header, no system: still counted";

    session.tick();
    alarms::AlarmGraph &graph = session.alarmGraph();
    const auto link = graph.find(QStringLiteral("systems/lauv/link"));
    ASSERT_NE(link, alarms::AlarmGraph::noNode);
    EXPECT_EQ(graph.ownLevel(link), alarms::Warning);
    EXPECT_TRUE(graph.message(link).contains(QStringLiteral("127.0.0.1:6002"))) << graph.message(link).toStdString();
    const auto unknown = graph.find(QStringLiteral("links/unknown senders"));
    ASSERT_NE(unknown, alarms::AlarmGraph::noNode);
    EXPECT_EQ(graph.ownLevel(unknown), alarms::Warning);
    EXPECT_TRUE(graph.message(unknown).contains(QStringLiteral("127.0.0.9:7000")));
}

TEST(ReceivePath, ATypeTheDefinitionsLackIsShownCountedAndWarnedAbout)
{
    auto tiny = msg::Schema::load({test::sourcePath(QStringLiteral("tests/data/tiny-imc.xml"))});
    ASSERT_TRUE(tiny) << tiny.error().toString().toStdString();
    session::Console session(*tiny);
    auto *imc = session.attachImc(std::make_unique<transport::ImcUdpTransport>(session.schemaSet(), unboundConfig()));
    // ServoPosition (281) from a DUNE vehicle: the packet that crashed the console.
    const QByteArray servo = QByteArray::fromHex("54fe1901050000000040fc54d941d10025ffffff030000003f8463");
    for (int i = 0; i < 5; ++i)
        imc->receive(servo, QHostAddress::LocalHost, 6002);
    EXPECT_EQ(imc->decodeErrors(), 0);
    const tree::VariableTree &tree = session.tree();
    const auto node = tree.find(u"0x00d1/Unknown(281)");
    ASSERT_NE(node, tree::noNode);
    EXPECT_TRUE(tree.snapshot(node).text.startsWith(QStringLiteral("unknown type 281, 5 bytes · 5 received")))
        << tree.snapshot(node).text.toStdString();
    const auto stats = session.linkStatistics().system(0x00D1);
    EXPECT_EQ(stats.unknownTypes(), 1);
    EXPECT_EQ(stats.bytes, 5u * static_cast<quint64>(servo.size()));

    session.tick();
    const auto definitions = session.alarmGraph().find(QStringLiteral("systems/0x00d1/definitions"));
    ASSERT_NE(definitions, alarms::AlarmGraph::noNode);
    EXPECT_EQ(session.alarmGraph().ownLevel(definitions), alarms::Warning);
    EXPECT_TRUE(session.alarmGraph().message(definitions).contains(QStringLiteral("lack (id 281)")))
        << session.alarmGraph().message(definitions).toStdString();
    EXPECT_TRUE(session.dumpTree().contains(QStringLiteral("0x00d1/Unknown(281)\tunknown type 281")));
}

TEST(ReceivePath, AVehicleOfAnotherImcRevisionIsDecodedAndCommandedInItsOwn)
{
    // DUNE numbers some messages differently: here Abort is 9550 and a
    // message of its own, 9001, is what our definitions lack.
    QByteArray theirs = R"(<messages name="IMC" version="5.4.30">
      <header>
        <field name="Synchronization Number" abbrev="sync" type="uint16_t" value="0xFE54" fixed="true"/>
        <field name="Message Identification Number" abbrev="mgid" type="uint16_t"/>
        <field name="Message size" abbrev="size" type="uint16_t"/>
        <field name="Time stamp" abbrev="timestamp" type="fp64_t"/>
        <field name="Source Address" abbrev="src" type="uint16_t"/>
        <field name="Source Entity" abbrev="src_ent" type="uint8_t"/>
        <field name="Destination Address" abbrev="dst" type="uint16_t"/>
        <field name="Destination Entity" abbrev="dst_ent" type="uint8_t"/>
      </header>
      <footer><field name="Check Sum" abbrev="crc16" type="uint16_t"/></footer>
      <message id="151" name="Announce" abbrev="Announce">
        <field name="System Name" abbrev="sys_name" type="plaintext"/>
        <field name="System Type" abbrev="sys_type" type="uint8_t"/>
        <field name="Control Owner" abbrev="owner" type="uint16_t"/>
        <field name="Latitude" abbrev="lat" type="fp64_t"/>
        <field name="Longitude" abbrev="lon" type="fp64_t"/>
        <field name="Height" abbrev="height" type="fp32_t"/>
        <field name="Services" abbrev="services" type="plaintext"/>
      </message>
      <message id="9001" name="Thing" abbrev="Thing"><field name="Value" abbrev="value" type="fp32_t"/></message>
      <message id="9550" name="Abort" abbrev="Abort"/>
    </messages>)";
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("IMC.xml"));
    QFile out(file);
    ASSERT_TRUE(out.open(QIODevice::WriteOnly));
    out.write(theirs);
    out.close();
    auto other = msg::Schema::load({file});
    ASSERT_TRUE(other) << other.error().toString().toStdString();

    session::Console session(test::shippedSchema());
    ASSERT_TRUE(session.setDefinitionsFor(QStringLiteral("lauv-old"), file)) << "by the name it announces";
    EXPECT_FALSE(session.setDefinitionsFor(QStringLiteral("0x22"), dir.filePath(QStringLiteral("missing.xml"))));
    auto *imc = session.attachImc(std::make_unique<transport::ImcUdpTransport>(session.schemaSet(), unboundConfig()));
    const msg::Codec theirCodec(*other);
    msg::Message announce((*other)->byAbbrev(u"Announce"));
    announce.header.src = 0x22;
    announce.setBytes(announce.def()->indexOf(u"sys_name"), "lauv-old");
    announce.setBytes(announce.def()->indexOf(u"services"), "imc+info://0.0.0.0/version/5.4.30;imc+udp://127.0.0.1:6010/");
    imc->receive(*theirCodec.encode(announce), QHostAddress::LocalHost, 6010);
    msg::Message thing((*other)->byAbbrev(u"Thing"));
    thing.header.src = 0x22;
    thing.setNumber(0, 2.5);
    imc->receive(*theirCodec.encode(thing), QHostAddress::LocalHost, 6010);

    EXPECT_EQ(imc->decodeErrors(), 0);
    EXPECT_EQ(imc->announcedVersion(0x22), QStringLiteral("5.4.30"));
    const tree::VariableTree &tree = session.tree();
    EXPECT_DOUBLE_EQ(tree.snapshot(tree.find(u"lauv-old/Thing/value")).value.toDouble(), 2.5)
        << "decoded with its own definitions, not as an unknown 9001";

    // Our Abort (550) goes out as theirs (9550).
    const auto converted = session.schemaSet()->forSystem(0x22, make("Abort", 0x4001));
    ASSERT_TRUE(converted) << converted.error().toStdString();
    EXPECT_EQ(converted->id(), 9550);
    const auto unconvertible = session.schemaSet()->forSystem(0x22, make("EstimatedState", 0x4001));
    ASSERT_FALSE(unconvertible);
    EXPECT_TRUE(unconvertible.error().contains(QStringLiteral("EstimatedState"))) << unconvertible.error().toStdString();
}

TEST(ReceivePath, AnAnnouncedImcVersionOtherThanOursIsAWarning)
{
    session::Console session(test::shippedSchema());
    auto *imc = session.attachImc(std::make_unique<transport::ImcUdpTransport>(session.schemaSet(), unboundConfig()));
    msg::Message announce = make("Announce", 0x30);
    announce.setBytes(announce.def()->indexOf(u"sys_name"), "old-asv");
    announce.setBytes(announce.def()->indexOf(u"services"), "dune://0.0.0.0/version/2019.01.0;imc+info://0.0.0.0/version/5.4.11");
    imc->receive(encode(announce), QHostAddress::LocalHost, 6011);
    const auto node = session.alarmGraph().find(QStringLiteral("systems/old-asv/definitions"));
    ASSERT_NE(node, alarms::AlarmGraph::noNode);
    EXPECT_EQ(session.alarmGraph().ownLevel(node), alarms::Warning);
    EXPECT_TRUE(session.alarmGraph().message(node).contains(QStringLiteral("announces IMC 5.4.11, ours is 5.4.31")))
        << session.alarmGraph().message(node).toStdString();
}

// Seen against a real DUNE (608 datagrams a second): the GUI thread stalled
// for 18 s, the host's queue filled, 483 datagrams were dropped unread and
// "input overload: 127.0.0.1 sent over 5000 datagrams a second" blamed the
// vehicle. Now the link decodes and records on a thread of its own: a GUI
// thread blocked for 20 s delays what it shows and loses nothing.
TEST(ReceivePath, AGuiThreadBlockedFor20SecondsLosesNothingAndBlamesNoVehicle)
{
    QTemporaryDir root;
    log::RecorderConfig recording;
    recording.root = root.path();
    recording.system = 0x4001;
    recording.definitionFiles = msg::Schema::filesIn(test::msgdefsDirectory());
    log::Recorder recorder(recording);
    ASSERT_TRUE(recorder.start());
    session::Console session(test::shippedSchema());
    session.setRecorder(&recorder);
    transport::ImcUdpConfig config;
    config.port = 0;
    config.discoveryPort = 0;
    ASSERT_TRUE(session.startImc(config));
    const quint16 port = session.imc()->port();

    // A vehicle streaming 600 datagrams a second, in bursts of 60 every 100 ms, for 21 s.
    const QByteArray packet = *msg::Codec(test::shippedSchema()).encode(make("EstimatedState", 0x23));
    std::atomic<int> sent = 0;
    std::thread vehicle([&] {
        QUdpSocket socket;
        const auto start = std::chrono::steady_clock::now();
        for (int burst = 0; burst < 210; ++burst) {
            std::this_thread::sleep_until(start + std::chrono::milliseconds(100 * burst));
            for (int i = 0; i < 60; ++i)
                if (socket.writeDatagram(packet, QHostAddress::LocalHost, port) == packet.size())
                    ++sent;
        }
    });
    std::this_thread::sleep_for(std::chrono::seconds(20)); // the GUI thread, blocked
    vehicle.join();
    ASSERT_GT(sent.load(), 12'000);
    EXPECT_TRUE(QTest::qWaitFor([&] { return session.linkStatistics().system(0x23).messages == quint64(sent.load()); }, 5000))
        << session.linkStatistics().system(0x23).messages << " of " << sent.load();
    EXPECT_EQ(session.imc()->droppedDatagrams(), 0u);
    QTest::qWait(1500); // a second for the overload report, had there been one
    session.imc()->forgetSilent();
    QCoreApplication::processEvents();
    for (const auto &alarm : session.alarmGraph().activeAlarms())
        EXPECT_FALSE(alarm.origin.startsWith(QStringLiteral("links/"))) << alarm.origin.toStdString() << ": "
                                                                         << alarm.message.toStdString();

    // Every one of them in the recording.
    const QString folder = recorder.status().folder;
    recorder.stop();
    auto logFile = log::LogFile::open(folder);
    ASSERT_TRUE(logFile) << logFile.error().toStdString();
    qint64 fromVehicle = 0;
    for (qsizetype i = 0; i < (*logFile)->count(); ++i)
        fromVehicle += (*logFile)->source(i) == 0x23;
    EXPECT_EQ(fromVehicle, sent.load());
}
