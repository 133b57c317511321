// A MAVLink vehicle's mission and commands: the conversation a ground station
// had with a real ArduRover (../shared/fixtures/mavlink/boat-mission.tlog)
// replayed against MavlinkMissionClient — it must say what the recorded
// ground station said, item for item, and take ArduPilot's answers as they
// came — and what ArduPilot changes in what it holds is not a difference.
#include "mission/MissionXml.h"
#include "plans/MavlinkMission.h"

#include "Fixtures.h"
#include "Missions.h"
#include "QtPrinters.h"
#include "Schemas.h"
#include "Tlog.h"

#include <QSignalSpy>
#include <QTest>
#include <QTimer>

#include <gtest/gtest.h>

using namespace neptus;
using namespace neptus::plans;
using namespace Qt::StringLiterals;

namespace {

constexpr quint16 vehicleId = 0xEA01; // the console id of ArduRover's system 1

bool conversational(const msg::Message &m)
{
    const QString &type = m.def()->abbrev;
    return type.startsWith(u"MISSION_"_s) || type == u"COMMAND_LONG" || type == u"COMMAND_ACK" || type == u"STATUSTEXT";
}

// The mission and command conversation of a tlog, from its first MISSION_COUNT on:
// what the ground station (system 255) sent and what the vehicle answered, in order.
struct Conversation
{
    struct Said
    {
        bool byStation = false;
        msg::Message message;
    };
    std::vector<Said> said;
    size_t at = 0;
    QStringList mismatches;

    explicit Conversation(const QString &tlog)
    {
        const msg::MavlinkCodec codec(test::mavlinkSchema());
        bool begun = false;
        for (const test::TlogRecord &r : test::readTlog(tlog)) {
            auto m = codec.decode(r.frame);
            if (!m || !m->def() || !conversational(*m))
                continue;
            begun = begun || m->def()->abbrev == u"MISSION_COUNT";
            if (!begun)
                continue;
            m->header.src = r.system() == 255 ? 0 : vehicleId;
            said.push_back({r.system() == 255, *m});
        }
    }

    // What our client sent, against what the ground station sent next; then the vehicle's answers, a moment later.
    void heard(const msg::Message &ours, MavlinkMissionClient &client)
    {
        if (at >= said.size() || !said[at].byStation) {
            mismatches << u"%1 sent where the recording has nothing more from the station"_s.arg(ours.def()->abbrev);
            return;
        }
        const msg::Message &theirs = said[at++].message;
        if (theirs.def()->abbrev != ours.def()->abbrev) {
            mismatches << u"%1 sent where the station sent %2"_s.arg(ours.def()->abbrev, theirs.def()->abbrev);
            return;
        }
        for (int i = 0; i < theirs.fieldCount(); ++i) {
            const QString &field = theirs.def()->fields[size_t(i)].abbrev;
            if (field.startsWith(u"target_"_s))
                continue; // the link fills them in
            if (ours.number(i) != theirs.number(i))
                mismatches << u"%1.%2: %3 sent, the station sent %4"_s.arg(ours.def()->abbrev, field).arg(ours.number(i)).arg(theirs.number(i));
        }
        std::vector<msg::Message> answers;
        while (at < said.size() && !said[at].byStation)
            answers.push_back(said[at++].message);
        QTimer::singleShot(1, &client, [&client, answers] {
            for (const msg::Message &m : answers)
                client.receive(m);
        });
    }
};

std::vector<MissionItem> itemsSentIn(const Conversation &c, int missionType)
{
    std::vector<MissionItem> items;
    for (const auto &s : c.said) {
        if (!s.byStation || s.message.def()->abbrev != u"MISSION_ITEM_INT" || s.message.integer(u"mission_type") != missionType)
            continue;
        MissionItem i = missionItemFrom(s.message);
        items.push_back(i);
    }
    return items;
}

} // namespace

TEST(MavlinkMission, AnArduRoverConversationReplaysItemForItemAndItsArmingRefusalComesInItsOwnWords)
{
    NEPTUS_REQUIRE_FIXTURE(path, "mavlink/boat-mission.tlog");
    Conversation conversation(path);
    ASSERT_GT(conversation.said.size(), 40u);
    const std::vector<MissionItem> fence = itemsSentIn(conversation, 1), mission = itemsSentIn(conversation, 0);
    ASSERT_EQ(fence.size(), 5u);
    ASSERT_EQ(mission.size(), 6u);

    MavlinkMissionClient *self = nullptr;
    MavlinkMissionClient client(test::mavlinkSchema(), vehicleId, [&](const msg::Message &m) -> std::expected<void, QString> {
        conversation.heard(m, *self);
        return {};
    });
    self = &client;
    std::vector<MavlinkMissionClient::Result> results;
    QObject::connect(&client, &MavlinkMissionClient::finished, [&](const auto &r) { results.push_back(r); });
    QSignalSpy progress(&client, &MavlinkMissionClient::progress);

    // As the recorded station did: fence up and back, mission up and back, AUTO, arm.
    client.upload(MissionType::Fence, fence);
    client.download(MissionType::Fence);
    client.upload(MissionType::Mission, mission);
    client.download(MissionType::Mission);
    client.command(176, {1, 10, 0, 0, 0, 0, 0}, u"mode AUTO"_s); // MAV_CMD_DO_SET_MODE, Rover AUTO = 10
    client.command(400, {1, 0, 0, 0, 0, 0, 0}, u"arm"_s);        // MAV_CMD_COMPONENT_ARM_DISARM
    ASSERT_TRUE(QTest::qWaitFor([&] { return results.size() == 6; }, 5000)) << results.size() << " operations ended";
    EXPECT_EQ(conversation.mismatches, QStringList());

    EXPECT_TRUE(results[0].ok) << results[0].info.toStdString();
    EXPECT_EQ(results[0].info, u"5 items accepted"_s);
    ASSERT_TRUE(results[1].ok) << results[1].info.toStdString();
    EXPECT_EQ(missionDifference(fence, results[1].items, MissionType::Fence), QString());
    EXPECT_TRUE(results[2].ok) << results[2].info.toStdString();
    ASSERT_TRUE(results[3].ok) << results[3].info.toStdString();
    ASSERT_EQ(results[3].items.size(), 6u);
    // What ArduRover holds differs where ArduPilot always changes it: its own home as item 0
    // (altitude -0.05), DO_CHANGE_SPEED back in frame 0; neither is a difference, either way round.
    EXPECT_NE(results[3].items[0].z, mission[0].z);
    EXPECT_NE(results[3].items[2].frame, mission[2].frame);
    EXPECT_EQ(missionDifference(mission, results[3].items, MissionType::Mission), QString());
    EXPECT_EQ(missionDifference(results[3].items, mission, MissionType::Mission), QString());
    // What it held is what keptByArduPilot (the simulator's store) says it keeps of what was sent.
    for (size_t i = 1; i < mission.size(); ++i)
        EXPECT_EQ(keptByArduPilot(mission[i], MissionType::Mission).frame, results[3].items[i].frame) << "item " << i;
    EXPECT_TRUE(results[4].ok) << results[4].info.toStdString();

    EXPECT_FALSE(results[5].ok);
    EXPECT_EQ(results[5].what, u"arm"_s);
    EXPECT_TRUE(results[5].info.startsWith(u"FAILED"_s)) << results[5].info.toStdString();
    EXPECT_TRUE(results[5].info.contains(u"Arm: Gyros inconsistent; Arm: AHRS: not using configured AHRS type"_s))
        << results[5].info.toStdString();
    EXPECT_FALSE(results[5].info.contains(u"Mission: 1 WP"_s)) << "an Info text is not a refusal's word";

    // Progress, item by item, of all four transfers (5 + 5 + 6 + 6).
    EXPECT_EQ(progress.size(), 22);
    EXPECT_EQ(progress.last().at(1).toInt(), 6);
    EXPECT_EQ(progress.last().at(2).toInt(), 6);
}

TEST(MavlinkMission, AVehicleThatAsksNoMoreEndsTheUploadSayingHowFarItGot)
{
    std::vector<msg::Message> sent;
    MavlinkMissionClient client(test::mavlinkSchema(), vehicleId, [&](const msg::Message &m) -> std::expected<void, QString> {
        sent.push_back(m);
        return {};
    });
    client.setTimeScale(0.02);
    std::vector<MavlinkMissionClient::Result> results;
    QObject::connect(&client, &MavlinkMissionClient::finished, [&](const auto &r) { results.push_back(r); });
    std::vector<MissionItem> items(4);
    client.upload(MissionType::Mission, items);
    // Nobody answers the count: sent three times, then given up.
    ASSERT_TRUE(QTest::qWaitFor([&] { return results.size() == 1; }, 2000));
    EXPECT_FALSE(results[0].ok);
    EXPECT_EQ(results[0].info, u"no answer to MISSION_COUNT after 3 tries"_s);
    EXPECT_EQ(sent.size(), 3u);

    // ArduPilot asks with MISSION_REQUEST; asked for two, then silence.
    client.upload(MissionType::Mission, items);
    msg::Message request(test::mavlinkSchema()->byAbbrev(u"MISSION_REQUEST"_s));
    request.header.src = vehicleId;
    for (int seq : {0, 1}) {
        request.setInteger(request.def()->indexOf(u"seq"), seq);
        EXPECT_TRUE(client.receive(request));
    }
    EXPECT_EQ(sent.back().def()->abbrev, u"MISSION_ITEM_INT"_s);
    EXPECT_EQ(sent.back().integer(u"seq"), 1);
    ASSERT_TRUE(QTest::qWaitFor([&] { return results.size() == 2; }, 2000));
    EXPECT_FALSE(results[1].ok);
    EXPECT_EQ(results[1].info, u"the vehicle stopped asking for items after 2 of 4"_s);
}

TEST(MavlinkMission, AMissionRefusedByItsAckSaysTheResultByName)
{
    MavlinkMissionClient client(test::mavlinkSchema(), vehicleId, [](const msg::Message &) -> std::expected<void, QString> { return {}; });
    std::vector<MavlinkMissionClient::Result> results;
    QObject::connect(&client, &MavlinkMissionClient::finished, [&](const auto &r) { results.push_back(r); });
    client.upload(MissionType::Fence, std::vector<MissionItem>(3));
    msg::Message ack(test::mavlinkSchema()->byAbbrev(u"MISSION_ACK"_s));
    ack.header.src = vehicleId;
    ack.setInteger(ack.def()->indexOf(u"mission_type"), 1);
    ack.setInteger(ack.def()->indexOf(u"type"), 4); // MAV_MISSION_NO_SPACE
    msg::Message other = ack;
    other.header.src = vehicleId + 1;
    EXPECT_FALSE(client.receive(other)) << "another vehicle's ACK";
    EXPECT_TRUE(client.receive(ack));
    ASSERT_EQ(results.size(), 1u);
    EXPECT_FALSE(results[0].ok);
    EXPECT_TRUE(results[0].info.startsWith(u"refused: NO_SPACE ("_s)) << results[0].info.toStdString();
}

TEST(MavlinkMission, ADifferenceIsNamedByItemAndField)
{
    std::vector<MissionItem> sent(3), held(3);
    sent[1].x = held[1].x = 411861769;
    sent[2].x = 411861769;
    held[2].x = 411861770;
    EXPECT_EQ(missionDifference(sent, held, MissionType::Mission), u"item 2: latitude 41.1861769 sent, 41.186177 held"_s);
    held[2].x = sent[2].x;
    held[1].frame = 0; // a waypoint's frame matters
    EXPECT_EQ(missionDifference(sent, held, MissionType::Mission), u"item 1: frame 3 sent, 0 held"_s);
    held.pop_back();
    EXPECT_EQ(missionDifference(sent, held, MissionType::Mission), u"3 items sent, 2 held"_s);
}

TEST(MavlinkMission, WhatArduPilotKeepsOfAnItemIsNoDifference)
{
    // AP_Mission keeps a waypoint's hold time only (acceptance radius and yaw read back 0), frames
    // folded (6 is kept as 3), altitudes in whole centimetres cut towards zero, a loiter's direction only.
    MissionItem waypoint;
    waypoint.frame = 6;
    waypoint.p1 = 2.7f;
    waypoint.p2 = 2;
    waypoint.p4 = std::nanf("");
    waypoint.x = 411861769;
    waypoint.z = 1.234f;
    MissionItem loiter = waypoint;
    loiter.command = 19;
    loiter.p3 = -20;
    loiter.p4 = 1;
    std::vector<MissionItem> sent{MissionItem{}, waypoint, loiter};
    std::vector<MissionItem> held = sent;
    held[1].frame = held[2].frame = 3;
    held[1].p1 = held[2].p1 = 2;
    held[1].p2 = held[1].p4 = 0;
    held[1].z = held[2].z = 1.23f;
    held[2].p3 = -1;
    EXPECT_EQ(missionDifference(sent, held, MissionType::Mission), QString());
    EXPECT_FLOAT_EQ(keptByArduPilot(waypoint, MissionType::Mission).z, 1.23f);
    EXPECT_EQ(keptByArduPilot(waypoint, MissionType::Mission).frame, 3);
    // A navigation command it is not known to change keeps its parameters, and its frame folds too.
    MissionItem spline = waypoint;
    spline.command = 82; // MAV_CMD_NAV_SPLINE_WAYPOINT
    spline.frame = 11;
    EXPECT_EQ(keptByArduPilot(spline, MissionType::Mission).frame, 10);
    EXPECT_FLOAT_EQ(keptByArduPilot(spline, MissionType::Mission).p2, 2.0f);
    held[2].p3 = 1; // the other way round
    EXPECT_EQ(missionDifference(sent, held, MissionType::Mission), u"item 2: param3 -1 sent, 1 held"_s);
}

// A rally point is kept as AP_Rally's RallyLocation (MissionItemProtocol_Rally): its position, its
// altitude frame (5/6/11 read back as 0/3/10) and its altitude as a whole number of metres (int16,
// cut towards zero); no parameters, no autocontinue. The mission's rally marks become such points.
TEST(MavlinkMission, ARallyPointKeepsItsPositionFrameAndWholeMetres)
{
    MissionItem point;
    point.command = 5100;
    point.frame = 6;
    point.p1 = 3;
    point.x = 411861769;
    point.y = -87060003;
    point.z = 12.7f;
    const MissionItem kept = keptByArduPilot(point, MissionType::Rally);
    EXPECT_EQ(kept.frame, 3);
    EXPECT_FLOAT_EQ(kept.z, 12.0f);
    EXPECT_FLOAT_EQ(kept.p1, 0.0f);
    EXPECT_EQ(kept.autocontinue, 0);
    EXPECT_EQ(kept.x, point.x);
    point.z = -3.5f;
    EXPECT_FLOAT_EQ(keptByArduPilot(point, MissionType::Rally).z, -3.0f);
    MissionItem held = kept;
    EXPECT_EQ(missionDifference({point}, {keptByArduPilot(point, MissionType::Rally)}, MissionType::Rally), QString())
        << "item 0 of rally points is a point like the others, and what AP_Rally keeps is no difference";
    held.y += 10;
    EXPECT_EQ(missionDifference({point}, {held}, MissionType::Rally), u"item 0: longitude -8.7060003 sent, -8.7059993 held"_s);

    auto m = mission::readMission(R"(<?xml version="1.0" encoding="UTF-8"?>
<mission format="1" id="r" name="R"><home lat="41.18" lon="-8.70" height="0"/>
  <map id="m"><mark id="pier" lat="41.185" lon="-8.706"/><mark id="safe" role="rally" lat="41.186" lon="-8.707" height="15"/>
    <mark id="north" role="rally" north="100" east="0"/></map></mission>)", u"r.xml"_s);
    ASSERT_TRUE(m.has_value()) << test::errorsText(m.error()).toStdString();
    const std::vector<MissionItem> rally = missionRally(*m);
    ASSERT_EQ(rally.size(), 2u) << "the rally marks, not the plain one";
    EXPECT_EQ(rally[0].command, 5100);
    EXPECT_EQ(rally[0].frame, 3);
    EXPECT_EQ(rally[0].x, 411860000);
    EXPECT_EQ(rally[0].y, -87070000);
    EXPECT_FLOAT_EQ(rally[0].z, 15.0f);
    EXPECT_EQ(rally[0].maneuver, u"safe"_s);
    EXPECT_NEAR(rally[1].x * 1e-7, 41.18 + 100 / 111000.0, 2e-5) << "placed north of home";
}

TEST(MavlinkMission, TranslatedItemsFollowAHomeItemAndABadOneIsNamed)
{
    const mission::GeoPosition home{41.1854582, -8.7060003, 0};
    const auto items = missionItemsFromXml(
        R"(<mission-items plan="p" vehicle="boat"><item maneuver="goto1" command="16" frame="3" lat="41.1861769" lon="-8.7060003" alt="0"/>
           <item maneuver="goto1" command="178" frame="2" p1="1" p2="3" p3="-1"/></mission-items>)",
        home);
    ASSERT_TRUE(items.has_value()) << items.error().toStdString();
    ASSERT_EQ(items->size(), 3u);
    EXPECT_EQ((*items)[0].x, 411854582);
    EXPECT_EQ((*items)[0].frame, 0);
    EXPECT_EQ((*items)[1].x, 411861769);
    EXPECT_EQ((*items)[1].maneuver, u"goto1"_s);
    EXPECT_EQ((*items)[2].command, 178);
    EXPECT_FLOAT_EQ((*items)[2].p2, 3.0f);

    const auto bad = missionItemsFromXml(R"(<mission-items><item command="16" lat="north"/></mission-items>)", home);
    ASSERT_FALSE(bad.has_value());
    EXPECT_EQ(bad.error(), u"mission item 1: lat 'north' is not a number"_s);
}
