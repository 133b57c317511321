#pragma once

#include "messages/MavlinkModes.h"
#include "messages/Message.h"

#include <QString>

#include <memory>
#include <optional>
#include <vector>

namespace neptus::transport {

// What a MAVLink vehicle means, in the console's vocabulary (IMC's, as DUNE
// presents the ArduPilot vehicles LSTS flies): its HEARTBEAT an Announce,
// AutopilotMode (the mode's name, decoded per autopilot family and vehicle
// type) and ArmingState; GLOBAL_POSITION_INT with the last ATTITUDE an
// EstimatedState; SYS_STATUS and BATTERY_STATUS Voltage, Current and
// FuelLevel; GPS_RAW_INT a GpsFix; SYS_STATUS's sensor health and
// EKF_STATUS_REPORT EntityStates of named entities (alarms, as any
// vehicle's); STATUSTEXT a LogBookEntry in the vehicle's words; the mission's
// progress (MISSION_CURRENT) a PlanControlState. Components, alarms, logs,
// the database and the web page read these whatever the protocol; the raw
// MAVLink messages go to the tree beside them.
//
// The family rules (what each autopilot family calls its modes) are
// msg::mavlink's (MavlinkModes.h).
class MavlinkVehicle
{
public:
    using Family = msg::mavlink::Family;
    using Kind = msg::mavlink::Kind;

    MavlinkVehicle(quint8 mavlinkSystem, quint16 consoleId, QString name, std::shared_ptr<const msg::Schema> imc);

    quint8 mavlinkSystem() const { return m_system; }
    quint16 consoleId() const { return m_id; }
    QString name() const { return m_name; }
    Family family() const { return m_family; }
    Kind kind() const { return m_kind; }
    int mavType() const { return m_mavType; }
    bool armed() const { return m_armed; }
    QString modeName() const { return msg::mavlink::modeName(m_family, m_mavType, m_customMode); }
    bool heard() const { return m_heard; }

    // The IMC messages `message` (a MAVLink message from this vehicle) means,
    // stamped as the vehicle's (`now`, seconds since 1970).
    std::vector<msg::Message> translate(const msg::Message &message, double now);
    // What the vehicle is named by, its entities (the EntityList a console asks for).
    msg::Message announce(double now) const;
    msg::Message entityList(double now) const;
    // The "Parameters" entity's state: reading (BOOT), all read (NORMAL), some never came (FAULT).
    msg::Message parameterState(int state, const QString &description, double now) const;
    // The modes Stop and Abort use when its vehicle definition names none:
    // ArduPilot HOLD (Rover), POSHOLD (Sub), LOITER (Plane, Copter), PX4
    // AUTO.LOITER; Abort RTL, and SURFACE for a Sub (which has no RTL).
    QString defaultStopMode() const { return msg::mavlink::stopMode(m_family, m_mavType); }
    QString defaultAbortMode() const { return msg::mavlink::abortMode(m_family, m_mavType); }

    // The plan this console gave it, for the mission's progress: the plan's
    // id and, per mission item, the maneuver it belongs to ("" for home).
    void setMission(QString planId, QStringList maneuverOfItem);

private:
    msg::Message make(const char *abbrev, double now, quint8 entity = 0xFF) const;
    msg::Message entityState(quint8 entity, int state, const QString &description, double now) const;

    quint8 m_system;
    quint16 m_id;
    QString m_name;
    std::shared_ptr<const msg::Schema> m_imc;
    bool m_heard = false;
    Family m_family = Family::Generic;
    Kind m_kind = Kind::Other;
    int m_mavType = 0;
    quint32 m_customMode = 0;
    bool m_armed = false;
    QString m_lastMode;
    std::optional<bool> m_lastArmed;
    int m_lastStatus = -1;
    double m_lastModeReport = 0;
    // The last attitude, for the next EstimatedState.
    double m_roll = 0, m_pitch = 0, m_yaw = 0, m_p = 0, m_q = 0, m_r = 0;
    double m_lat = 0, m_lon = 0; // rad, for the Announce
    double m_altitude = -1;      // above the bottom (an ROV's rangefinder), -1 unknown
    quint32 m_sensorsHealthy = ~0u, m_sensorsPresent = 0;
    int m_ekfState = -1;
    QString m_planId;
    QStringList m_maneuverOfItem;
    int m_missionState = 0;      // MISSION_CURRENT.mission_state
    int m_missionSeq = 0, m_missionTotal = 0;
    int m_planState = -1;        // what PlanControlState said last
    bool m_ran = false;          // it ran its mission since the console heard it
};

} // namespace neptus::transport
