#pragma once

#include "messages/Message.h"
#include "mission/Mission.h"

#include <QObject>
#include <QTimer>

#include <array>
#include <deque>
#include <expected>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace neptus::plans {

// One MAVLink mission item (MISSION_ITEM_INT's fields), and the maneuver of
// the plan it was made from ("" for home and for what the vehicle holds).
struct MissionItem
{
    quint16 command = 16; // MAV_CMD_NAV_WAYPOINT
    quint8 frame = 3;     // MAV_FRAME_GLOBAL_RELATIVE_ALT
    float p1 = 0, p2 = 0, p3 = 0, p4 = 0;
    qint32 x = 0, y = 0;  // degrees × 1e7 (or a local/mission value)
    float z = 0;
    quint8 autocontinue = 1;
    QString maneuver;
};

// An item as a MISSION_ITEM_INT (or an older autopilot's MISSION_ITEM, in float degrees) carries it.
MissionItem missionItemFrom(const msg::Message &message);

// MAV_MISSION_TYPE: the mission, the geofence, the rally points.
enum class MissionType { Mission = 0, Fence = 1, Rally = 2 };

// What a plan becomes on a MAVLink vehicle: the mission's items (item 0
// home, as ArduPilot counts it), the geofence made of the mission's
// operating areas (inclusion) and no-go areas (exclusion), and its rally points.
struct MavlinkPlan
{
    std::vector<MissionItem> items;
    std::vector<MissionItem> fence;
    std::vector<MissionItem> rally;
    QStringList maneuverOfItem() const;
};

// The items a mission translation made (the "mavlink" target:
// <mission-items><item maneuver command frame p1 p2 p3 p4 lat lon alt/>…),
// after a home item at `home`; an error names the item and attribute.
std::expected<std::vector<MissionItem>, QString> missionItemsFromXml(QByteArrayView xml, const mission::GeoPosition &home);
// The geofence of a mission's areas: each operating area an inclusion
// polygon, each no-go area an exclusion polygon (MAV_CMD_NAV_FENCE_POLYGON_VERTEX_*).
std::vector<MissionItem> missionFence(const mission::Mission &mission);
// The rally points of a mission: each mark of role "rally", a
// MAV_CMD_NAV_RALLY_POINT at its position and height above home (frame 3).
std::vector<MissionItem> missionRally(const mission::Mission &mission);

// Whether the vehicle holds what was sent: "" when it does, else the first
// difference, said for people ("item 3: latitude 41.1861769 sent, 41.186177
// held"). What ArduPilot is known to change is not a difference: item 0 of
// a mission is the vehicle's own home; frames fold to 0, 3 or 10; the
// parameters a command does not keep read back 0 (a waypoint's acceptance
// radius and yaw), those it keeps in 16 bits come back whole; altitudes are
// kept in whole centimetres; a fence vertex keeps its count and position
// only; a rally point its position, its frame and its altitude in whole
// metres (AP_Mission, MissionItemProtocol_Fence, MissionItemProtocol_Rally;
// docs/mavlink.md).
QString missionDifference(const std::vector<MissionItem> &sent, const std::vector<MissionItem> &held, MissionType type);
// What ArduPilot keeps of an item and reads back (the rules above); the
// simulated ArduPilot (sim::MavlinkAutopilot) stores its items through it.
MissionItem keptByArduPilot(const MissionItem &item, MissionType type);

// Talks to one MAVLink vehicle's mission and command handling, through
// MAVLink messages sent to its console id (the link fills in its system and
// component). One operation at a time, in order; each ends with a Result,
// never silently:
//  - upload: MISSION_COUNT, then each item the vehicle asks for
//    (MISSION_REQUEST or MISSION_REQUEST_INT — ArduPilot asks with the
//    former, and re-asks a second later) sent as MISSION_ITEM_INT, until its
//    MISSION_ACK: ACCEPTED, or the refusal by its MAV_MISSION_RESULT name
//    and meaning. MISSION_COUNT is sent again while nothing is asked (3
//    tries); a vehicle that stops asking ends it after 9 s (ArduPilot gives
//    up after 8 s and says so with OPERATION_CANCELLED).
//  - download: MISSION_REQUEST_LIST, its MISSION_COUNT, each item asked
//    with MISSION_REQUEST_INT (again after a second, 5 tries), then our ACK.
//  - command: COMMAND_LONG until its COMMAND_ACK (again with the
//    confirmation counted up, 3 tries); IN_PROGRESS keeps waiting; a refusal
//    comes with the vehicle's own words, the warnings (STATUSTEXT, severity
//    WARNING or worse) it said with it ("Arm: Gyros inconsistent").
class MavlinkMissionClient : public QObject
{
    Q_OBJECT

public:
    using Sender = std::function<std::expected<void, QString>(const msg::Message &)>;
    struct Result
    {
        int id = 0;
        QString what;        // "upload mission", "download fence", "arm", "mode AUTO"
        bool ok = false;
        QString info;        // the vehicle's answer, or why it failed here
        std::vector<MissionItem> items; // a download's
        int attempts = 0;
    };

    MavlinkMissionClient(std::shared_ptr<const msg::Schema> mavlink, quint16 vehicle, Sender send, QObject *parent = nullptr);

    quint16 vehicle() const { return m_vehicle; }
    // Ground station ids (replies addressed to another are not ours).
    void setOwnSystem(quint8 system) { m_ownSystem = system; }
    // Time scale of the retries (tests shorten it): 1.0 is the times above.
    void setTimeScale(double scale) { m_scale = scale; }

    int upload(MissionType type, std::vector<MissionItem> items);
    int download(MissionType type);
    int command(quint16 command, std::array<float, 7> params, QString what);
    bool busy() const { return m_current.has_value() || !m_queue.empty(); }

    // A MAVLink message from the vehicle. True when it was part of an operation.
    bool receive(const msg::Message &message);

signals:
    void finished(const neptus::plans::MavlinkMissionClient::Result &result);
    // An upload's or download's progress: items done of all.
    void progress(int id, int done, int total);

private:
    struct Operation
    {
        enum class Kind { Upload, Download, Command } kind = Kind::Upload;
        int id = 0;
        QString what;
        MissionType type = MissionType::Mission;
        std::vector<MissionItem> items;  // to send, or received
        int count = -1;                  // a download's, once told
        int next = 0;                    // the next item to ask for (download)
        quint16 command = 0;
        std::array<float, 7> params{};
        int attempts = 0;                // sends of the current step
        int totalSends = 0;
        qint64 lastHeardMs = 0;
        QStringList said;                // warnings heard while it ran
        std::optional<msg::Message> refusal; // a command's refusing ACK, waiting for its words
    };

    void startNext();
    void step();         // sends the current step (again)
    void timeout();
    void finish(bool ok, const QString &info);
    msg::Message make(const char *name) const;
    void send(const msg::Message &m);
    void sendItem(int seq);
    QString enumText(const msg::Message &m, const char *field, bool withMeaning) const;
    qint64 nowMs() const;

    std::shared_ptr<const msg::Schema> m_schema;
    quint16 m_vehicle;
    Sender m_send;
    quint8 m_ownSystem = 255;
    double m_scale = 1.0;
    int m_nextId = 1;
    std::deque<Operation> m_queue;
    std::optional<Operation> m_current;
    QTimer m_timer;
};

} // namespace neptus::plans
