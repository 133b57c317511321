// MAVLink vehicles end to end: neptus-sim playing ArduRover (sim::MavlinkPeer,
// which answers as ArduPilot's source and the fixtures say) as a process of
// its own, met by the console program over UDP on loopback (its tree, its
// database, its mavlink.tlog beside Data.lsf); by the console's own wiring
// (ConsoleSession) over TCP; and in a mixed team with an IMC AUV and a DDS
// ASV, each running its plan at once.
#include "core/DataFiles.h"
#include "database/Database.h"
#include "messages/MavlinkCodec.h"
#include "mission/MissionXml.h"
#include "qmlmodels/ConsoleSession.h"
#include "session/OperationsFeed.h"
#include "transport/mavlink/MavlinkTransport.h"
#include "web/LiveServer.h"

#include "Missions.h"
#include "Paths.h"
#include "Ports.h"
#include "QtPrinters.h"
#include "Schemas.h"
#include "Tlog.h"
#include "PlanRun.h"

#include <QDirIterator>
#include <QFile>
#include <QNetworkAccessManager>
#include <QNetworkReply>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <QUdpSocket>

#include <gtest/gtest.h>

using namespace neptus;
using namespace Qt::StringLiterals;
using namespace neptus::test;

namespace {

struct Program
{
    QProcess process;
    QByteArray output;
    void start(const QString &program, const QStringList &arguments, const char *ready)
    {
        process.setProcessChannelMode(QProcess::MergedChannels);
        QObject::connect(&process, &QProcess::readyRead, [this] { output += process.readAll(); });
        process.start(programPath(program), arguments);
        ASSERT_TRUE(process.waitForStarted(5000));
        ASSERT_TRUE(QTest::qWaitFor([&] { return output.contains(ready); }, 15000)) << output.constData();
    }
    ~Program()
    {
        if (process.state() != QProcess::NotRunning) {
            process.kill();
            process.waitForFinished(5000);
        }
    }
};

QString firstFile(const QString &root, const QString &name)
{
    QDirIterator it(root, {name}, QDir::Files, QDirIterator::Subdirectories);
    return it.hasNext() ? it.next() : QString();
}

} // namespace

TEST(Mavlink, TheConsoleProgramMeetsAnArduRoverProcessRecordsItsFramesAndWritesItToTheDatabase)
{
    QTemporaryDir dir;
    const quint16 port = freeUdpPort();
    Program boat, console;
    boat.start(u"neptus-sim"_s, {u"--mavlink"_s, u"127.0.0.1:%1"_s.arg(port)}, "talking to");
    const QString tree = dir.filePath(u"tree.txt"_s), logs = dir.filePath(u"logs"_s);
    console.start(u"neptus"_s, {u"--console"_s, sourcePath(u"qml/consoles/Inspector.qml"_s), u"--imc-port"_s, u"0"_s,
                                u"--dds-domain"_s, u"-1"_s, u"--mavlink"_s, u"udp:%1"_s.arg(port), u"--log-dir"_s, logs,
                                u"--dump-tree"_s, tree, u"--quit-after"_s, u"7000"_s},
                  "neptus: MAVLink/UDP on");
    ASSERT_TRUE(console.process.waitForFinished(20000)) << console.output.constData();
    EXPECT_EQ(console.process.exitCode(), 0) << console.output.constData();

    // Its tree: the vehicle's own messages and what they mean in the console's words.
    QFile dump(tree);
    ASSERT_TRUE(dump.open(QIODevice::ReadOnly)) << console.output.constData();
    const QString text = QString::fromUtf8(dump.readAll());
    EXPECT_TRUE(text.contains(u"ardurover-1/HEARTBEAT/custom_mode"_s)) << text.left(2000).toStdString();
    EXPECT_TRUE(text.contains(u"ardurover-1/GLOBAL_POSITION_INT/lat"_s));
    EXPECT_TRUE(text.contains(u"ardurover-1/EstimatedState/lat"_s));

    // What was said both ways, in a tlog pymavlink and QGroundControl read.
    const QString tlog = firstFile(logs, u"mavlink.tlog"_s);
    ASSERT_FALSE(tlog.isEmpty()) << "no mavlink.tlog under " << logs.toStdString();
    EXPECT_TRUE(QFile::exists(QFileInfo(tlog).dir().filePath(u"Data.lsf"_s)));
    const auto records = readTlog(tlog);
    ASSERT_GT(records.size(), 20u);
    int fromBoat = 0, fromConsole = 0;
    for (const TlogRecord &r : records) {
        fromBoat += r.system() == 1;
        fromConsole += r.system() == 255;
    }
    EXPECT_GT(fromBoat, 10);
    EXPECT_GT(fromConsole, 3) << "the console's heartbeats and stream requests";
    EXPECT_LE(records.front().usec, records.back().usec);

    // Its database (beside the logs): the boat by name, and its track.
    const auto location = db::Location::parse(logs + u"/operation.db"_s);
    ASSERT_TRUE(location.has_value());
    auto reader = db::Reader::open(*location);
    ASSERT_TRUE(reader.has_value()) << reader.error().toStdString();
    const auto systems = (*reader)->systems();
    ASSERT_TRUE(systems.has_value());
    EXPECT_TRUE(std::any_of(systems->begin(), systems->end(), [](const auto &s) { return s.name == u"ardurover-1"_s; }));
    EXPECT_GT((*reader)->track(u"ardurover-1"_s, 0, std::numeric_limits<qint64>::max())->size(), 3u);
}

// As with ArduPilot's SITL: the vehicle listens on TCP and the console connects.
TEST(Mavlink, OverTcpAPlanIsUploadedReadBackAndTheBoatStopped)
{
    const quint16 port = closedTcpPort(); // free for the boat to listen on
    Program boat;
    boat.start(u"neptus-sim"_s, {u"--mavlink"_s, u"tcp:%1"_s.arg(port), u"--time-factor"_s, u"10"_s}, "listening on TCP");
    ConsoleSession session(shippedSchema());
    const auto config = transport::parseMavlinkLink(u"tcp:127.0.0.1:%1"_s.arg(port));
    ASSERT_TRUE(config.has_value());
    ASSERT_TRUE(session.console().startMavlink(*config).has_value());
    auto &desk = session.planDesk();
    ASSERT_TRUE(desk.openMission(sourcePath(u"docs/examples/leixoes.xml"_s)).has_value());
    ASSERT_TRUE(QTest::qWaitFor([&] { return desk.isMavlink(u"ardurover-1"_s); }, 10000)) << boat.output.constData();
    const auto log = [&] { return desk.log(u"ardurover-1"_s).join(u'\n'); };
    ASSERT_TRUE(desk.send(u"ardurover-1"_s, u"harbour-loop"_s).has_value());
    ASSERT_TRUE(QTest::qWaitFor([&] { return log().contains(u"harbour-loop sent: the vehicle holds its"_s); }, 15000)) << log().toStdString();
    EXPECT_EQ(desk.sync(u"ardurover-1"_s, u"harbour-loop"_s), plans::Sync::Same);
    ASSERT_TRUE(desk.start(u"ardurover-1"_s, u"harbour-loop"_s).has_value());
    ASSERT_TRUE(QTest::qWaitFor([&] { return log().contains(u"harbour-loop started"_s); }, 10000)) << log().toStdString();
    ASSERT_TRUE(desk.stop(u"ardurover-1"_s).has_value());
    ASSERT_TRUE(QTest::qWaitFor([&] { return log().contains(u"harbour-loop stopped"_s); }, 10000)) << log().toStdString();
}

// Signing on at both ends (the console requires it; the boat drops what is not signed
// with the key, as ArduPilot does on a telemetry link): an unsigned impostor that tells
// the boat to arm and go AUTO, to clear its mission, and tells the console the boat is
// armed in AUTO, changes nothing; the console's own signed commands still work.
TEST(Mavlink, WithSigningOnAnUnsignedImpostorsCommandsAndHeartbeatsChangeNothing)
{
    QTemporaryDir dir;
    const QString keyFile = dir.filePath(u"boat.key"_s);
    {
        QFile key(keyFile);
        ASSERT_TRUE(key.open(QIODevice::WriteOnly) && key.write("douro harbour boat\n") > 0);
    }
    const quint16 port = freeUdpPort();
    Program boat;
    boat.start(u"neptus-sim"_s, {u"--mavlink"_s, u"127.0.0.1:%1"_s.arg(port), u"--mavlink-key"_s, keyFile, u"--time-factor"_s, u"10"_s},
               "talking to");
    ASSERT_TRUE(boat.output.contains("signing and taking only signed frames")) << boat.output.constData();
    const QRegularExpressionMatch at = QRegularExpression(u"on 127\\.0\\.0\\.1:(\\d+),"_s).match(QString::fromUtf8(boat.output));
    ASSERT_TRUE(at.hasMatch()) << boat.output.constData();
    const quint16 boatPort = quint16(at.captured(1).toUInt());

    ConsoleSession session(shippedSchema());
    auto config = transport::parseMavlinkLink(u"udp:%1"_s.arg(port));
    ASSERT_TRUE(config.has_value());
    config->signingKey = *transport::mavlinkKeyFromFile(keyFile);
    config->requireSigning = true;
    ASSERT_TRUE(session.console().startMavlink(*config).has_value());
    transport::MavlinkTransport &link = *session.console().mavlinkLinks().front();
    auto &desk = session.planDesk();
    ASSERT_TRUE(desk.openMission(sourcePath(u"docs/examples/leixoes.xml"_s)).has_value());
    ASSERT_TRUE(QTest::qWaitFor([&] { return desk.isMavlink(u"ardurover-1"_s); }, 10000)) << boat.output.constData();
    const quint16 id = config->idBase + 1;
    const auto log = [&] { return desk.log(u"ardurover-1"_s).join(u'\n'); };
    ASSERT_TRUE(desk.send(u"ardurover-1"_s, u"harbour-loop"_s).has_value());
    ASSERT_TRUE(QTest::qWaitFor([&] { return log().contains(u"harbour-loop sent: the vehicle holds its"_s); }, 15000)) << log().toStdString();
    EXPECT_EQ(link.mode(id), std::pair(u"MANUAL"_s, false));

    // The impostor: unsigned frames as a ground station to the boat, and as the boat to the console.
    msg::MavlinkCodec codec(mavlinkSchema());
    QUdpSocket impostor;
    ASSERT_TRUE(impostor.bind(QHostAddress::LocalHost, 0));
    const auto make = [&](const char *name, std::initializer_list<std::pair<const char *, double>> fields, quint8 system) {
        msg::Message m(mavlinkSchema()->byAbbrev(QString::fromLatin1(name)));
        for (const auto &[field, value] : fields)
            m.setNumber(m.def()->indexOf(QString::fromLatin1(field)), value);
        msg::MavlinkCodec::Options options;
        options.system = system;
        options.component = 1;
        return *codec.encode(m, options);
    };
    const quint64 refusedBefore = link.refusedFrames();
    for (int round = 0; round < 3; ++round) {
        impostor.writeDatagram(make("COMMAND_LONG", {{"target_system", 1}, {"target_component", 1}, {"command", 400}, {"param1", 1}}, 255),
                               QHostAddress::LocalHost, boatPort); // arm
        impostor.writeDatagram(make("COMMAND_LONG", {{"target_system", 1}, {"target_component", 1}, {"command", 176}, {"param1", 1},
                                                     {"param2", 10}}, 255), QHostAddress::LocalHost, boatPort); // AUTO
        impostor.writeDatagram(make("MISSION_CLEAR_ALL", {{"target_system", 1}, {"target_component", 1}}, 255), QHostAddress::LocalHost,
                               boatPort);
        impostor.writeDatagram(make("HEARTBEAT", {{"type", 11}, {"autopilot", 3}, {"base_mode", 0x81}, {"custom_mode", 10},
                                                  {"system_status", 4}, {"mavlink_version", 3}}, 1),
                               QHostAddress::LocalHost, port); // "armed, in AUTO"
        QTest::qWait(400);
    }
    EXPECT_GE(link.refusedFrames(), refusedBefore + 3) << "the impostor's heartbeats were read";
    QTest::qWait(1000); // the boat's own heartbeats, a second of them
    EXPECT_EQ(link.mode(id), std::pair(u"MANUAL"_s, false)) << "the boat obeyed the impostor, or the console believed it";
    ASSERT_TRUE(desk.refresh(u"ardurover-1"_s).has_value());
    ASSERT_TRUE(QTest::qWaitFor([&] { return desk.fetched(u"ardurover-1"_s); }, 10000)) << log().toStdString();
    EXPECT_EQ(desk.sync(u"ardurover-1"_s, u"harbour-loop"_s), plans::Sync::Same) << "the impostor cleared the mission";

    // The console's own, signed, commands are obeyed.
    ASSERT_TRUE(desk.start(u"ardurover-1"_s, u"harbour-loop"_s).has_value());
    ASSERT_TRUE(QTest::qWaitFor([&] { return log().contains(u"harbour-loop started"_s); }, 10000)) << log().toStdString();
    EXPECT_EQ(link.mode(id), std::pair(u"AUTO"_s, true));
    ASSERT_TRUE(desk.stop(u"ardurover-1"_s).has_value());
    ASSERT_TRUE(QTest::qWaitFor([&] { return log().contains(u"harbour-loop stopped"_s); }, 10000)) << log().toStdString();
}

// The paper's team in one console: an AUV on IMC, an ASV on DDS and an
// ArduRover boat on MAVLink, each given its plan of docs/examples/leixoes.xml
// at once; the plan logs, the database and the web page's state show all three.
TEST(Mavlink, AMixedTeamRunsItsPlansAtOnceAndTheDatabaseAndWebPageShowAllThree)
{
    QTemporaryDir dir;
    const quint16 mavlinkPort = freeUdpPort();
    Program auv, asv, boat;
    auv.start(u"neptus-sim"_s, {u"--id"_s, u"0x1f"_s, u"--name"_s, u"lauv-sim-1"_s, u"--port"_s, u"16190"_s, u"--time-factor"_s, u"30"_s},
              "on 127.0.0.1");
    asv.start(u"neptus-sim"_s, {u"--dds"_s, u"--dds-domain"_s, u"23"_s, u"--id"_s, u"0x20"_s, u"--name"_s, u"caravela-sim"_s, u"--kind"_s,
                                u"asv"_s, u"--port"_s, u"16191"_s, u"--time-factor"_s, u"30"_s},
              "on 127.0.0.1");
    boat.start(u"neptus-sim"_s, {u"--mavlink"_s, u"127.0.0.1:%1"_s.arg(mavlinkPort), u"--time-factor"_s, u"10"_s}, "talking to");

    ConsoleSession session(shippedSchema());
    session::Console &console = session.console();
    const db::Location location = *db::Location::parse(dir.filePath(u"operation.db"_s));
    db::Writer writer(location, {dir.filePath(u"spool"_s), 512ll << 20, 250, 1000, u"mixed"_s, {}, u"tst_e2e_mavlink"_s});
    session::OperationsFeed feed(console, &writer);
    web::WebConfig webConfig;
    webConfig.port = 0;
    webConfig.pageDir = dataPath(u"web"_s);
    webConfig.history = location;
    web::LiveServer page(feed, webConfig);
    ASSERT_TRUE(page.start().has_value());
    ASSERT_TRUE(console.startImc(imcTo({16190})).has_value());
    ASSERT_TRUE(console.startDds({23, {}, 0x4001}).has_value());
    transport::MavlinkConfig mavlink;
    mavlink.port = mavlinkPort;
    ASSERT_TRUE(console.startMavlink(mavlink).has_value());
    auto &desk = session.planDesk();
    ASSERT_TRUE(desk.openMission(sourcePath(u"docs/examples/leixoes.xml"_s)).has_value());
    ASSERT_TRUE(QTest::qWaitFor([&] { return heard(console.tree(), u"lauv-sim-1"_s) && heard(console.tree(), u"caravela-sim"_s)
                                              && desk.isMavlink(u"ardurover-1"_s); }, 20000));

    const std::pair<const char *, const char *> plans[] = {{"lauv-sim-1", "survey"}, {"caravela-sim", "patrol"}, {"ardurover-1", "harbour-loop"}};
    const auto log = [&](const char *vehicle) { return desk.log(QString::fromLatin1(vehicle)).join(u'\n'); };
    for (const auto &[vehicle, plan] : plans) {
        const QString name = QString::fromLatin1(vehicle), id = QString::fromLatin1(plan);
        ASSERT_TRUE(desk.refresh(name).has_value());
        ASSERT_TRUE(QTest::qWaitFor([&] { return desk.fetched(name); }, 10000)) << vehicle;
        ASSERT_TRUE(desk.send(name, id).has_value()) << vehicle;
    }
    for (const auto &[vehicle, plan] : plans) {
        const QString name = QString::fromLatin1(vehicle), id = QString::fromLatin1(plan);
        ASSERT_TRUE(QTest::qWaitFor([&] { return desk.sync(name, id) == plans::Sync::Same; }, 15000)) << vehicle << "\n" << log(vehicle).toStdString();
        const auto started = desk.start(name, id);
        ASSERT_TRUE(started.has_value()) << vehicle << ": " << started.error().toStdString();
    }
    for (const auto &[vehicle, plan] : plans)
        ASSERT_TRUE(QTest::qWaitFor([&] { return log(vehicle).contains(QString::fromLatin1(plan) + u" started"_s); }, 15000))
            << vehicle << "\n" << log(vehicle).toStdString();
    ASSERT_TRUE(QTest::qWaitFor([&] { return log("ardurover-1").contains(u"harbour-loop completed"_s); }, 60000)) << log("ardurover-1").toStdString();

    // The map (Map2D draws session.tracks): each of the three off Leixões, with a trail.
    for (const auto &[vehicle, plan] : plans) {
        const QVariantMap at = session.tracks()->latest(QString::fromLatin1(vehicle));
        ASSERT_FALSE(at.isEmpty()) << vehicle << " is not on the map";
        EXPECT_NEAR(at.value(u"lat"_s).toDouble(), 41.1705, 0.01) << vehicle;
        EXPECT_NEAR(at.value(u"lon"_s).toDouble(), -8.7150, 0.01) << vehicle;
        EXPECT_GT(session.tracks()->count(QString::fromLatin1(vehicle)), 5) << vehicle << " has no trail";
    }

    // The database: the three systems by name, and each plan's start.
    ASSERT_TRUE(writer.flush(5000));
    auto reader = db::Reader::open(location);
    ASSERT_TRUE(reader.has_value()) << reader.error().toStdString();
    const auto systems = (*reader)->systems();
    const auto events = (*reader)->planEvents(0, std::numeric_limits<qint64>::max());
    ASSERT_TRUE(systems.has_value() && events.has_value());
    for (const auto &[vehicle, plan] : plans) {
        EXPECT_TRUE(std::any_of(systems->begin(), systems->end(), [&](const auto &s) { return s.name == QLatin1StringView(vehicle); })) << vehicle;
        EXPECT_TRUE(std::any_of(events->begin(), events->end(), [&](const auto &e) {
            return e.system == QLatin1StringView(vehicle) && e.plan == QLatin1StringView(plan) && e.event == u"started"_s;
        })) << vehicle << " " << plan;
    }
    EXPECT_TRUE(std::any_of(events->begin(), events->end(), [](const auto &e) {
        return e.system == u"ardurover-1"_s && e.plan == u"harbour-loop"_s && e.event == u"completed"_s; // as for an IMC vehicle
    }));

    // The web page's state: the three, each with a position.
    QNetworkAccessManager http;
    QNetworkReply *reply = http.get(QNetworkRequest(QUrl(page.url() + u"api/state"_s)));
    ASSERT_TRUE(QTest::qWaitFor([&] { return reply->isFinished(); }, 10000));
    const QByteArray state = reply->readAll();
    reply->deleteLater();
    for (const auto &[vehicle, plan] : plans)
        EXPECT_TRUE(state.contains(QByteArray("\"") + vehicle + "\"")) << vehicle << ": " << state.left(600).constData();
}
