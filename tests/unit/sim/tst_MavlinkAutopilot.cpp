// The simulator's ArduPilot (and its link, MavlinkPeer): each behaviour the console relies on, named,
// as ArduPilot's source has it (GCS_MAVLink MissionItemProtocol, AP_Mission,
// Rover's mode.cpp) and the real vehicles of ../shared/fixtures/mavlink did.
#include "sim/MavlinkAutopilot.h"
#include "sim/MavlinkPeer.h"

#include "QtPrinters.h"
#include "Schemas.h"

#include <QNetworkDatagram>
#include <QTest>
#include <QUdpSocket>

#include <gtest/gtest.h>

#include <array>

using namespace neptus;
using namespace Qt::StringLiterals;

namespace {

msg::Message make(const char *name, std::initializer_list<std::pair<const char *, double>> fields = {})
{
    msg::Message m(test::mavlinkSchema()->byAbbrev(QString::fromLatin1(name)));
    for (const auto &[field, value] : fields)
        m.setNumber(m.def()->indexOf(QString::fromLatin1(field)), value);
    return m;
}

QStringList said(const std::vector<msg::Message> &out)
{
    QStringList lines;
    for (const msg::Message &m : out) {
        const QString &type = m.def()->abbrev;
        if (type == u"STATUSTEXT")
            lines << u"STATUSTEXT %1 %2"_s.arg(m.integer(u"severity")).arg(m.text(u"text"));
        else if (type == u"MISSION_REQUEST" || type == u"MISSION_REQUEST_INT")
            lines << u"%1 %2"_s.arg(type).arg(m.integer(u"seq"));
        else if (type == u"MISSION_ACK")
            lines << u"MISSION_ACK %1"_s.arg(m.integer(u"type"));
        else if (type == u"COMMAND_ACK")
            lines << u"COMMAND_ACK %1 %2"_s.arg(m.integer(u"command")).arg(m.integer(u"result"));
        else if (type == u"MISSION_ITEM_INT")
            lines << u"MISSION_ITEM_INT %1 cmd %2 frame %3 p2 %4 z %5"_s.arg(m.integer(u"seq")).arg(m.integer(u"command"))
                         .arg(m.integer(u"frame")).arg(m.number(u"param2")).arg(m.number(u"z"));
    }
    return lines;
}

msg::Message waypoint(int seq, double z = 0)
{
    return make("MISSION_ITEM_INT", {{"seq", seq}, {"command", 16}, {"frame", 3}, {"param2", 2}, {"x", 411861769}, {"y", -87060003}, {"z", z}});
}

} // namespace

TEST(MavlinkAutopilot, ItAsksForItemsWithMissionRequestAgainAfterASecondAndGivesUpEightSecondsAfterTheLast)
{
    sim::MavlinkAutopilot boat(test::mavlinkSchema(), {});
    EXPECT_EQ(said(boat.receive(make("MISSION_COUNT", {{"count", 3}}), 0)), QStringList{u"MISSION_REQUEST 0"_s});
    EXPECT_EQ(said(boat.step(0.5)), QStringList());
    EXPECT_EQ(said(boat.step(1.0)), QStringList{u"MISSION_REQUEST 0"_s});
    EXPECT_EQ(said(boat.receive(waypoint(0), 1.2)), QStringList{u"MISSION_REQUEST 1"_s});
    EXPECT_EQ(said(boat.receive(waypoint(2), 1.3)), QStringList{u"MISSION_ACK 13"_s}) << "INVALID_SEQUENCE";
    QStringList late;
    for (double t = 1.5; t <= 9.3; t += 0.1)
        late << said(boat.step(t));
    EXPECT_EQ(late.filter(u"MISSION_ACK"_s), QStringList{u"MISSION_ACK 15"_s}) << "OPERATION_CANCELLED";
    EXPECT_TRUE(late.contains(u"STATUSTEXT 4 Mission upload timeout"_s));
}

TEST(MavlinkAutopilot, ItKeepsItsOwnHomeAsItemZeroAndWhatAPMissionKeepsOfEachItem)
{
    sim::MavlinkAutopilot boat(test::mavlinkSchema(), {});
    boat.receive(make("MISSION_COUNT", {{"count", 3}}), 0);
    boat.receive(waypoint(0, 99), 0);
    boat.receive(make("MISSION_ITEM_INT", {{"seq", 1}, {"command", 178}, {"frame", 2}, {"param1", 1}, {"param2", 3}}), 0);
    EXPECT_EQ(said(boat.receive(waypoint(2, 1.234), 0)),
              (QStringList{u"STATUSTEXT 6 Flight plan received"_s, u"MISSION_ACK 0"_s}));
    QStringList back;
    for (int seq = 0; seq < 3; ++seq)
        back << said(boat.receive(make("MISSION_REQUEST_INT", {{"seq", seq}}), 0));
    EXPECT_EQ(back, (QStringList{u"MISSION_ITEM_INT 0 cmd 16 frame 0 p2 0 z 0"_s, u"MISSION_ITEM_INT 1 cmd 178 frame 0 p2 3 z 0"_s,
                                 u"MISSION_ITEM_INT 2 cmd 16 frame 3 p2 0 z 1.23"_s}));
}

// Rally points (MissionItemProtocol_Rally): taken as RallyLocations (altitude in whole metres) and read
// back above home; MISSION_CLEAR_ALL clears one mission type and is ACCEPTED (the mission keeps its home),
// but AP_Mission::clear() refuses while the vehicle is armed and running its mission (MAV_MISSION_ERROR).
TEST(MavlinkAutopilot, ItKeepsRallyPointsInWholeMetresAndClearsATypeUnlessItsMissionIsRunning)
{
    sim::MavlinkAutopilot boat(test::mavlinkSchema(), {});
    EXPECT_EQ(said(boat.receive(make("MISSION_COUNT", {{"count", 1}, {"mission_type", 2}}), 0)), QStringList{u"MISSION_REQUEST 0"_s});
    EXPECT_EQ(said(boat.receive(make("MISSION_ITEM_INT", {{"seq", 0}, {"command", 5100}, {"frame", 6}, {"x", 411860000}, {"y", -87070000},
                                                          {"z", 15.8}, {"mission_type", 2}}), 0)),
              QStringList{u"MISSION_ACK 0"_s});
    EXPECT_EQ(boat.rallyCount(), 1);
    EXPECT_EQ(said(boat.receive(make("MISSION_REQUEST_INT", {{"seq", 0}, {"mission_type", 2}}), 0)),
              QStringList{u"MISSION_ITEM_INT 0 cmd 5100 frame 3 p2 0 z 15"_s});
    EXPECT_EQ(said(boat.receive(make("MISSION_CLEAR_ALL", {{"mission_type", 2}}), 0)), QStringList{u"MISSION_ACK 0"_s});
    EXPECT_EQ(boat.rallyCount(), 0);

    boat.receive(make("MISSION_COUNT", {{"count", 2}}), 0);
    boat.receive(waypoint(0), 0);
    boat.receive(waypoint(1), 0);
    ASSERT_EQ(boat.missionCount(), 2);
    boat.receive(make("COMMAND_LONG", {{"command", 400}, {"param1", 1}}), 0);
    boat.receive(make("COMMAND_LONG", {{"command", 176}, {"param1", 1}, {"param2", 10}}), 0);
    boat.step(0.1);
    ASSERT_EQ(boat.modeName(), u"AUTO"_s);
    EXPECT_EQ(said(boat.receive(make("MISSION_CLEAR_ALL", {}), 0.2)), QStringList{u"MISSION_ACK 1"_s}) << "ERROR: it is running";
    EXPECT_EQ(boat.missionCount(), 2);
    boat.receive(make("COMMAND_LONG", {{"command", 176}, {"param1", 1}, {"param2", 4}}), 0.3); // HOLD
    boat.receive(make("COMMAND_LONG", {{"command", 400}, {"param1", 0}}), 0.3);
    EXPECT_EQ(said(boat.receive(make("MISSION_CLEAR_ALL", {}), 0.4)), QStringList{u"MISSION_ACK 0"_s});
    EXPECT_EQ(boat.missionCount(), 1) << "its home";
}

TEST(MavlinkAutopilot, AutoWithoutAMissionAndArmingThatFailsAreRefusedInArduRoversWords)
{
    sim::MavlinkAutopilot::Config config;
    config.armingFailures = {u"Gyros inconsistent"_s};
    sim::MavlinkAutopilot boat(test::mavlinkSchema(), config);
    EXPECT_EQ(said(boat.receive(make("COMMAND_LONG", {{"command", 176}, {"param1", 1}, {"param2", 10}}), 0)),
              (QStringList{u"COMMAND_ACK 176 4"_s, u"STATUSTEXT 5 No Mission. Can't set AUTO."_s,
                           u"STATUSTEXT 4 Flight mode change failed"_s}));
    EXPECT_EQ(said(boat.receive(make("COMMAND_LONG", {{"command", 176}, {"param1", 0}, {"param2", 4}}), 0)),
              QStringList{u"COMMAND_ACK 176 2"_s}) << "DENIED without the custom-mode flag";
    EXPECT_EQ(said(boat.receive(make("COMMAND_LONG", {{"command", 400}, {"param1", 1}}), 0)),
              (QStringList{u"COMMAND_ACK 400 4"_s, u"STATUSTEXT 2 Arm: Gyros inconsistent"_s}));
    EXPECT_FALSE(boat.armed());
    EXPECT_EQ(said(boat.receive(make("COMMAND_LONG", {{"command", 400}, {"param1", 1}, {"param2", 2989}}), 0)),
              (QStringList{u"COMMAND_ACK 400 0"_s, u"STATUSTEXT 6 Throttle armed"_s})) << "forced";
}

TEST(MavlinkAutopilot, ASubLeftWithoutManualControlForThreeSecondsSaysSoAndDisarms)
{
    sim::MavlinkAutopilot::Config config;
    config.type = sim::MavlinkAutopilot::Type::Sub;
    sim::MavlinkAutopilot sub(test::mavlinkSchema(), config);
    sub.receive(make("COMMAND_LONG", {{"command", 400}, {"param1", 1}}), 0);
    ASSERT_TRUE(sub.armed());
    sub.receive(make("MANUAL_CONTROL", {{"target", 1}, {"x", 800}, {"z", 500}}), 0.5);
    QStringList words;
    for (double t = 0.6; t < 3.4; t += 0.1)
        words << said(sub.step(t));
    EXPECT_TRUE(sub.armed()) << "still within 3 s";
    EXPECT_FALSE(words.contains(u"STATUSTEXT 2 Lost manual control"_s));
    for (double t = 3.4; t < 4.0; t += 0.1)
        words << said(sub.step(t));
    EXPECT_TRUE(words.contains(u"STATUSTEXT 2 Lost manual control"_s)) << words.join(u" | "_s).toStdString();
    EXPECT_FALSE(sub.armed());
}

TEST(MavlinkAutopilot, ItListsItsParametersByIndexAndEchoesASetOneWithIndex65535)
{
    sim::MavlinkAutopilot boat(test::mavlinkSchema(), {});
    const auto all = boat.receive(make("PARAM_REQUEST_LIST"), 0);
    ASSERT_GE(all.size(), 5u);
    for (size_t i = 0; i < all.size(); ++i) {
        EXPECT_EQ(all[i].integer(u"param_index"), qint64(i));
        EXPECT_EQ(all[i].integer(u"param_count"), qint64(all.size()));
    }
    msg::Message set = make("PARAM_SET", {{"param_value", 1}, {"param_type", 9}});
    set.setBytes(set.def()->indexOf(u"param_id"), "FS_GCS_ENABLE");
    const auto echo = boat.receive(set, 0);
    ASSERT_EQ(echo.size(), 1u);
    EXPECT_EQ(echo[0].text(u"param_id"), u"FS_GCS_ENABLE"_s);
    EXPECT_EQ(echo[0].number(u"param_value"), 1.0);
    EXPECT_EQ(echo[0].integer(u"param_index"), 65535);
}

namespace {

// What MISSION_CURRENT says now: seq, mission_state, mission_mode.
std::array<qint64, 3> current(sim::MavlinkAutopilot &vehicle, double &t)
{
    std::array<qint64, 3> said{-1, -1, -1};
    for (int i = 0; i < 12; ++i) // a second or so: one MISSION_CURRENT
        for (const msg::Message &m : vehicle.step(t += 0.1))
            if (m.def()->abbrev == u"MISSION_CURRENT")
                said = {m.integer(u"seq"), m.integer(u"mission_state"), m.integer(u"mission_mode")};
    return said;
}

} // namespace

// As the sub-dive fixture shows it (../shared/fixtures/mavlink): seq 0 and NOT_STARTED before the
// mission, the running item while ACTIVE, the last nav item and COMPLETE afterwards, in AUTO and
// out of it; mission_mode 0 on a Sub (only Rover's modes require a mission); disarming resets it.
TEST(MavlinkAutopilot, MissionCurrentSaysWhatArduSubsDoesBeforeDuringAndAfterItsMission)
{
    sim::MavlinkAutopilot::Config config;
    config.type = sim::MavlinkAutopilot::Type::Sub;
    sim::MavlinkAutopilot sub(test::mavlinkSchema(), config);
    double t = 0;
    sub.receive(make("MISSION_COUNT", {{"count", 2}}), t);
    sub.receive(waypoint(0), t);
    sub.receive(make("MISSION_ITEM_INT", {{"seq", 1}, {"command", 16}, {"frame", 3}, {"x", 411855000}, {"y", -87060003}, {"z", -2}}), t);
    EXPECT_EQ(current(sub, t), (std::array<qint64, 3>{0, 2, 0})) << "NOT_STARTED, no item running";
    sub.receive(make("COMMAND_LONG", {{"command", 400}, {"param1", 1}}), t);
    sub.receive(make("COMMAND_LONG", {{"command", 176}, {"param1", 1}, {"param2", 3}}), t); // AUTO
    EXPECT_EQ(current(sub, t), (std::array<qint64, 3>{1, 3, 0})) << "ACTIVE on item 1";
    std::array<qint64, 3> now = current(sub, t);
    for (int second = 0; second < 60 && now[1] != 5; ++second) // it dives and goes the 60 m
        now = current(sub, t);
    EXPECT_EQ(now, (std::array<qint64, 3>{1, 5, 0})) << "COMPLETE, keeping its last item";
    sub.receive(make("COMMAND_LONG", {{"command", 176}, {"param1", 1}, {"param2", 9}}), t); // SURFACE
    EXPECT_EQ(current(sub, t), (std::array<qint64, 3>{1, 5, 0})) << "still COMPLETE out of AUTO";
    sub.receive(make("COMMAND_LONG", {{"command", 400}, {"param1", 0}}), t);
    EXPECT_EQ(current(sub, t), (std::array<qint64, 3>{0, 2, 0})) << "disarmed: the mission is reset";
}

TEST(MavlinkAutopilot, SetMissionCurrentTakesZeroAsTheFirstItemAndDeniesOneOutOfRange)
{
    sim::MavlinkAutopilot boat(test::mavlinkSchema(), {});
    boat.receive(make("MISSION_COUNT", {{"count", 2}}), 0);
    boat.receive(waypoint(0), 0);
    boat.receive(waypoint(1), 0);
    EXPECT_EQ(said(boat.receive(make("COMMAND_LONG", {{"command", 224}, {"param1", 0}}), 0)), QStringList{u"COMMAND_ACK 224 0"_s});
    EXPECT_EQ(said(boat.receive(make("COMMAND_LONG", {{"command", 224}, {"param1", 5}}), 0)), QStringList{u"COMMAND_ACK 224 2"_s})
        << "DENIED (GCS_Common.cpp)";
}

// With a key, the simulated vehicle is an ArduPilot telemetry channel with signing set
// (GCS_Signing.cpp): what it sends is signed and verifies with the key; it silently drops
// unsigned frames but a radio's RADIO_STATUS, frames signed with another key, replays of a
// stream's frame and a new stream's frame more than a minute old.
TEST(MavlinkPeer, WithAKeyItSignsAndTakesOnlyFreshFramesSignedWithItButARadiosStatus)
{
    const QByteArray key(32, '\x42');
    sim::MavlinkPeer::Config config;
    config.signingKey = key;
    QUdpSocket ground;
    ASSERT_TRUE(ground.bind(QHostAddress::LocalHost, 0));
    config.groundPort = ground.localPort();
    sim::MavlinkPeer boat(test::mavlinkSchema(), config);
    ASSERT_TRUE(boat.start().has_value());
    ASSERT_TRUE(QTest::qWaitFor([&] { return ground.hasPendingDatagrams(); }, 3000));
    const QByteArray first = ground.receiveDatagram().data();
    msg::MavlinkCodec codec(test::mavlinkSchema());
    msg::MavlinkFrame header;
    ASSERT_TRUE(codec.decode(first, &header).has_value());
    EXPECT_TRUE(header.isSigned);
    EXPECT_TRUE(msg::MavlinkCodec::signatureValid(first, key));

    const auto frame = [&](const msg::Message &m, msg::MavlinkSigning *signing) {
        msg::MavlinkCodec::Options options;
        options.system = 255;
        options.component = 190;
        options.signing = signing;
        return *codec.encode(m, options);
    };
    const auto arm = make("COMMAND_LONG", {{"target_system", 1}, {"target_component", 1}, {"command", 400}, {"param1", 1}});
    const auto deliver = [&](const QByteArray &bytes) {
        ground.writeDatagram(bytes, QHostAddress::LocalHost, boat.port());
        QTest::qWait(150);
    };
    deliver(frame(arm, nullptr));
    EXPECT_EQ(boat.refusedFrames(), 1) << "unsigned";
    msg::MavlinkSigning other{QByteArray(32, '\x01'), 0, msg::MavlinkSigning::now()};
    deliver(frame(arm, &other));
    EXPECT_EQ(boat.refusedFrames(), 2) << "another key";
    msg::MavlinkSigning stale{key, 0, msg::MavlinkSigning::now() - 2 * msg::MavlinkSigningStreams::window};
    deliver(frame(arm, &stale));
    EXPECT_EQ(boat.refusedFrames(), 3) << "a new stream two minutes old";
    EXPECT_FALSE(boat.autopilot().armed());
    deliver(frame(make("RADIO_STATUS", {{"rssi", 200}}), nullptr));
    EXPECT_EQ(boat.refusedFrames(), 3) << "a radio's status is taken unsigned";

    msg::MavlinkSigning signing{key, 0, msg::MavlinkSigning::now()};
    const QByteArray signedArm = frame(arm, &signing);
    deliver(signedArm);
    EXPECT_EQ(boat.refusedFrames(), 3);
    EXPECT_TRUE(boat.autopilot().armed());
    deliver(frame(make("COMMAND_LONG", {{"target_system", 1}, {"target_component", 1}, {"command", 400}, {"param1", 0}}), &signing));
    EXPECT_FALSE(boat.autopilot().armed());
    deliver(signedArm); // the arming again, byte for byte
    EXPECT_EQ(boat.refusedFrames(), 4) << "a replay";
    EXPECT_FALSE(boat.autopilot().armed());
}
