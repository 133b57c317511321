// The MAVLink link: vehicles met by their HEARTBEAT and shown in the
// console's words, against what real ArduPilot vehicles sent
// (../shared/fixtures/mavlink) and against vehicles played here on loopback
// (UDP and TCP): streams and parameters asked for, commands only to the
// address a vehicle was heard from, signing.
#include "transport/mavlink/MavlinkTransport.h"

#include "runs/PlanRuns.h"
#include "session/Console.h"

#include "Fixtures.h"
#include "QtPrinters.h"
#include "Schemas.h"
#include "Tlog.h"

#include <QCoreApplication>
#include <QNetworkDatagram>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>
#include <QUdpSocket>

#include <gtest/gtest.h>

#include <map>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

using namespace neptus;
using namespace neptus::transport;
using namespace Qt::StringLiterals;

namespace {

using test::mavlinkSchema;

msg::Message make(const char *name, std::initializer_list<std::pair<const char *, double>> fields = {})
{
    msg::Message m(mavlinkSchema()->byAbbrev(QString::fromLatin1(name)));
    for (const auto &[field, value] : fields) {
        const int i = m.def()->indexOf(QString::fromLatin1(field));
        EXPECT_GE(i, 0) << name << "." << field;
        if (i >= 0)
            m.setNumber(i, value);
    }
    return m;
}

msg::Message heartbeat(double type, double customMode, bool armed, double autopilot = 3)
{
    return make("HEARTBEAT", {{"type", type}, {"autopilot", autopilot}, {"custom_mode", customMode},
                              {"base_mode", armed ? 0x80 | 0x01 : 0x01}, {"system_status", 4}, {"mavlink_version", 3}});
}

// A MAVLink vehicle (or someone claiming to be one) on a loopback UDP port.
struct Peer
{
    explicit Peer(quint8 system = 1)
        : codec(mavlinkSchema())
        , system(system)
    {
        EXPECT_TRUE(socket.bind(QHostAddress::LocalHost, 0));
        QObject::connect(&socket, &QUdpSocket::readyRead, [this] {
            while (socket.hasPendingDatagrams()) {
                const QByteArray datagram = socket.receiveDatagram().data();
                raw.push_back(datagram);
                msg::MavlinkFrame header;
                if (auto m = codec.decode(datagram, &header)) {
                    got.push_back(*m);
                    headers.push_back(header);
                }
            }
        });
    }
    QByteArray frame(const msg::Message &m, msg::MavlinkSigning *signing = nullptr)
    {
        msg::MavlinkCodec::Options options;
        options.system = system;
        options.component = 1;
        options.sequence = sequence++;
        options.signing = signing;
        return *codec.encode(m, options);
    }
    void send(const QByteArray &frame, quint16 port) { socket.writeDatagram(frame, QHostAddress::LocalHost, port); }
    void send(const msg::Message &m, quint16 port, msg::MavlinkSigning *signing = nullptr) { send(frame(m, signing), port); }
    std::vector<msg::Message> of(const char *type) const
    {
        std::vector<msg::Message> out;
        for (const msg::Message &m : got)
            if (m.abbrev() == QLatin1StringView(type))
                out.push_back(m);
        return out;
    }

    QUdpSocket socket;
    msg::MavlinkCodec codec;
    quint8 system;
    quint8 sequence = 0;
    std::vector<msg::Message> got;
    std::vector<msg::MavlinkFrame> headers;
    std::vector<QByteArray> raw;
};

MavlinkConfig loopback()
{
    MavlinkConfig config;
    config.port = 0;
    config.heartbeatMs = 100;
    return config;
}

std::unique_ptr<MavlinkTransport> link(MavlinkConfig config = loopback())
{
    auto l = std::make_unique<MavlinkTransport>(mavlinkSchema(), test::shippedSchema(), config);
    auto started = l->start();
    EXPECT_TRUE(started) << started.error().toStdString();
    return l;
}

// What a fixture vehicle meant, as the console took it: the mode and arming
// changes, the plan events, the alarms its words raised, the tree.
struct Replayed
{
    QStringList modes;
    QStringList arming;
    std::vector<plans::PlanRuns::Event> plan;
    QStringList warnings; // statustext alarms, as raised
    double maxDepth = 0;
    QString parameters;
    int derivedStates = 0;
};

Replayed replay(session::Console &console, ManualClock &clock, const QString &path)
{
    Replayed out;
    MavlinkConfig config;
    config.clock = &clock;
    auto *l = console.attachMavlink(std::make_unique<MavlinkTransport>(console.mavlinkSchema(), console.sharedSchema(), config));
    plans::PlanRuns runs;
    QObject::connect(l, &MavlinkTransport::derived, [&](const msg::Message &m) {
        const QString type = m.abbrev();
        if (type == u"AutopilotMode" && (out.modes.isEmpty() || out.modes.last() != m.text(u"mode")))
            out.modes << m.text(u"mode");
        else if (type == u"ArmingState") {
            const QString state = m.integer(u"state") == 0 ? u"armed"_s : u"disarmed"_s;
            if (out.arming.isEmpty() || out.arming.last() != state)
                out.arming << state;
        } else if (type == u"EstimatedState") {
            out.maxDepth = std::max(out.maxDepth, m.number(u"depth"));
            ++out.derivedStates;
        } else if (type == u"EntityState" && m.header.srcEnt == 14) {
            out.parameters = m.text(u"description");
        }
        for (auto &e : runs.observe(m, clock.now().toMSecsSinceEpoch()))
            out.plan.push_back(e);
    });
    const auto records = test::readTlog(path);
    EXPECT_FALSE(records.empty()) << path.toStdString();
    for (const auto &r : records) {
        clock.set(QDateTime::fromMSecsSinceEpoch(r.usec / 1000, QTimeZone::UTC));
        if (r.system() != 1)
            continue; // the ground station's own frames
        l->receive(r.frame, QHostAddress::LocalHost, 14551);
        l->service();
        QCoreApplication::processEvents(); // STATUSTEXT alarms are raised on this thread
        const auto node = console.alarmGraph().find(u"systems/%1/statustext"_s.arg(console.tree().systemName(0xEA01)));
        if (node != alarms::AlarmGraph::noNode && console.alarmGraph().ownLevel(node) >= alarms::Warning) {
            const QString said = console.alarmGraph().message(node);
            if (out.warnings.isEmpty() || out.warnings.last() != said)
                out.warnings << said;
        }
    }
    return out;
}

} // namespace

// ArduRover on a motorboat (fixtures/mavlink/boat-mission.tlog): found,
// named by its type, shown in the console's words, its arming refusals in
// its own words, its mission followed to "completed", its parameters read.
TEST(MavlinkLink, ARealArduRoverBoatIsShownInTheConsolesWords)
{
    NEPTUS_REQUIRE_FIXTURE(path, "mavlink/boat-mission.tlog");
    ManualClock clock;
    session::Console console(test::shippedSchema(), &clock);
    const Replayed r = replay(console, clock, path);

    EXPECT_EQ(console.tree().systemName(0xEA01), u"ardurover-1"_s);
    // README: INITIALISING -> MANUAL, then AUTO, then HOLD; armed at ~43.8, disarmed at ~144.
    EXPECT_EQ(r.modes, (QStringList{u"INITIALISING"_s, u"MANUAL"_s, u"AUTO"_s, u"HOLD"_s}));
    EXPECT_EQ(r.arming, (QStringList{u"disarmed"_s, u"armed"_s, u"disarmed"_s}));
    // The arming refusals are CRITICAL STATUSTEXTs: an alarm in the vehicle's words.
    ASSERT_FALSE(r.warnings.isEmpty());
    EXPECT_EQ(r.warnings.first(), u"Arm: Gyros inconsistent"_s) << r.warnings.join(u" | "_s).toStdString();
    EXPECT_TRUE(r.warnings.contains(u"PreArm: AHRS: not using configured AHRS type"_s));
    // The mission: running from arming in AUTO, completed at "Mission Complete".
    ASSERT_GE(r.plan.size(), 2u);
    EXPECT_EQ(r.plan.front().kind, plans::PlanRuns::Event::Kind::Started);
    EXPECT_EQ(r.plan.back().kind, plans::PlanRuns::Event::Kind::Ended);
    EXPECT_EQ(r.plan.back().outcome, plans::PlanRuns::Outcome::Completed);
    EXPECT_EQ(r.parameters, u"1235 parameters read"_s);
    EXPECT_EQ(r.derivedStates, 1291); // one EstimatedState per GLOBAL_POSITION_INT

    // The same variables an IMC vehicle fills, and the raw MAVLink beside them.
    const auto text = [&](const QString &path) {
        const auto node = console.tree().find(path);
        EXPECT_NE(node, tree::noNode) << path.toStdString();
        return node == tree::noNode ? QString() : console.tree().snapshot(node).text;
    };
    EXPECT_NEAR(text(u"ardurover-1/EstimatedState/lat"_s).toDouble() * 180 / M_PI, 41.1855, 0.001);
    EXPECT_FALSE(text(u"ardurover-1/FuelLevel/value"_s).isEmpty());
    EXPECT_EQ(text(u"ardurover-1/AutopilotMode/mode"_s), u"HOLD"_s);
    EXPECT_EQ(text(u"ardurover-1/Announce/sys_type"_s), u"USV"_s);
    EXPECT_FALSE(text(u"ardurover-1/HEARTBEAT/custom_mode"_s).isEmpty());
    EXPECT_FALSE(text(u"ardurover-1/GLOBAL_POSITION_INT/lat"_s).isEmpty());
    // Every frame of the vehicle counted as its traffic (the derived messages are not).
    EXPECT_EQ(console.linkStatistics().system(0xEA01).messages, 7619u);
    EXPECT_EQ(console.linkStatistics().system(0xEA01).link, u"MAVLink/UDP"_s);
}

// ArduSub (fixtures/mavlink/sub-dive.tlog): an underwater vehicle, its depth
// from its altitude below home, its mission complete although it stays in
// AUTO (ArduSub says so only with MISSION_CURRENT's mission_state).
TEST(MavlinkLink, ARealArduSubDiveIsAUuvWhoseMissionCompletesInAuto)
{
    NEPTUS_REQUIRE_FIXTURE(path, "mavlink/sub-dive.tlog");
    ManualClock clock;
    session::Console console(test::shippedSchema(), &clock);
    const Replayed r = replay(console, clock, path);

    EXPECT_EQ(console.tree().systemName(0xEA01), u"ardusub-1"_s);
    EXPECT_EQ(r.modes, (QStringList{u"MANUAL"_s, u"AUTO"_s, u"SURFACE"_s, u"ALT_HOLD"_s, u"MANUAL"_s}));
    EXPECT_NEAR(r.maxDepth, 4.97, 0.05); // README: about 4.96 m, at most 4.97 m
    ASSERT_GE(r.plan.size(), 2u);
    const auto ended = std::find_if(r.plan.begin(), r.plan.end(), [](const auto &e) { return e.kind == plans::PlanRuns::Event::Kind::Ended; });
    ASSERT_NE(ended, r.plan.end());
    EXPECT_EQ(ended->outcome, plans::PlanRuns::Outcome::Completed);
    const auto node = console.tree().find(u"ardusub-1/Announce/sys_type"_s);
    ASSERT_NE(node, tree::noNode);
    EXPECT_EQ(console.tree().snapshot(node).text, u"UUV"_s);
}

// A vehicle on UDP: met by its heartbeat, given the ground station's
// heartbeat, asked for its streams (again until acknowledged) and its
// parameters (missing ones asked again by index), with the progress.
TEST(MavlinkLink, AVehicleIsMetByItsHeartbeatAndAskedForStreamsAndParameters)
{
    Peer vehicle;
    auto l = link();
    QSignalSpy discovered(l.get(), &MavlinkTransport::systemDiscovered);
    QStringList parameterStates;
    QObject::connect(l.get(), &MavlinkTransport::derived, [&](const msg::Message &m) {
        if (m.abbrev() == u"EntityState" && m.header.srcEnt == 14)
            parameterStates << m.text(u"description");
    });
    vehicle.send(heartbeat(11, 10, false), l->port());
    ASSERT_TRUE(QTest::qWaitFor([&] { return discovered.size() == 1; }, 2000));
    EXPECT_EQ(discovered[0][0].toUInt(), 0xEA01u);
    EXPECT_EQ(discovered[0][1].toString(), u"ardurover-1"_s);

    // The ground station's heartbeat, the stream requests and the parameter list.
    const int streams = int(MavlinkConfig{}.streams.size());
    ASSERT_TRUE(QTest::qWaitFor([&] { return int(vehicle.of("COMMAND_LONG").size()) >= streams && !vehicle.of("PARAM_REQUEST_LIST").empty()
                                              && !vehicle.of("HEARTBEAT").empty(); }, 2000));
    const msg::Message gcs = vehicle.of("HEARTBEAT").front();
    EXPECT_EQ(gcs.integer(u"type"), 6); // MAV_TYPE_GCS
    EXPECT_EQ(gcs.integer(u"autopilot"), 8); // MAV_AUTOPILOT_INVALID
    EXPECT_EQ(vehicle.headers.front().system, 255);
    EXPECT_EQ(vehicle.headers.front().component, 190);
    for (const msg::Message &c : vehicle.of("COMMAND_LONG")) {
        EXPECT_EQ(c.integer(u"command"), 511); // SET_MESSAGE_INTERVAL
        EXPECT_EQ(c.integer(u"target_system"), 1);
        EXPECT_EQ(c.integer(u"target_component"), 1);
    }
    EXPECT_EQ(vehicle.of("COMMAND_LONG").front().number(u"param1"), 33); // GLOBAL_POSITION_INT first
    EXPECT_EQ(vehicle.of("COMMAND_LONG").front().number(u"param2"), 200000); // 5 Hz
    // All but one acknowledged: that one is asked again, the others not.
    for (int i = 0; i < streams - 1; ++i)
        vehicle.send(make("COMMAND_ACK", {{"command", 511}, {"result", 0}, {"target_system", 255}, {"target_component", 190}}), l->port());
    // Ten parameters, two of which do not come.
    for (int i = 0; i < 10; ++i) {
        if (i == 4 || i == 7)
            continue;
        msg::Message p = make("PARAM_VALUE", {{"param_value", i * 1.5}, {"param_count", 10}, {"param_index", i}});
        p.setBytes(p.def()->indexOf(u"param_id"), u"P%1"_s.arg(i).toLatin1());
        vehicle.send(p, l->port());
    }
    ASSERT_TRUE(QTest::qWaitFor([&] { return vehicle.of("PARAM_REQUEST_READ").size() >= 2; }, 3000));
    std::vector<int> asked;
    for (const msg::Message &m : vehicle.of("PARAM_REQUEST_READ"))
        asked.push_back(int(m.integer(u"param_index")));
    EXPECT_EQ(asked, (std::vector<int>{4, 7}));
    for (const int i : {4, 7}) {
        msg::Message p = make("PARAM_VALUE", {{"param_value", i * 1.5}, {"param_count", 10}, {"param_index", i}});
        p.setBytes(p.def()->indexOf(u"param_id"), u"P%1"_s.arg(i).toLatin1());
        vehicle.send(p, l->port());
    }
    ASSERT_TRUE(QTest::qWaitFor([&] { return !parameterStates.isEmpty() && parameterStates.last() == u"10 parameters read"_s; }, 2000))
        << parameterStates.join(u" | "_s).toStdString();
    EXPECT_EQ(l->parameters(0xEA01).at(u"P7"_s), 10.5);
    EXPECT_TRUE(parameterStates.first().startsWith(u"reading parameters"_s));
    // The unacknowledged stream was asked again (2 s later); the others were not.
    ASSERT_TRUE(QTest::qWaitFor([&] { return int(vehicle.of("COMMAND_LONG").size()) == streams + 1; }, 3000));
    QTest::qWait(300);
    EXPECT_EQ(int(vehicle.of("COMMAND_LONG").size()), streams + 1);
}

// Commands go only to the address a vehicle was heard from: a heartbeat
// from elsewhere changes neither where they go nor what the console shows,
// and is reported.
TEST(MavlinkLink, AHeartbeatFromAnotherAddressRedirectsNothing)
{
    Peer vehicle, impostor;
    auto l = link();
    QSignalSpy sources(l.get(), &MavlinkTransport::sourcesChanged);
    vehicle.send(heartbeat(11, 10, true), l->port());
    ASSERT_TRUE(QTest::qWaitFor([&] { return l->mode(0xEA01).first == u"AUTO"_s; }, 2000));
    impostor.send(heartbeat(11, 0, false), l->port()); // "MANUAL, disarmed"
    ASSERT_TRUE(QTest::qWaitFor([&] { return sources.size() == 1; }, 2000));
    EXPECT_EQ(sources[0][1].toStringList().size(), 2);
    EXPECT_EQ(sources[0][2].toString(), u"127.0.0.1:%1"_s.arg(vehicle.socket.localPort()));
    EXPECT_EQ(l->mode(0xEA01), std::make_pair(u"AUTO"_s, true));

    // Abort: the boat's abort mode (RTL, 11), to the vehicle only.
    msg::Message abort(test::shippedSchema()->byAbbrev(u"Abort"));
    ASSERT_TRUE(l->publish(0xEA01, abort));
    ASSERT_TRUE(QTest::qWaitFor([&] {
        for (const msg::Message &c : vehicle.of("COMMAND_LONG"))
            if (c.integer(u"command") == 176)
                return true;
        return false;
    }, 2000));
    for (const msg::Message &c : vehicle.of("COMMAND_LONG"))
        if (c.integer(u"command") == 176) {
            EXPECT_EQ(c.number(u"param1"), 1);
            EXPECT_EQ(c.number(u"param2"), 11); // RTL
        }
    QTest::qWait(300);
    EXPECT_TRUE(impostor.got.empty()) << impostor.got.size() << " frames reached the impostor";
    EXPECT_GT(l->refusedFrames(), 0u);
    // An IMC command without a MAVLink meaning is refused, saying why.
    msg::Message planControl(test::shippedSchema()->byAbbrev(u"PlanControl"));
    const auto refused = l->publish(0xEA01, planControl);
    ASSERT_FALSE(refused);
    EXPECT_TRUE(refused.error().contains(u"speaks MAVLink"_s)) << refused.error().toStdString();
}

// A signing link: unsigned or wrongly signed frames and replays are refused
// before anything is read; what the console sends is signed with the key.
TEST(MavlinkLink, OnASigningLinkOnlyFramesSignedWithTheKeyAreRead)
{
    const QByteArray key = QByteArray(32, '\x5a');
    MavlinkConfig config = loopback();
    config.signingKey = key;
    config.requireSigning = true;
    Peer vehicle, impostor;
    auto l = link(config);
    QSignalSpy discovered(l.get(), &MavlinkTransport::systemDiscovered);
    QSignalSpy refused(l.get(), &MavlinkTransport::refused);

    impostor.send(heartbeat(11, 10, true), l->port()); // unsigned
    msg::MavlinkSigning wrong{QByteArray(32, '\x01'), 0, msg::MavlinkSigning::now()};
    impostor.send(heartbeat(11, 10, true), l->port(), &wrong);
    ASSERT_TRUE(QTest::qWaitFor([&] { return l->refusedFrames() >= 2; }, 2000));
    EXPECT_EQ(discovered.size(), 0);

    msg::MavlinkSigning signing{key, 0, msg::MavlinkSigning::now()};
    const QByteArray auto1 = vehicle.frame(heartbeat(11, 10, true), &signing);
    vehicle.send(auto1, l->port());
    ASSERT_TRUE(QTest::qWaitFor([&] { return discovered.size() == 1; }, 2000));
    vehicle.send(heartbeat(11, 4, true), l->port(), &signing); // HOLD
    ASSERT_TRUE(QTest::qWaitFor([&] { return l->mode(0xEA01).first == u"HOLD"_s; }, 2000));
    const quint64 before = l->refusedFrames();
    vehicle.send(auto1, l->port()); // the AUTO heartbeat again, byte for byte
    ASSERT_TRUE(QTest::qWaitFor([&] { return l->refusedFrames() > before; }, 2000));
    EXPECT_EQ(l->mode(0xEA01).first, u"HOLD"_s);

    // What the console sends is signed, and verifies with the key.
    ASSERT_TRUE(QTest::qWaitFor([&] { return !vehicle.raw.empty(); }, 2000));
    for (const QByteArray &frame : vehicle.raw)
        EXPECT_TRUE(msg::MavlinkCodec::signatureValid(frame, key));
    EXPECT_GE(refused.size(), 1);
    EXPECT_EQ(refused.size(), 1) << "refusals from one system are said once a minute, however many frames";

    // A telemetry radio's RADIO_STATUS comes unsigned, and is read (as ArduPilot reads it).
    const quint64 refusedBefore = l->refusedFrames();
    QSignalSpy received(l.get(), &MavlinkTransport::received); // before the frame: the link may read it at once
    vehicle.send(make("RADIO_STATUS", {{"rssi", 180}, {"remrssi", 170}}), l->port());
    ASSERT_TRUE(QTest::qWaitFor([&] {
        return std::any_of(received.begin(), received.end(), [](const QList<QVariant> &r) {
            return r[0].value<msg::Message>().abbrev() == u"RADIO_STATUS"_s;
        });
    }, 2000));
    EXPECT_EQ(l->refusedFrames(), refusedBefore);
}

// An abort mode this vehicle does not have is an error naming it, never another mode
// (the link used to send RTL for any name it did not know).
TEST(MavlinkLink, AnUnknownAbortModeIsRefusedNotReplaced)
{
    MavlinkConfig config = loopback();
    config.vehicles[1].abortMode = u"SURFASE"_s;
    Peer vehicle;
    auto l = link(config);
    QSignalSpy discovered(l.get(), &MavlinkTransport::systemDiscovered);
    vehicle.send(heartbeat(11, 10, true), l->port());
    ASSERT_TRUE(QTest::qWaitFor([&] { return discovered.size() == 1; }, 2000));
    const auto sent = l->publish(0xEA01, msg::Message(test::shippedSchema()->byAbbrev(u"Abort"_s)));
    ASSERT_FALSE(sent.has_value());
    EXPECT_EQ(sent.error(), u"ardurover-1 has no mode called SURFASE"_s);
    QTest::qWait(200);
    for (const msg::Message &c : vehicle.of("COMMAND_LONG"))
        EXPECT_NE(c.integer(u"command"), 176) << "no mode change was sent";
}

// The parameter list's request lost (a radio): asked again after 3 s of silence.
TEST(MavlinkLink, AParameterListNobodyAnsweredIsAskedForAgain)
{
    Peer vehicle;
    auto l = link();
    vehicle.send(heartbeat(11, 0, false), l->port());
    ASSERT_TRUE(QTest::qWaitFor([&] { return vehicle.of("PARAM_REQUEST_LIST").size() == 1; }, 2000));
    ASSERT_TRUE(QTest::qWaitFor([&] { return vehicle.of("PARAM_REQUEST_LIST").size() == 2; }, 5000));
}

// TCP (a simulator's 5760): the link connects, reads frames however the
// stream splits them, and answers over the same connection.
TEST(MavlinkLink, ATcpVehicleIsReadHoweverTheStreamSplitsItsFrames)
{
    QTcpServer server;
    ASSERT_TRUE(server.listen(QHostAddress::LocalHost, 0));
    MavlinkConfig config = loopback();
    config.kind = MavlinkConfig::Kind::Tcp;
    config.peers = {{QHostAddress::LocalHost, server.serverPort()}};
    auto l = link(config);
    QSignalSpy discovered(l.get(), &MavlinkTransport::systemDiscovered);
    ASSERT_TRUE(server.waitForNewConnection(3000));
    QTcpSocket *vehicle = server.nextPendingConnection();
    Peer encoder(7);
    const QByteArray bytes = u"Init ArduSub"_s.toLatin1() + encoder.frame(heartbeat(12, 19, false)) + encoder.frame(heartbeat(12, 19, false));
    for (qsizetype at = 0; at < bytes.size(); at += 5) {
        vehicle->write(bytes.mid(at, 5));
        vehicle->flush();
        QTest::qWait(5);
    }
    ASSERT_TRUE(QTest::qWaitFor([&] { return discovered.size() == 1; }, 2000));
    EXPECT_EQ(discovered[0][0].toUInt(), 0xEA07u);
    EXPECT_EQ(discovered[0][1].toString(), u"ardusub-7"_s);
    EXPECT_EQ(l->destination(0xEA07), u"MAVLink/TCP"_s);
    // The ground station's heartbeat comes back over the connection.
    msg::MavlinkFramer framer(encoder.codec);
    bool gcs = false;
    ASSERT_TRUE(QTest::qWaitFor([&] {
        framer.feed(vehicle->readAll());
        while (auto f = framer.next())
            if (auto m = encoder.codec.decode(*f); m && m->abbrev() == u"HEARTBEAT" && m->integer(u"type") == 6)
                gcs = true;
        return gcs;
    }, 3000));
}

// A telemetry radio is a serial line: here a pseudo-terminal, its far end the vehicle.
TEST(MavlinkLink, ATelemetryRadioOnASerialLineIsReadAsAStreamAndAnswered)
{
    int vehicleEnd = -1, consoleEnd = -1;
    char device[256] = {};
    ASSERT_EQ(::openpty(&vehicleEnd, &consoleEnd, device, nullptr, nullptr), 0) << std::strerror(errno);
    termios raw{};
    ASSERT_EQ(::tcgetattr(vehicleEnd, &raw), 0);
    ::cfmakeraw(&raw);
    ASSERT_EQ(::tcsetattr(vehicleEnd, TCSANOW, &raw), 0);
    ASSERT_EQ(::fcntl(vehicleEnd, F_SETFL, ::fcntl(vehicleEnd, F_GETFL) | O_NONBLOCK), 0);
    MavlinkConfig config = loopback();
    config.kind = MavlinkConfig::Kind::Serial;
    config.serialDevice = QString::fromLocal8Bit(device);
    config.baudRate = 57600;
    auto l = link(config);
    ::close(consoleEnd); // the link opened its own
    QSignalSpy discovered(l.get(), &MavlinkTransport::systemDiscovered);
    Peer encoder(3);
    const QByteArray bytes = encoder.frame(heartbeat(11, 4, false)) + encoder.frame(heartbeat(11, 4, false));
    for (qsizetype at = 0; at < bytes.size(); at += 7) // a radio delivers bytes as they come
        ASSERT_EQ(::write(vehicleEnd, bytes.constData() + at, size_t(std::min<qsizetype>(7, bytes.size() - at))),
                  std::min<qsizetype>(7, bytes.size() - at));
    ASSERT_TRUE(QTest::qWaitFor([&] { return discovered.size() == 1; }, 3000));
    EXPECT_EQ(discovered[0][1].toString(), u"ardurover-3"_s);
    EXPECT_EQ(l->destination(0xEA03), u"MAVLink/serial"_s);
    // The ground station's heartbeat goes back down the line.
    msg::MavlinkFramer framer(encoder.codec);
    bool gcs = false;
    ASSERT_TRUE(QTest::qWaitFor([&] {
        char buffer[512];
        for (ssize_t n; (n = ::read(vehicleEnd, buffer, sizeof buffer)) > 0;)
            framer.feed(QByteArray(buffer, n));
        while (auto f = framer.next())
            if (auto m = encoder.codec.decode(*f); m && m->abbrev() == u"HEARTBEAT" && m->integer(u"type") == 6)
                gcs = true;
        return gcs;
    }, 3000));
    l.reset();
    ::close(vehicleEnd);
}

// The joystick speaks the console's words (RemoteActions); a MAVLink vehicle
// gets MANUAL_CONTROL as ArduPilot reads it: ArduSub forward x, yaw r,
// vertical z around 500; ArduRover steering y, throttle z.
TEST(MavlinkLink, AJoysticksRemoteActionsBecomeManualControlAsArduPilotReadsIt)
{
    Peer sub(2), boat(3);
    auto l = link();
    QSignalSpy discovered(l.get(), &MavlinkTransport::systemDiscovered);
    sub.send(heartbeat(12, 19, true), l->port());
    boat.send(heartbeat(11, 0, true), l->port());
    ASSERT_TRUE(QTest::qWaitFor([&] { return discovered.size() == 2; }, 2000));
    msg::Message actions(test::shippedSchema()->byAbbrev(u"RemoteActions"_s));
    actions.setBytes(actions.def()->indexOf(u"actions"), "Heading=0.50;Thrust=0.80");
    ASSERT_TRUE(l->publish(0xEA02, actions).has_value());
    ASSERT_TRUE(l->publish(0xEA03, actions).has_value());
    ASSERT_TRUE(QTest::qWaitFor([&] { return !sub.of("MANUAL_CONTROL").empty() && !boat.of("MANUAL_CONTROL").empty(); }, 2000));
    const msg::Message toSub = sub.of("MANUAL_CONTROL").back(), toBoat = boat.of("MANUAL_CONTROL").back();
    EXPECT_EQ(toSub.integer(u"target"), 2);
    EXPECT_EQ(toSub.integer(u"x"), 800);
    EXPECT_EQ(toSub.integer(u"r"), 500);
    EXPECT_EQ(toSub.integer(u"z"), 500) << "the vertical stick at rest";
    EXPECT_EQ(toBoat.integer(u"target"), 3);
    EXPECT_EQ(toBoat.integer(u"y"), 500);
    EXPECT_EQ(toBoat.integer(u"z"), 800);
    // Released: zeros, the vehicle stops.
    actions.setBytes(actions.def()->indexOf(u"actions"), "Heading=0.00;Thrust=0.00");
    ASSERT_TRUE(l->publish(0xEA03, actions).has_value());
    ASSERT_TRUE(QTest::qWaitFor([&] { return boat.of("MANUAL_CONTROL").size() == 2; }, 2000));
    EXPECT_EQ(boat.of("MANUAL_CONTROL").back().integer(u"z"), 0);
    EXPECT_EQ(boat.of("MANUAL_CONTROL").back().integer(u"y"), 0);
}
