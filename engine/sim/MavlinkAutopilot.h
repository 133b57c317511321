#pragma once

#include "messages/Message.h"
#include "geo/Geodesy.h"
#include "plans/MavlinkMission.h"
#include "sim/Kinematics.h"

#include <QString>

#include <array>

#include <memory>
#include <optional>
#include <vector>

namespace neptus::sim {

// A MAVLink vehicle that answers as ArduPilot does (ArduRover on a boat, or
// ArduSub), for the simulator and the tests: each behaviour is taken from
// ArduPilot's source and from what real vehicles sent
// (../shared/fixtures/mavlink, README):
//  - the mission protocol (AP_Mission, GCS_MAVLink MissionItemProtocol):
//    items asked with MISSION_REQUEST, asked again after 1 s, the upload
//    cancelled 8 s after the last item ("Mission upload timeout",
//    OPERATION_CANCELLED); item 0 of a mission is its own home whatever was
//    sent; a command that is not a navigation command comes back in frame 0;
//    a fence vertex comes back without its altitude; "Flight plan received";
//  - commands: DO_SET_MODE (custom mode in param2, needs the custom-mode
//    flag in param1: DENIED without it; AUTO with no mission refused with
//    "No Mission. Can't set AUTO."), arming (FAILED then its reasons,
//    CRITICAL, "Arm: …"; "Throttle armed" or "Arming motors"),
//    DO_SET_MISSION_CURRENT, MISSION_START (Rover: AUTO), SET_MESSAGE_INTERVAL;
//  - MANUAL_CONTROL from the ground station in MANUAL, armed: Rover steers
//    with y and throttles with z, Sub drives forward with x and turns with r;
//    3 s after the last one the override is forgotten (Sub: "Lost manual
//    control", CRITICAL, and it disarms: its pilot-input failsafe);
//  - parameters (a few of ArduRover's or ArduSub's): PARAM_REQUEST_LIST
//    answered with every PARAM_VALUE (index, count), PARAM_REQUEST_READ by
//    index or name, PARAM_SET echoed with index 65535;
//  - running the mission in AUTO when armed: MISSION_CURRENT (seq 0 before a
//    nav command runs, ACTIVE, COMPLETE keeping the last nav command; mission
//    reset on disarm, Sub always, Rover out of AUTO; mission_mode Rover's only), MISSION_ITEM_REACHED and "Reached
//    waypoint #n" per waypoint, DO_CHANGE_SPEED, "Mission Complete" (Rover).
// Messages are MAVLink's (a MAVLink schema); step() advances time.
class MavlinkAutopilot
{
public:
    enum class Type { Boat, Sub };
    struct Config
    {
        Type type = Type::Boat;
        geo::Geodetic home{geo::radians(41.1854582), geo::radians(-8.7060003), 0};
        // Why arming is refused ("Gyros inconsistent"); empty: it arms.
        QStringList armingFailures;
    };

    MavlinkAutopilot(std::shared_ptr<const msg::Schema> mavlink, Config config);

    // A message from the ground station; what the vehicle answers at once.
    std::vector<msg::Message> receive(const msg::Message &message, double nowSeconds);
    // Time passes: what the vehicle says on its own (HEARTBEAT, positions and
    // MISSION_CURRENT once a second or more often, re-asked items, words).
    std::vector<msg::Message> step(double nowSeconds);

    int mavType() const { return m_config.type == Type::Sub ? 12 : 11; }
    QString modeName() const;
    bool armed() const { return m_armed; }
    int missionCount() const { return int(m_mission.size()); }
    int fenceCount() const { return int(m_fence.size()); }
    int rallyCount() const { return int(m_rally.size()); }
    // The last MANUAL_CONTROL's axes (x, y, z, r), and whether it still drives (under 3 s old).
    std::array<int, 4> manualControl() const { return m_manual; }
    bool driven() const { return m_manualAt >= 0; }
    // A custom mode's number by name, for this vehicle ("AUTO" 10 on Rover, 3 on Sub).
    std::optional<quint32> modeNumber(const QString &name) const;

    using Item = plans::MissionItem;

private:
    struct Upload
    {
        int type = 0;
        int count = 0;
        int next = 0;
        std::vector<Item> items;
        double askedAt = 0, lastItemAt = 0;
    };

    msg::Message make(const char *name) const;
    msg::Message ack(quint16 command, int result) const;
    msg::Message text(int severity, const QString &words) const;
    msg::Message missionAck(int type, int result) const;
    msg::Message request(const Upload &u) const;
    std::vector<Item> &held(int type);
    const std::vector<Item> &held(int type) const;
    msg::Message parameter(int index, int reportedIndex) const;
    msg::Message item(int type, int seq) const;
    std::vector<msg::Message> command(const msg::Message &m, double now);
    bool setMode(quint32 mode, std::vector<msg::Message> &out);
    void run(double dt, std::vector<msg::Message> &out);
    const Item *currentNav();
    void resetMission();
    double cruiseSpeed() const;
    double parameterValue(const char *name) const;

    std::shared_ptr<const msg::Schema> m_schema;
    Config m_config;
    std::vector<Item> m_mission; // item 0: home
    std::vector<Item> m_fence;
    std::vector<Item> m_rally;
    std::optional<Upload> m_upload;
    quint32 m_mode = 0;
    bool m_armed = false;
    int m_current = 1;
    int m_missionState = 1; // NO_MISSION
    double m_speed = 0; // CRUISE_SPEED (Rover), WPNAV_SPEED (Sub), until DO_CHANGE_SPEED
    Motion m_motion;
    Limits m_limits;
    double m_lastStep = -1, m_lastSlow = -1e9, m_lastFast = -1e9;
    struct Parameter
    {
        QByteArray name;
        float value = 0;
        int type = 9; // MAV_PARAM_TYPE
    };
    std::vector<Parameter> m_parameters;
    quint32 m_manualMode = 0, m_autoMode = 0, m_holdMode = 0;
    int m_lastNav = 0; // the last nav command reached
    quint8 m_to = 255, m_toComponent = 190; // who asked last: its answers' targets
    std::array<int, 4> m_manual{0, 0, 0, 0};
    double m_manualAt = -1; // when the last MANUAL_CONTROL came; -1: none driving
};

} // namespace neptus::sim
