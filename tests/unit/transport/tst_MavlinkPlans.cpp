// Plans on a MAVLink vehicle, through the console's own wiring
// (ConsoleSession: link, plan desk, translation) against an ArduPilot-like
// vehicle on loopback UDP (sim::MavlinkPeer, which answers as ArduPilot's
// source and the fixtures say): the plan is translated, uploaded with its
// geofence, read back and recognised; START arms and sets AUTO, or is
// refused in the vehicle's words; the plan runs to its end, told once.
#include "qmlmodels/ConsoleSession.h"
#include "sim/MavlinkPeer.h"

#include "mission/MissionXml.h"

#include "Missions.h"
#include "Paths.h"
#include "QtPrinters.h"
#include "Schemas.h"

#include <QDir>
#include <QFile>
#include <QStandardPaths>
#include <QTest>
#include <QNetworkDatagram>
#include <QUdpSocket>

#include <gtest/gtest.h>

using namespace neptus;
using namespace Qt::StringLiterals;

namespace {

const char *const missionText = R"X(<?xml version="1.0" encoding="UTF-8"?>
<mission format="1" id="boat" name="Boat">
  <home lat="41.1854582" lon="-8.7060003" height="0"/>
  <vehicle id="ardurover-1"/>
  <map id="m">
    <polygon id="ops" role="operating-area">
      <point lat="41.1840" lon="-8.7080"/><point lat="41.1870" lon="-8.7080"/>
      <point lat="41.1870" lon="-8.7040"/><point lat="41.1840" lon="-8.7040"/>
    </polygon>
    <mark id="slipway" name="Slipway" role="rally" lat="41.1852" lon="-8.7064" height="2.6"/>
  </map>
  <plan id="box" vehicle="ardurover-1" start="out">
    <maneuvers>
      <Goto id="out" lat="41.1856" lon="-8.7060" z="0" z_units="DEPTH" speed="3" speed_units="METERS_PS"/>
      <Goto id="back" lat="41.1855" lon="-8.7058" z="0" z_units="DEPTH" speed="3" speed_units="METERS_PS"/>
    </maneuvers>
    <transition from="out" to="back"/>
  </plan>
</mission>
)X";

struct MavlinkPlans : ::testing::Test
{
    ConsoleSession session{test::shippedSchema()};
    plans::PlanDesk &desk = session.planDesk();
    std::unique_ptr<sim::MavlinkPeer> boat;

    void startBoat(QStringList armingFailures = {})
    {
        transport::MavlinkConfig config;
        config.port = 0;
        ASSERT_TRUE(session.console().startMavlink(config).has_value());
        const quint16 consolePort = session.console().mavlinkLinks().front()->port();
        sim::MavlinkPeer::Config peer;
        peer.groundPort = consolePort;
        peer.timeFactor = 8;
        peer.autopilot.armingFailures = std::move(armingFailures);
        boat = std::make_unique<sim::MavlinkPeer>(test::mavlinkSchema(), peer);
        ASSERT_TRUE(boat->start().has_value());
        desk.setMavlinkTimeScale(0.3);
        auto m = mission::readMission(missionText, u"boat.xml"_s);
        ASSERT_TRUE(m) << test::errorsText(m.error()).toStdString();
        desk.setMission(std::move(*m), u"boat.xml"_s);
        ASSERT_TRUE(QTest::qWaitFor([&] { return desk.isMavlink(u"ardurover-1"_s); }, 5000)) << "the boat was never seen";
    }
    bool logSays(const QString &words, int ms = 8000)
    {
        return QTest::qWaitFor([&] { return desk.log(u"ardurover-1"_s).join(u'\n').contains(words); }, ms);
    }
    QString log() const { return desk.log(u"ardurover-1"_s).join(u'\n'); }
    QString planAlarm()
    {
        auto &graph = session.console().alarmGraph();
        const auto node = graph.find(u"systems/ardurover-1/plan"_s);
        return node == alarms::AlarmGraph::noNode ? QString() : graph.message(node);
    }
};

} // namespace

TEST_F(MavlinkPlans, APlanIsUploadedWithItsFenceReadBackStartedAndRunToItsEnd)
{
    startBoat();
    ASSERT_TRUE(desk.refresh(u"ardurover-1"_s).has_value());
    ASSERT_TRUE(QTest::qWaitFor([&] { return desk.fetched(u"ardurover-1"_s); }, 5000)) << log().toStdString();
    EXPECT_TRUE(desk.storedPlans(u"ardurover-1"_s).empty()) << "a fresh vehicle holds only its home";
    EXPECT_EQ(desk.sync(u"ardurover-1"_s, u"box"_s), plans::Sync::Absent);
    const auto refused = desk.start(u"ardurover-1"_s, u"box"_s);
    ASSERT_FALSE(refused.has_value());
    EXPECT_EQ(refused.error(), u"ardurover-1 does not hold box: send it first"_s);

    QStringList transfers; // as the plan panel shows them
    QObject::connect(&desk, &plans::PlanDesk::changed, [&](const QString &system) {
        if (const auto t = desk.transfer(system))
            transfers << u"%1: %2 of %3"_s.arg(t->what).arg(t->done).arg(t->total);
    });
    ASSERT_TRUE(desk.send(u"ardurover-1"_s, u"box"_s).has_value());
    ASSERT_TRUE(logSays(u"box sent: the vehicle holds its 3 items as sent"_s)) << log().toStdString();
    EXPECT_TRUE(transfers.contains(u"uploading the geofence of box: 4 of 4"_s)) << transfers.join(u" | "_s).toStdString();
    EXPECT_TRUE(transfers.contains(u"uploading box: 4 of 4"_s)) << transfers.join(u" | "_s).toStdString();
    EXPECT_TRUE(transfers.contains(u"reading box back: 4 of 4"_s)) << transfers.join(u" | "_s).toStdString();
    EXPECT_FALSE(desk.transfer(u"ardurover-1"_s).has_value());
    EXPECT_TRUE(log().contains(u"sending box: 3 mission items, a geofence of 4 vertices, a rally point"_s)) << log().toStdString();
    EXPECT_TRUE(transfers.contains(u"uploading the rally points of box: 1 of 1"_s)) << transfers.join(u" | "_s).toStdString();
    EXPECT_EQ(boat->autopilot().missionCount(), 4) << "home, the speed, two waypoints";
    // The geofence and the rally point are read back and compared too (the point's 2.6 m kept as 2 m is no difference).
    ASSERT_TRUE(logSays(u"box: the vehicle holds its geofence as sent (4 items)"_s)) << log().toStdString();
    ASSERT_TRUE(logSays(u"box: the vehicle holds its rally points as sent (1 item)"_s)) << log().toStdString();
    EXPECT_EQ(boat->autopilot().fenceCount(), 4);
    EXPECT_EQ(boat->autopilot().rallyCount(), 1);
    ASSERT_EQ(desk.storedPlans(u"ardurover-1"_s).size(), 1u);
    EXPECT_EQ(desk.storedPlans(u"ardurover-1"_s).front().id, u"box"_s) << "recognised by what it holds";
    EXPECT_EQ(desk.sync(u"ardurover-1"_s, u"box"_s), plans::Sync::Same);

    ASSERT_TRUE(desk.start(u"ardurover-1"_s, u"box"_s).has_value());
    ASSERT_TRUE(logSays(u"box: mode AUTO accepted"_s)) << log().toStdString();
    EXPECT_TRUE(boat->autopilot().armed());
    EXPECT_EQ(boat->autopilot().modeName(), u"AUTO"_s);
    ASSERT_TRUE(logSays(u"box started"_s)) << log().toStdString();
    ASSERT_TRUE(logSays(u"box completed"_s, 30000)) << log().toStdString();
    EXPECT_EQ(log().count(u"box completed"_s), 1);
}

TEST_F(MavlinkPlans, ARefusedArmingStopsTheStartAndSaysTheVehiclesReasons)
{
    startBoat({u"Gyros inconsistent"_s});
    ASSERT_TRUE(desk.send(u"ardurover-1"_s, u"box"_s).has_value());
    ASSERT_TRUE(logSays(u"box sent"_s)) << log().toStdString();
    ASSERT_TRUE(desk.start(u"ardurover-1"_s, u"box"_s).has_value());
    ASSERT_TRUE(logSays(u"box did not start: arm: FAILED: Arm: Gyros inconsistent"_s)) << log().toStdString();
    EXPECT_EQ(planAlarm(), u"plan box did not start: arm: FAILED: Arm: Gyros inconsistent"_s);
    QTest::qWait(300);
    EXPECT_NE(boat->autopilot().modeName(), u"AUTO"_s) << "no AUTO after a refused arming";
    EXPECT_FALSE(boat->autopilot().armed());
}

TEST_F(MavlinkPlans, StopPutsTheBoatInHoldAndTheRunEndsStoppedNotFailed)
{
    startBoat();
    ASSERT_TRUE(desk.send(u"ardurover-1"_s, u"box"_s).has_value());
    ASSERT_TRUE(logSays(u"box sent"_s)) << log().toStdString();
    ASSERT_TRUE(desk.start(u"ardurover-1"_s, u"box"_s).has_value());
    ASSERT_TRUE(logSays(u"box started"_s)) << log().toStdString();
    ASSERT_TRUE(desk.stop(u"ardurover-1"_s).has_value());
    ASSERT_TRUE(logSays(u"box stopped"_s)) << log().toStdString();
    EXPECT_EQ(boat->autopilot().modeName(), u"HOLD"_s);
    EXPECT_FALSE(log().contains(u"box failed"_s)) << log().toStdString();
}

TEST_F(MavlinkPlans, AbortPutsTheBoatInRtlAndTheRunEndsFailedWithWhy)
{
    startBoat();
    ASSERT_TRUE(desk.send(u"ardurover-1"_s, u"box"_s).has_value());
    ASSERT_TRUE(logSays(u"box sent"_s)) << log().toStdString();
    ASSERT_TRUE(desk.start(u"ardurover-1"_s, u"box"_s).has_value());
    ASSERT_TRUE(logSays(u"box started"_s)) << log().toStdString();
    ASSERT_TRUE(desk.abort(u"ardurover-1"_s).has_value());
    ASSERT_TRUE(QTest::qWaitFor([&] { return boat->autopilot().modeName() == u"RTL"_s; }, 3000)) << boat->autopilot().modeName().toStdString();
    ASSERT_TRUE(logSays(u"box failed: left the mission for RTL"_s)) << log().toStdString();
    EXPECT_EQ(planAlarm(), u"plan box failed: left the mission for RTL"_s);
}

// A maneuver mission items cannot carry, in a plan for a MAVLink vehicle whose
// definition lists it (an operator's own definition of the boat, adding YoYo),
// is refused before anything reaches the vehicle, naming the maneuver.
TEST_F(MavlinkPlans, AManeuverMissionItemsCannotCarryIsRefusedBeforeAnythingIsSent)
{
    QStandardPaths::setTestModeEnabled(true); // the user's vehicles folder, in a place of its own
    const QString folder = QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation) + u"/neptus-qt/vehicles"_s;
    struct Restore
    {
        QString file;
        ~Restore()
        {
            QFile::remove(file);
            QStandardPaths::setTestModeEnabled(false);
        }
    } restore{folder + u"/ardurover-1.xml"_s};
    ASSERT_TRUE(QDir().mkpath(folder));
    QFile shipped(test::sourcePath(u"vehicles/ardurover-1.xml"_s));
    ASSERT_TRUE(shipped.open(QIODevice::ReadOnly));
    QByteArray definition = shipped.readAll();
    definition.replace("<maneuver type=\"StationKeeping\"/>", "<maneuver type=\"StationKeeping\"/><maneuver type=\"YoYo\"/>");
    QFile own(restore.file);
    ASSERT_TRUE(own.open(QIODevice::WriteOnly) && own.write(definition) == definition.size());
    own.close();

    startBoat();
    QString text = QString::fromUtf8(missionText);
    text.replace(u"<Goto id=\"back\""_s, u"<YoYo id=\"dive\" lat=\"41.1857\" lon=\"-8.7059\" z=\"0\" z_units=\"DEPTH\" "
                                       u"amplitude=\"0\" pitch=\"15\" speed=\"2\" speed_units=\"METERS_PS\"/>\n"
                                       u"      <Goto id=\"back\""_s);
    text.replace(u"<transition from=\"out\" to=\"back\"/>"_s,
                 u"<transition from=\"out\" to=\"dive\"/><transition from=\"dive\" to=\"back\"/>"_s);
    auto m = mission::readMission(text.toUtf8(), u"boat.xml"_s);
    ASSERT_TRUE(m) << test::errorsText(m.error()).toStdString();
    desk.setMission(std::move(*m), u"boat.xml"_s);
    const int held = boat->autopilot().missionCount();
    const auto sent = desk.send(u"ardurover-1"_s, u"box"_s);
    ASSERT_FALSE(sent.has_value()) << "a yo-yo flown as waypoints would not rise and fall";
    EXPECT_TRUE(sent.error().startsWith(u"plan 'box' is not sent: "_s)) << sent.error().toStdString();
    EXPECT_TRUE(sent.error().contains(u"not expressible as MAVLink mission items: maneuver dive (YoYo), its rise and fall in depth"_s))
        << sent.error().toStdString();
    QTest::qWait(300);
    EXPECT_EQ(boat->autopilot().missionCount(), held) << "nothing reached the vehicle";
    EXPECT_FALSE(desk.transfer(u"ardurover-1"_s).has_value());
}

// Another ground station (here a mission client on a socket of its own) sent
// and started the plan before this console looked: the console recognises
// the mission as the plan, shows it running, and tells one run, not a
// "mission" replaced by the plan.
TEST_F(MavlinkPlans, AMissionAnotherStationStartedIsRecognisedAsItsPlanAndIsOneRun)
{
    startBoat();
    auto m = mission::readMission(missionText, u"boat.xml"_s);
    ASSERT_TRUE(m.has_value());
    const auto translated = ConsoleSession::mavlinkPlanFor(*m, m->plans.front());
    ASSERT_TRUE(translated.has_value()) << translated.error().toStdString();
    QUdpSocket station;
    ASSERT_TRUE(station.bind(QHostAddress::LocalHost, 0));
    const msg::MavlinkCodec codec(test::mavlinkSchema());
    plans::MavlinkMissionClient other(test::mavlinkSchema(), 1, [&](const msg::Message &message) -> std::expected<void, QString> {
        msg::Message addressed = message;
        if (const int t = addressed.def()->indexOf(u"target_system"); t >= 0)
            addressed.setInteger(t, 1);
        msg::MavlinkCodec::Options o;
        o.system = 254;
        station.writeDatagram(*codec.encode(addressed, o), QHostAddress::LocalHost, boat->port());
        return {};
    });
    other.setOwnSystem(254);
    QObject::connect(&station, &QUdpSocket::readyRead, [&] {
        while (station.hasPendingDatagrams())
            if (auto message = codec.decode(station.receiveDatagram().data()))
                other.receive(*message);
    });
    int done = 0;
    QObject::connect(&other, &plans::MavlinkMissionClient::finished, [&](const auto &r) { done += r.ok; });
    other.upload(plans::MissionType::Mission, translated->items);
    other.command(400, {1, 0, 0, 0, 0, 0, 0}, u"arm"_s);
    other.command(176, {1, 10, 0, 0, 0, 0, 0}, u"mode AUTO"_s);
    ASSERT_TRUE(QTest::qWaitFor([&] { return done == 3; }, 5000)) << done;
    ASSERT_TRUE(QTest::qWaitFor([&] { return boat->autopilot().modeName() == u"AUTO"_s; }, 3000));

    ASSERT_TRUE(desk.refresh(u"ardurover-1"_s).has_value());
    ASSERT_TRUE(QTest::qWaitFor([&] { return desk.sync(u"ardurover-1"_s, u"box"_s) == plans::Sync::Same; }, 5000)) << log().toStdString();
    ASSERT_TRUE(logSays(u"box completed"_s, 30000)) << log().toStdString();
    EXPECT_FALSE(log().contains(u"started in its place"_s)) << log().toStdString();
    EXPECT_FALSE(log().contains(u"PlanDB"_s)) << "a MAVLink vehicle is asked nothing of IMC's: " << log().toStdString();
    EXPECT_EQ(planAlarm(), u"plan box completed"_s) << "its end, not a replacement";
}
