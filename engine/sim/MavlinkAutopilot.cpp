#include "sim/MavlinkAutopilot.h"

#include "messages/MavlinkModes.h"

#include <cmath>

namespace neptus::sim {

using namespace Qt::StringLiterals;

namespace {

// MAV_MISSION_RESULT, MAV_RESULT, MAV_SEVERITY, MISSION_STATE values used here.
constexpr int missionAccepted = 0, missionError = 1, missionUnsupported = 3, missionInvalidSequence = 13,
              missionCancelled = 15;
constexpr int resultAccepted = 0, resultDenied = 2, resultUnsupported = 3, resultFailed = 4;
constexpr int severityCritical = 2, severityWarning = 4, severityNotice = 5, severityInfo = 6;
constexpr int stateNoMission = 1, stateNotStarted = 2, stateActive = 3, stateComplete = 5;

bool isNavigation(quint16 command)
{
    return command < 95;
}

void set(msg::Message &m, QStringView field, double value)
{
    if (const int i = m.def()->indexOf(field); i >= 0)
        m.setNumber(i, value);
}

} // namespace

MavlinkAutopilot::MavlinkAutopilot(std::shared_ptr<const msg::Schema> mavlink, Config config)
    : m_schema(std::move(mavlink))
    , m_config(std::move(config))
{
    m_limits = m_config.type == Type::Boat ? Limits::asv() : Limits::auv();
    m_manualMode = *modeNumber(u"MANUAL"_s);
    m_autoMode = *modeNumber(u"AUTO"_s);
    m_holdMode = modeNumber(u"HOLD"_s).value_or(m_manualMode);
    m_mode = m_manualMode;
    Item home; // read back as a waypoint in frame 0 at its height above sea level
    home.frame = 0;
    home.x = qint32(std::lround(geo::degrees(m_config.home.lat) * 1e7));
    home.y = qint32(std::lround(geo::degrees(m_config.home.lon) * 1e7));
    home.z = float(m_config.home.height);
    m_mission.push_back(home);
    // A few of the vehicle's parameters, with ArduPilot's defaults and types (MAV_PARAM_TYPE:
    // INT8 2, INT16 4, INT32 6, REAL32 9; Rover/Parameters.cpp, ArduSub/Parameters.cpp, the fixtures).
    if (m_config.type == Type::Boat)
        m_parameters = {{"ARMING_CHECK", 1, 6}, {"CRUISE_SPEED", 2, 9}, {"FRAME_CLASS", 2, 2}, {"FS_GCS_ENABLE", 0, 2},
                        {"MAV_GCS_SYSID", 255, 4}, {"MAV_SYSID", 1, 4}, {"MIS_DONE_BEHAVE", 0, 2}, {"RC_OVERRIDE_TIME", 3, 9},
                        {"WP_RADIUS", 2, 9}};
    else
        m_parameters = {{"ARMING_CHECK", 1, 6}, {"FS_GCS_ENABLE", 2, 2}, {"FS_PILOT_INPUT", 2, 2}, {"FS_PILOT_TIMEOUT", 3, 9},
                        {"MAV_GCS_SYSID", 255, 4}, {"MAV_SYSID", 1, 4}, {"WPNAV_SPEED", 100, 9}};
    m_speed = cruiseSpeed();
}

double MavlinkAutopilot::parameterValue(const char *name) const
{
    for (const Parameter &p : m_parameters)
        if (p.name == name)
            return p.value;
    return 0;
}

msg::Message MavlinkAutopilot::parameter(int index, int reportedIndex) const
{
    msg::Message m = make("PARAM_VALUE");
    const Parameter &p = m_parameters[size_t(index)];
    m.setBytes(m.def()->indexOf(u"param_id"), p.name);
    set(m, u"param_value", p.value);
    set(m, u"param_type", p.type);
    set(m, u"param_count", double(m_parameters.size()));
    set(m, u"param_index", reportedIndex);
    return m;
}

std::optional<quint32> MavlinkAutopilot::modeNumber(const QString &name) const
{
    return msg::mavlink::modeNumber(msg::mavlink::Family::ArduPilot, mavType(), name);
}

QString MavlinkAutopilot::modeName() const
{
    return msg::mavlink::modeName(msg::mavlink::Family::ArduPilot, mavType(), m_mode);
}

msg::Message MavlinkAutopilot::make(const char *name) const
{
    return msg::Message(m_schema->byAbbrev(QString::fromLatin1(name)));
}

msg::Message MavlinkAutopilot::ack(quint16 command, int result) const
{
    msg::Message m = make("COMMAND_ACK");
    set(m, u"command", command);
    set(m, u"result", result);
    set(m, u"target_system", m_to);
    set(m, u"target_component", m_toComponent);
    return m;
}

msg::Message MavlinkAutopilot::text(int severity, const QString &words) const
{
    msg::Message m = make("STATUSTEXT");
    set(m, u"severity", severity);
    m.setBytes(m.def()->indexOf(u"text"), words.toUtf8().left(50));
    return m;
}

msg::Message MavlinkAutopilot::missionAck(int type, int result) const
{
    msg::Message m = make("MISSION_ACK");
    set(m, u"type", result);
    set(m, u"mission_type", type);
    set(m, u"target_system", m_to);
    set(m, u"target_component", m_toComponent);
    return m;
}

// ArduPilot asks with MISSION_REQUEST (not _INT), whatever the ground station uses.
msg::Message MavlinkAutopilot::request(const Upload &u) const
{
    msg::Message m = make("MISSION_REQUEST");
    set(m, u"seq", u.next);
    set(m, u"mission_type", u.type);
    set(m, u"target_system", m_to);
    set(m, u"target_component", m_toComponent);
    return m;
}

// What it holds of a MAV_MISSION_TYPE (0 mission, 1 fence, 2 rally; callers keep to these).
std::vector<MavlinkAutopilot::Item> &MavlinkAutopilot::held(int type)
{
    return type == 1 ? m_fence : type == 2 ? m_rally : m_mission;
}

const std::vector<MavlinkAutopilot::Item> &MavlinkAutopilot::held(int type) const
{
    return type == 1 ? m_fence : type == 2 ? m_rally : m_mission;
}

msg::Message MavlinkAutopilot::item(int type, int seq) const
{
    const Item &i = held(type)[size_t(seq)];
    msg::Message m = make("MISSION_ITEM_INT");
    set(m, u"seq", seq);
    set(m, u"frame", i.frame);
    set(m, u"command", i.command);
    set(m, u"autocontinue", i.autocontinue);
    const float p[] = {i.p1, i.p2, i.p3, i.p4};
    for (int k = 0; k < 4; ++k)
        set(m, u"param%1"_s.arg(k + 1), p[k]);
    m.setInteger(m.def()->indexOf(u"x"), i.x);
    m.setInteger(m.def()->indexOf(u"y"), i.y);
    set(m, u"z", i.z);
    set(m, u"mission_type", type);
    set(m, u"target_system", m_to);
    set(m, u"target_component", m_toComponent);
    return m;
}

std::vector<msg::Message> MavlinkAutopilot::receive(const msg::Message &m, double now)
{
    std::vector<msg::Message> out;
    if (!m.def())
        return out;
    // Answers go to who asked (GCS_MAVLink: its system and component as targets).
    if (m.header.src != 0 && m.header.src <= 255) {
        m_to = quint8(m.header.src);
        m_toComponent = quint8(m.header.srcEnt);
    }
    const QString &type = m.def()->abbrev;
    const auto missionType = [&] { return int(m.integer(u"mission_type")); };
    if (type == u"MISSION_COUNT") {
        if (missionType() > 2) {
            out.push_back(missionAck(missionType(), missionUnsupported));
            return out;
        }
        Upload u;
        u.type = missionType();
        u.count = int(m.integer(u"count"));
        u.askedAt = u.lastItemAt = now;
        if (u.count == 0) {
            held(u.type).resize(u.type == 0 ? 1 : 0); // a mission keeps its home
            out.push_back(missionAck(u.type, missionAccepted));
            return out;
        }
        m_upload = u;
        out.push_back(request(*m_upload));
    } else if (type == u"MISSION_ITEM_INT" || type == u"MISSION_ITEM") {
        if (!m_upload || missionType() != m_upload->type) {
            out.push_back(missionAck(missionType(), missionError));
            return out;
        }
        Upload &u = *m_upload;
        if (m.integer(u"seq") != u.next) {
            out.push_back(missionAck(u.type, missionInvalidSequence));
            return out;
        }
        Item i = plans::missionItemFrom(m);
        i = plans::keptByArduPilot(i, plans::MissionType(u.type)); // what AP_Mission, the fence and AP_Rally keep
        u.items.push_back(i);
        ++u.next;
        u.askedAt = u.lastItemAt = now;
        if (u.next < u.count) {
            out.push_back(request(u));
            return out;
        }
        if (u.type != 0) {
            held(u.type) = std::move(u.items);
        } else {
            u.items[0] = m_mission[0]; // its own home, whatever was sent
            m_mission = std::move(u.items);
            resetMission();
            if (m_mission.size() < 2)
                m_missionState = stateNoMission;
            out.push_back(text(severityInfo, u"Flight plan received"_s));
        }
        const int uploaded = u.type;
        m_upload.reset();
        out.push_back(missionAck(uploaded, missionAccepted));
    } else if (type == u"MISSION_CLEAR_ALL") {
        // MissionItemProtocol::handle_mission_clear_all: an upload under way is cancelled, all is gone but the
        // mission's home, and ACCEPTED; but AP_Mission::clear() refuses while armed and running the mission.
        if (missionType() > 2) {
            out.push_back(missionAck(missionType(), missionUnsupported));
            return out;
        }
        m_upload.reset();
        if (missionType() == 0 && m_armed && m_missionState == stateActive) {
            out.push_back(missionAck(missionType(), missionError));
            return out;
        }
        held(missionType()).resize(missionType() == 0 ? 1 : 0);
        if (missionType() == 0) {
            resetMission();
            m_missionState = stateNoMission;
        }
        out.push_back(missionAck(missionType(), missionAccepted));
    } else if (type == u"MISSION_REQUEST_LIST") {
        msg::Message count = make("MISSION_COUNT");
        set(count, u"count", double(missionType() > 2 ? 0 : held(missionType()).size()));
        set(count, u"mission_type", missionType());
        set(count, u"target_system", m_to);
        set(count, u"target_component", m_toComponent);
        out.push_back(std::move(count));
    } else if (type == u"MISSION_REQUEST_INT" || type == u"MISSION_REQUEST") {
        const int seq = int(m.integer(u"seq"));
        const size_t size = missionType() > 2 ? 0 : held(missionType()).size();
        if (seq < 0 || size_t(seq) >= size)
            out.push_back(missionAck(missionType(), missionInvalidSequence));
        else
            out.push_back(item(missionType(), seq));
    } else if (type == u"COMMAND_LONG") {
        return command(m, now);
    } else if (type == u"PARAM_REQUEST_LIST") {
        for (size_t i = 0; i < m_parameters.size(); ++i)
            out.push_back(parameter(int(i), int(i)));
    } else if (type == u"PARAM_REQUEST_READ" || type == u"PARAM_SET") {
        const bool setting = type == u"PARAM_SET";
        const QByteArray id = m.bytes(m.def()->indexOf(u"param_id"));
        const qint64 index = setting ? -1 : m.integer(u"param_index"); // -1: by name
        const auto found = std::find_if(m_parameters.begin(), m_parameters.end(), [&](const Parameter &p) {
            return index >= 0 ? &p - m_parameters.data() == index : p.name == id;
        });
        if (found == m_parameters.end())
            return out; // ArduPilot says nothing of a parameter it does not have
        if (setting)
            found->value = float(m.number(u"param_value"));
        out.push_back(parameter(int(found - m_parameters.begin()), setting ? 65535 : int(found - m_parameters.begin())));
    } else if (type == u"MANUAL_CONTROL") {
        m_manual = {int(m.integer(u"x")), int(m.integer(u"y")), int(m.integer(u"z")), int(m.integer(u"r"))};
        m_manualAt = now;
    }
    return out;
}

bool MavlinkAutopilot::setMode(quint32 mode, std::vector<msg::Message> &out)
{
    if (mode == m_autoMode && m_mission.size() < 2) {
        // Rover/mode_auto.cpp and Rover/system.cpp; ArduSub/mode.cpp says only the second.
        if (m_config.type == Type::Boat) {
            out.push_back(text(severityNotice, u"No Mission. Can't set AUTO."_s));
            out.push_back(text(severityWarning, u"Flight mode change failed"_s));
        } else {
            out.push_back(text(severityWarning, u"Flight mode change failed AUTO"_s));
        }
        return false;
    }
    if (mode == m_autoMode && m_mode != mode && m_missionState == stateComplete) {
        m_current = 1; // a finished mission starts again
        m_missionState = stateNotStarted;
    }
    m_mode = mode;
    return true;
}

std::vector<msg::Message> MavlinkAutopilot::command(const msg::Message &m, double)
{
    std::vector<msg::Message> out;
    const quint16 cmd = quint16(m.integer(u"command"));
    const auto p = [&](int i) { return m.number(u"param%1"_s.arg(i)); };
    switch (cmd) {
    case 176: { // MAV_CMD_DO_SET_MODE
        if (!(int(p(1)) & 1)) {
            out.push_back(ack(cmd, resultDenied));
            return out;
        }
        const quint32 mode = quint32(p(2));
        if (msg::mavlink::modeName(msg::mavlink::Family::ArduPilot, mavType(), mode).startsWith(u"mode "_s)) {
            out.push_back(ack(cmd, resultFailed));
            out.push_back(text(severityWarning, u"No such mode %1"_s.arg(mode)));
            return out;
        }
        std::vector<msg::Message> words;
        const bool ok = setMode(mode, words);
        out.push_back(ack(cmd, ok ? resultAccepted : resultFailed));
        out.insert(out.end(), words.begin(), words.end());
        return out;
    }
    case 300: { // MAV_CMD_MISSION_START (Rover: AUTO)
        std::vector<msg::Message> words;
        const bool ok = setMode(m_autoMode, words);
        out.push_back(ack(cmd, ok ? resultAccepted : resultFailed));
        out.insert(out.end(), words.begin(), words.end());
        return out;
    }
    case 400: { // MAV_CMD_COMPONENT_ARM_DISARM
        const bool arm = p(1) > 0.5;
        if (arm && !m_armed && !m_config.armingFailures.isEmpty() && int(p(2)) != 2989) {
            out.push_back(ack(cmd, resultFailed));
            for (const QString &why : m_config.armingFailures)
                out.push_back(text(severityCritical, u"Arm: "_s + why));
            return out;
        }
        out.push_back(ack(cmd, resultAccepted));
        if (arm != m_armed) {
            m_armed = arm;
            if (!arm && (m_config.type == Type::Sub || m_mode != m_autoMode))
                resetMission();
            const bool rover = m_config.type == Type::Boat;
            out.push_back(text(severityInfo, arm ? (rover ? u"Throttle armed"_s : u"Arming motors"_s)
                                                 : (rover ? u"Throttle disarmed"_s : u"Disarming motors"_s)));
        }
        return out;
    }
    case 224: { // MAV_CMD_DO_SET_MISSION_CURRENT
        const int seq = std::max(1, int(p(1))); // 0 is the home: the mission's first item
        if (seq >= int(m_mission.size())) {
            out.push_back(ack(cmd, resultDenied));
            return out;
        }
        m_current = seq;
        if (m_missionState == stateComplete)
            m_missionState = stateNotStarted;
        out.push_back(ack(cmd, resultAccepted));
        return out;
    }
    case 511: // MAV_CMD_SET_MESSAGE_INTERVAL
    case 512: // MAV_CMD_REQUEST_MESSAGE
        out.push_back(ack(cmd, resultAccepted));
        return out;
    default:
        out.push_back(ack(cmd, resultUnsupported));
        return out;
    }
}

const MavlinkAutopilot::Item *MavlinkAutopilot::currentNav()
{
    return m_current >= 1 && m_current < int(m_mission.size()) ? &m_mission[size_t(m_current)] : nullptr;
}

void MavlinkAutopilot::resetMission()
{
    m_current = 1;
    m_lastNav = 0;
    m_speed = cruiseSpeed();
    if (m_mission.size() > 1)
        m_missionState = stateNotStarted;
}

double MavlinkAutopilot::cruiseSpeed() const
{
    return m_config.type == Type::Boat ? parameterValue("CRUISE_SPEED") : parameterValue("WPNAV_SPEED") / 100.0;
}

void MavlinkAutopilot::run(double dt, std::vector<msg::Message> &out)
{
    const double overrideSeconds = parameterValue(m_config.type == Type::Boat ? "RC_OVERRIDE_TIME" : "FS_PILOT_TIMEOUT");
    if (m_manualAt >= 0 && m_lastStep - m_manualAt >= overrideSeconds) { // the override is forgotten
        m_manualAt = -1;
        m_manual = {0, 0, 0, 0};
        if (m_config.type == Type::Sub && m_armed && parameterValue("FS_PILOT_INPUT") == 2) { // 2: disarm
            out.push_back(text(severityCritical, u"Lost manual control"_s));
            m_armed = false;
            resetMission();
            out.push_back(text(severityInfo, u"Disarming motors"_s));
        }
    }
    if (m_mode == m_manualMode && m_armed && m_manualAt >= 0) {
        const bool sub = m_config.type == Type::Sub;
        const double throttle = (sub ? m_manual[0] : m_manual[2]) / 1000.0, turn = (sub ? m_manual[3] : m_manual[1]) / 1000.0;
        const double heading = m_motion.psi + turn * m_limits.turnRate * std::max(dt, 0.05) * 4;
        const Eigen::Vector2d ahead = m_motion.ned.head<2>() + 50.0 * Eigen::Vector2d(std::cos(heading), std::sin(heading));
        if (throttle > 0.01)
            steer(m_motion, ahead, throttle * m_limits.maxSpeed, nullptr, dt, m_limits);
        else
            hold(m_motion, nullptr, dt, m_limits);
        return;
    }
    const bool autoMode = m_mode == m_autoMode;
    if (!autoMode || m_missionState == stateComplete || m_mission.size() < 2) {
        if (!autoMode && m_missionState == stateActive)
            m_missionState = stateNotStarted; // left the mission: it resumes where it was
        hold(m_motion, nullptr, dt, m_limits);
        return;
    }
    // In AUTO the mission is ACTIVE, armed or not (ArduRover's MISSION_CURRENT in the fixture); it moves once armed.
    if (m_missionState != stateActive) {
        m_missionState = stateActive;
        out.push_back(text(severityInfo, u"Mission: %1 WP"_s.arg(m_current)));
    }
    if (!m_armed) {
        hold(m_motion, nullptr, dt, m_limits);
        return;
    }
    // Commands that are not navigation ones happen at once.
    while (const Item *i = currentNav()) {
        if (isNavigation(i->command))
            break;
        if (i->command == 178 && i->p2 > 0) { // MAV_CMD_DO_CHANGE_SPEED (else CRUISE_SPEED / WPNAV_SPEED)
            m_speed = i->p2;
            out.push_back(text(severityInfo, u"Mission: %1 ChangeSpeed"_s.arg(m_current))); // AP_Mission, as the fixture
        }
        ++m_current;
    }
    const Item *target = currentNav();
    if (!target) {
        m_missionState = stateComplete;
        if (m_config.type == Type::Boat)
            out.push_back(text(severityNotice, u"Mission Complete"_s));
        return;
    }
    const geo::Geodetic point{geo::radians(target->x * 1e-7), geo::radians(target->y * 1e-7), 0};
    const Eigen::Vector3d ned = geo::toNed(point, m_config.home);
    const double down = m_config.type == Type::Sub ? std::max(0.0, double(-target->z)) : 0.0;
    if (!steer(m_motion, ned.head<2>(), m_speed, &down, dt, m_limits))
        return;
    msg::Message reached = make("MISSION_ITEM_REACHED");
    set(reached, u"seq", m_current);
    m_lastNav = m_current;
    out.push_back(std::move(reached));
    // Rover/mode_auto.cpp; ArduSub/commands_logic.cpp says "command".
    out.push_back(text(severityInfo, (m_config.type == Type::Boat ? u"Reached waypoint #%1"_s : u"Reached command #%1"_s).arg(m_current)));
    ++m_current;
    if (currentNav())
        out.push_back(text(severityInfo, u"Mission: %1 WP"_s.arg(m_current)));
}

std::vector<msg::Message> MavlinkAutopilot::step(double now)
{
    std::vector<msg::Message> out;
    const double dt = m_lastStep < 0 ? 0 : std::min(1.0, now - m_lastStep);
    m_lastStep = now;
    if (m_upload) {
        Upload &u = *m_upload;
        if (now - u.lastItemAt >= 8.0) { // GCS_MAVLink: the upload is given up 8 s after the last item
            out.push_back(text(severityWarning, u"Mission upload timeout"_s));
            out.push_back(missionAck(u.type, missionCancelled));
            m_upload.reset();
        } else if (now - u.askedAt >= 1.0) { // asked again a second later
            u.askedAt = now;
            out.push_back(request(u));
        }
    }
    run(dt, out);
    if (now - m_lastFast >= 0.2) {
        m_lastFast = now;
        const geo::Geodetic here = geo::fromNed(m_motion.ned, m_config.home);
        msg::Message g = make("GLOBAL_POSITION_INT");
        set(g, u"time_boot_ms", std::fmod(now * 1000, 4e9));
        g.setInteger(g.def()->indexOf(u"lat"), std::lround(geo::degrees(here.lat) * 1e7));
        g.setInteger(g.def()->indexOf(u"lon"), std::lround(geo::degrees(here.lon) * 1e7));
        set(g, u"alt", std::lround(-m_motion.ned.z() * 1000));
        set(g, u"relative_alt", std::lround(-m_motion.ned.z() * 1000));
        set(g, u"vx", std::lround(m_motion.speed * std::cos(m_motion.psi) * 100));
        set(g, u"vy", std::lround(m_motion.speed * std::sin(m_motion.psi) * 100));
        set(g, u"hdg", std::lround(std::fmod(geo::degrees(m_motion.psi) + 360.0, 360.0) * 100));
        out.push_back(std::move(g));
    }
    if (now - m_lastSlow >= 1.0) {
        m_lastSlow = now;
        msg::Message beat = make("HEARTBEAT");
        set(beat, u"type", mavType());
        set(beat, u"autopilot", 3); // MAV_AUTOPILOT_ARDUPILOTMEGA
        set(beat, u"base_mode", 1 | (m_armed ? 128 : 0));
        set(beat, u"custom_mode", m_mode);
        // MAV_STATE ACTIVE 4, STANDBY 3: Rover is STANDBY in HOLD only (GCS_MAVLink_Rover.cpp), Sub when disarmed.
        const bool standby = m_config.type == Type::Boat ? m_mode == m_holdMode : !m_armed;
        set(beat, u"system_status", standby ? 3 : 4);
        set(beat, u"mavlink_version", 3);
        out.push_back(std::move(beat));
        msg::Message current = make("MISSION_CURRENT");
        // seq: the nav command running, 0 before one is (AP_Mission::get_current_nav_index), the
        // last one once complete (the sub fixture: seq 3, COMPLETE, through SURFACE and MANUAL).
        const int seq = m_missionState == stateActive ? m_current : m_missionState == stateComplete ? m_lastNav : 0;
        set(current, u"seq", seq);
        set(current, u"total", double(m_mission.size()) - 1);
        set(current, u"mission_state", m_mission.size() < 2 ? stateNoMission : m_missionState);
        // mission_mode: Rover's modes that run the mission (current_mode_requires_mission); Sub sends 0.
        set(current, u"mission_mode", m_config.type == Type::Boat && m_mode == m_autoMode ? 1 : 0);
        out.push_back(std::move(current));
        msg::Message status = make("SYS_STATUS");
        set(status, u"voltage_battery", 15800);
        set(status, u"battery_remaining", 87);
        out.push_back(std::move(status));
        msg::Message battery = make("BATTERY_STATUS"); // as ArduPilot sends it beside SYS_STATUS
        set(battery, u"voltages[0]", 15800);
        for (int cell = 1; cell < 10; ++cell)
            set(battery, u"voltages[%1]"_s.arg(cell), 65535);
        set(battery, u"current_battery", m_armed ? 420 : 30);
        set(battery, u"current_consumed", -1);
        set(battery, u"energy_consumed", -1);
        set(battery, u"temperature", 32767);
        set(battery, u"battery_remaining", 87);
        out.push_back(std::move(battery));
    }
    return out;
}

} // namespace neptus::sim
