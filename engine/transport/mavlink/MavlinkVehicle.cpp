#include "transport/mavlink/MavlinkVehicle.h"

#include <cmath>
#include <numbers>

namespace neptus::transport {

using namespace Qt::StringLiterals;

namespace {

// Entities of what the adapter reports (EntityList below).
constexpr quint8 batteriesEntity = 3, navigationEntity = 4, gpsEntity = 5, autopilotEntity = 13, parametersEntity = 14;
struct Sensor
{
    quint32 bit;
    quint8 entity;
    const char *label;
};
// MAV_SYS_STATUS_SENSOR bits (common.xml) and what the console calls them.
constexpr Sensor sensors[] = {
    {0x1, 8, "Gyroscope"},      {0x2, 9, "Accelerometer"}, {0x4, 6, "Compass"}, {0x8, 7, "Barometer"},
    {0x20, gpsEntity, "GPS"},   {0x10000, 11, "RC"},       {0x200000, 10, "AHRS"},
    {0x2000000, batteriesEntity, "Batteries"},             {0x10000000, 12, "Pre-arm"},
};

void setNumber(msg::Message &m, QStringView field, double value)
{
    if (const int i = m.def()->indexOf(field); i >= 0)
        m.setNumber(i, value);
}
void setInteger(msg::Message &m, QStringView field, qint64 value)
{
    if (const int i = m.def()->indexOf(field); i >= 0)
        m.setInteger(i, value);
}
void setText(msg::Message &m, QStringView field, const QString &text)
{
    if (const int i = m.def()->indexOf(field); i >= 0)
        m.setBytes(i, text.toUtf8());
}

constexpr double degree = std::numbers::pi / 180;

} // namespace

MavlinkVehicle::MavlinkVehicle(quint8 mavlinkSystem, quint16 consoleId, QString name, std::shared_ptr<const msg::Schema> imc)
    : m_system(mavlinkSystem)
    , m_id(consoleId)
    , m_name(std::move(name))
    , m_imc(std::move(imc))
{
}

void MavlinkVehicle::setMission(QString planId, QStringList maneuverOfItem)
{
    m_planId = std::move(planId);
    m_maneuverOfItem = std::move(maneuverOfItem);
}

msg::Message MavlinkVehicle::make(const char *abbrev, double now, quint8 entity) const
{
    msg::Message m(m_imc->byAbbrev(QString::fromLatin1(abbrev)));
    m.header.src = m_id;
    m.header.srcEnt = entity;
    m.header.timestamp = now;
    return m;
}

msg::Message MavlinkVehicle::entityState(quint8 entity, int state, const QString &description, double now) const
{
    msg::Message m = make("EntityState", now, entity);
    setInteger(m, u"state", state);
    setText(m, u"description", description);
    return m;
}

msg::Message MavlinkVehicle::announce(double now) const
{
    msg::Message m = make("Announce", now);
    setText(m, u"sys_name", m_name);
    // IMC's SystemType: UUV 2, USV 3, UAV 4, UGV 5.
    const int type = m_kind == Kind::Underwater ? 2 : m_kind == Kind::Surface ? 3 : m_kind == Kind::Air ? 4 : m_kind == Kind::Ground ? 5 : 7;
    setInteger(m, u"sys_type", type);
    setInteger(m, u"owner", 0xFFFF);
    setNumber(m, u"lat", m_lat);
    setNumber(m, u"lon", m_lon);
    const char *family = m_family == Family::ArduPilot ? "ardupilot" : m_family == Family::Px4 ? "px4" : "generic";
    setText(m, u"services", u"mavlink://%1/system/%2/type/%3"_s.arg(QLatin1StringView(family)).arg(m_system).arg(m_mavType));
    return m;
}

msg::Message MavlinkVehicle::entityList(double now) const
{
    msg::Message m = make("EntityList", now);
    setInteger(m, u"op", 0); // REPORT
    QStringList pairs{u"Navigation=%1"_s.arg(navigationEntity), u"Autopilot=%1"_s.arg(autopilotEntity),
                      u"Parameters=%1"_s.arg(parametersEntity)};
    for (const Sensor &s : sensors)
        pairs << u"%1=%2"_s.arg(QLatin1StringView(s.label)).arg(s.entity);
    setText(m, u"list", pairs.join(u';'));
    return m;
}

msg::Message MavlinkVehicle::parameterState(int state, const QString &description, double now) const
{
    return entityState(parametersEntity, state, description, now);
}

std::vector<msg::Message> MavlinkVehicle::translate(const msg::Message &message, double now)
{
    std::vector<msg::Message> out;
    if (!message.def())
        return out;
    const QString &type = message.def()->abbrev;
    if (type == u"HEARTBEAT") {
        if (message.header.srcEnt != 0xFF) // another component's heartbeat (a camera, a gimbal)
            return out;
        const bool first = !m_heard;
        m_heard = true;
        m_mavType = int(message.integer(u"type"));
        m_family = msg::mavlink::familyOf(int(message.integer(u"autopilot")));
        m_kind = msg::mavlink::kindOf(m_mavType);
        m_armed = message.integer(u"base_mode") & 0x80; // MAV_MODE_FLAG_SAFETY_ARMED
        m_customMode = quint32(message.integer(u"custom_mode"));
        if (first) {
            out.push_back(announce(now));
            out.push_back(entityList(now));
        }
        out.push_back(make("Heartbeat", now));
        const QString mode = modeName();
        const int status = int(message.integer(u"system_status"));
        if (mode != m_lastMode || m_lastArmed != m_armed || status != m_lastStatus || now - m_lastModeReport >= 1) {
            const bool changed = mode != m_lastMode || m_lastArmed != m_armed;
            m_lastStatus = status;
            m_lastMode = mode;
            m_lastArmed = m_armed;
            m_lastModeReport = now;
            msg::Message autopilot = make("AutopilotMode", now);
            static const QStringList manual{u"MANUAL"_s, u"ACRO"_s, u"STABILIZE"_s, u"STABILIZED"_s};
            static const QStringList automatic{u"AUTO"_s, u"RTL"_s, u"SMART_RTL"_s, u"GUIDED"_s, u"AUTO_RTL"_s, u"LAND"_s,
                                               u"TAKEOFF"_s, u"SURFACE"_s, u"QRTL"_s, u"QLAND"_s, u"AUTOLAND"_s};
            setInteger(autopilot, u"autonomy", manual.contains(mode) ? 0 : automatic.contains(mode) || mode.startsWith(u"AUTO"_s) ? 2 : 1);
            setText(autopilot, u"mode", mode);
            out.push_back(std::move(autopilot));
            msg::Message arming = make("ArmingState", now);
            setInteger(arming, u"state", m_armed ? 0 : 1);
            out.push_back(std::move(arming));
            // MAV_STATE CRITICAL: a failsafe is on; EMERGENCY: it is losing control.
            const QString said = u"%1 · %2"_s.arg(mode, m_armed ? u"armed"_s : u"disarmed"_s);
            out.push_back(status == 5   ? entityState(autopilotEntity, 2, u"failsafe (MAV_STATE_CRITICAL) · "_s + said, now)
                          : status == 6 ? entityState(autopilotEntity, 3, u"emergency (MAV_STATE_EMERGENCY) · "_s + said, now)
                                        : entityState(autopilotEntity, 1, said, now));
            if (changed && m_planState == 3 && mode != msg::mavlink::missionMode(m_family)) // a mission stopped by a mode change
                m_missionState = -1;
        }
    } else if (type == u"ATTITUDE") {
        m_roll = message.number(u"roll");
        m_pitch = message.number(u"pitch");
        m_yaw = message.number(u"yaw");
        m_p = message.number(u"rollspeed");
        m_q = message.number(u"pitchspeed");
        m_r = message.number(u"yawspeed");
    } else if (type == u"GLOBAL_POSITION_INT") {
        msg::Message s = make("EstimatedState", now);
        m_lat = message.number(u"lat") * 1e-7 * degree;
        m_lon = message.number(u"lon") * 1e-7 * degree;
        setNumber(s, u"lat", m_lat);
        setNumber(s, u"lon", m_lon);
        setNumber(s, u"height", message.number(u"alt") / 1000.0); // above mean sea level
        const double relative = message.number(u"relative_alt") / 1000.0; // above home
        const double vx = message.number(u"vx") / 100.0, vy = message.number(u"vy") / 100.0, vz = message.number(u"vz") / 100.0;
        setNumber(s, u"phi", m_roll);
        setNumber(s, u"theta", m_pitch);
        setNumber(s, u"psi", m_yaw);
        setNumber(s, u"vx", vx);
        setNumber(s, u"vy", vy);
        setNumber(s, u"vz", vz);
        setNumber(s, u"u", std::hypot(vx, vy));
        setNumber(s, u"p", m_p);
        setNumber(s, u"q", m_q);
        setNumber(s, u"r", m_r);
        setNumber(s, u"depth", m_kind == Kind::Underwater ? std::max(0.0, -relative) : 0.0);
        setNumber(s, u"alt", m_kind == Kind::Air ? relative : m_altitude);
        out.push_back(std::move(s));
    } else if (type == u"RANGEFINDER") {
        m_altitude = message.number(u"distance");
    } else if (type == u"DISTANCE_SENSOR" && message.integer(u"orientation") == 25) { // MAV_SENSOR_ROTATION_PITCH_270: down
        m_altitude = message.number(u"current_distance") / 100.0;
    } else if (type == u"SYS_STATUS") {
        if (const qint64 mv = message.integer(u"voltage_battery"); mv > 0 && mv != 0xFFFF) {
            msg::Message v = make("Voltage", now, batteriesEntity);
            setNumber(v, u"value", double(mv) / 1000.0);
            out.push_back(std::move(v));
        }
        if (const qint64 ca = message.integer(u"current_battery"); ca >= 0) {
            msg::Message c = make("Current", now, batteriesEntity);
            setNumber(c, u"value", double(ca) / 100.0);
            out.push_back(std::move(c));
        }
        const quint32 present = quint32(message.integer(u"onboard_control_sensors_present"));
        const quint32 enabled = quint32(message.integer(u"onboard_control_sensors_enabled"));
        const quint32 healthy = quint32(message.integer(u"onboard_control_sensors_health"));
        const bool changed = present != m_sensorsPresent || healthy != m_sensorsHealthy;
        m_sensorsPresent = present;
        m_sensorsHealthy = healthy;
        for (const Sensor &sensor : sensors) {
            if (!(present & sensor.bit) || !(enabled & sensor.bit))
                continue;
            const bool good = healthy & sensor.bit;
            if (!changed && good)
                continue; // said when it changes; a fault again each time (it stays raised)
            const bool prearm = sensor.bit == 0x10000000;
            // NORMAL 1, FAULT 2, ERROR 3
            out.push_back(entityState(sensor.entity, good ? 1 : prearm ? 2 : 3,
                                      good ? u"healthy"_s
                                           : prearm ? u"pre-arm checks failing"_s
                                                    : u"%1 unhealthy"_s.arg(QLatin1StringView(sensor.label)), now));
        }
    } else if (type == u"BATTERY_STATUS") {
        if (const qint64 remaining = message.integer(u"battery_remaining"); remaining >= 0) {
            msg::Message f = make("FuelLevel", now, batteriesEntity);
            setNumber(f, u"value", double(remaining));
            setNumber(f, u"confidence", 100);
            out.push_back(std::move(f));
        }
    } else if (type == u"GPS_RAW_INT") {
        msg::Message g = make("GpsFix", now, gpsEntity);
        const int fix = int(message.integer(u"fix_type"));
        // IMC GpsFix types: STANDALONE 1, DIFFERENTIAL 2, DEAD_RECKONING 3, MANUAL_INPUT 4, SIMULATION 5; 0 none.
        setInteger(g, u"type", fix >= 4 ? 2 : fix >= 2 ? 1 : 0);
        setInteger(g, u"satellites", message.integer(u"satellites_visible"));
        setNumber(g, u"lat", message.number(u"lat") * 1e-7 * degree);
        setNumber(g, u"lon", message.number(u"lon") * 1e-7 * degree);
        setNumber(g, u"height", message.number(u"alt") / 1000.0);
        setNumber(g, u"sog", message.number(u"vel") / 100.0);
        setNumber(g, u"cog", message.number(u"cog") / 100.0 * degree);
        if (const qint64 eph = message.integer(u"eph"); eph != 0xFFFF)
            setNumber(g, u"hdop", double(eph) / 100.0);
        // VALID_POS 0x4, VALID_COG 0x8, VALID_SOG 0x10, VALID_HDOP 0x80
        setInteger(g, u"validity", fix >= 2 ? 0x4 | 0x8 | 0x10 | 0x80 : 0);
        out.push_back(std::move(g));
    } else if (type == u"EKF_STATUS_REPORT") {
        const quint32 flags = quint32(message.integer(u"flags"));
        const int state = flags & 1024 ? 3 : !(flags & 16) || (flags & 32768) ? 2 : 1;
        if (state != m_ekfState) {
            m_ekfState = state;
            out.push_back(entityState(navigationEntity, state,
                                      flags & 1024 ? u"EKF not initialised"_s
                                      : flags & 32768 ? u"GPS glitching"_s
                                      : !(flags & 16) ? u"no absolute position yet (EKF)"_s
                                                      : u"position good (EKF)"_s, now));
        }
    } else if (type == u"STATUSTEXT") {
        const int severity = int(message.integer(u"severity"));
        msg::Message entry = make("LogBookEntry", now, autopilotEntity);
        // IMC: INFO 0, WARNING 1, ERROR 2, CRITICAL 3, DEBUG 4.
        setInteger(entry, u"type", severity <= 2 ? 3 : severity == 3 ? 2 : severity == 4 ? 1 : severity == 7 ? 4 : 0);
        setNumber(entry, u"htime", now);
        setText(entry, u"context", u"autopilot"_s);
        setText(entry, u"text", message.text(u"text"));
        out.push_back(std::move(entry));
    } else if (type == u"MISSION_CURRENT") {
        m_missionSeq = int(message.integer(u"seq"));
        m_missionTotal = int(message.integer(u"total"));
        const int missionState = int(message.integer(u"mission_state"));
        // 3 ACTIVE, 5 COMPLETE (MISSION_STATE); without the field (an older autopilot), AUTO and armed is running.
        const bool reportsState = missionState != 0;
        const bool executing = modeName() == msg::mavlink::missionMode(m_family) && m_armed && (reportsState ? missionState == 3 : true);
        msg::Message s = make("PlanControlState", now);
        // Its mission by the plan it came from; "mission" once an unlabelled one ran; none before.
        const QString plan = !m_planId.isEmpty() ? m_planId : executing || m_planState == 3 || m_ran ? u"mission"_s : QString();
        m_ran = m_ran || executing;
        setText(s, u"plan_id", plan);
        int outcome = 0;
        if (executing) {
            setInteger(s, u"state", 3); // EXECUTING
            const QString maneuver = m_missionSeq >= 0 && m_missionSeq < m_maneuverOfItem.size() && !m_maneuverOfItem[m_missionSeq].isEmpty()
                                         ? m_maneuverOfItem[m_missionSeq] : u"item %1"_s.arg(m_missionSeq);
            setText(s, u"man_id", maneuver);
            setNumber(s, u"plan_progress", m_missionTotal > 0 ? 100.0 * std::max(0, m_missionSeq - 1) / m_missionTotal : 0.0);
            setInteger(s, u"plan_eta", -1);
        } else {
            setInteger(s, u"state", 1); // READY
            setNumber(s, u"plan_progress", -1);
            if (m_planState == 3) // it was running: how did it end?
                outcome = missionState == 5 || (m_missionState != -1 && m_missionTotal > 0 && m_missionSeq >= m_missionTotal) ? 1 : 2;
        }
        if (outcome == 2) {
            // The vehicle's words, as a plan engine's FAILURE reply says them (PlanRuns takes them).
            msg::Message reply = make("PlanControl", now);
            setInteger(reply, u"type", 2); // FAILURE
            setInteger(reply, u"op", 0);   // START
            setText(reply, u"plan_id", plan);
            setText(reply, u"info", !m_armed ? u"disarmed"_s : u"left the mission for %1"_s.arg(modeName()));
            out.push_back(std::move(reply));
        }
        setInteger(s, u"last_outcome", outcome);
        m_planState = executing ? 3 : 1;
        m_missionState = missionState;
        out.push_back(std::move(s));
    }
    return out;
}

} // namespace neptus::transport
