#pragma once

#include "alarms/AlarmGraph.h"
#include "messages/Codec.h"
#include "plans/MavlinkMission.h"
#include "mission/Mission.h"
#include "mission/PlanCheck.h"
#include "mission/Vehicle.h"
#include "plans/PlanClient.h"
#include "plans/PlanDatabase.h"
#include "runs/PlanRuns.h"
#include "plans/Supervisor.h"
#include "tree/VariableTree.h"

#include <QHash>
#include <QObject>
#include <QTimer>

#include <expected>
#include <functional>
#include <map>
#include <memory>

namespace neptus::plans {

// The console's desk for plans on vehicles. For each vehicle (by the name
// the tree shows it by): what its plan database holds (PlanDB GET_DSTATE,
// fetched on first look and after every change), whether each plan of the
// open mission is there exactly as here (the MD5s DUNE keeps), and the
// commands — send, remove, start, stop, abort. START is refused while the
// vehicle's copy differs from the mission's or is missing: the operator
// sends it first. Every command, reply and start and end of a plan is a
// line of the vehicle's log; a plan's end — as the vehicle's PlanControlState
// tells it (PlanRuns), whoever started the plan, also one that began before
// this console joined — is also an event on the alarm node
// "systems/<vehicle>/plan", exactly once: Warning when it failed, with the
// vehicle's reason; Info when it completed, was stopped or replaced. A plan with
// conditions on its transitions is carried out by a Supervisor, one stretch
// at a time, for every vehicle: DUNE ignores conditions, and only the
// console sees every vehicle a condition may name.
//
// A MAVLink vehicle (its HEARTBEAT is in the tree) holds one mission, not a
// database of plans: a plan is translated to mission items and a geofence
// (MavlinkSupport::translate), uploaded with the MAVLink mission protocol
// and read back to compare; the vehicle "holds" the plan whose items are
// what it keeps of them (missionDifference). Start: mission item 1, arm when disarmed, then the mission mode
// (ArduPilot AUTO); each refusal is said in the vehicle's own words. Stop:
// its stop mode (ArduPilot Rover HOLD, Sub POSHOLD); Abort goes through the
// link (its abort mode). Conditions on transitions are not carried out for
// MAVLink vehicles (they are refused at start).
class PlanDesk : public QObject
{
    Q_OBJECT

public:
    using Sender = std::function<std::expected<void, QString>(quint16 system, const msg::Message &message)>;
    // The console's script host, made on first use (conditions run there).
    using Scripts = std::function<scripting::ScriptHost *()>;

    struct StoredPlan
    {
        QString id;
        QByteArray md5;
        int size = 0;
        double changeTime = 0;
    };

    // What the desk needs for MAVLink vehicles, from the layers above it.
    struct MavlinkSupport
    {
        std::function<std::shared_ptr<const msg::Schema>()> schema; // MAVLink's (loaded on first use)
        // A plan as mission items and geofence; an error names the maneuver or item.
        // Given the plan's vehicle definition, if it has one.
        std::function<std::expected<MavlinkPlan, QString>(const mission::Mission &, const mission::Plan &,
                                                          const mission::VehicleDefinition *)> translate;
        // The plan a vehicle holds, for its progress (Console::labelMission).
        std::function<void(quint16 system, const QString &planId, const QStringList &maneuverOfItem)> label;
        // The mode Stop puts it in ("" for its autopilot's default).
        std::function<QString(quint16 system)> stopMode;
    };
    // A mission transfer under way: "uploading plan1", items done of all.
    struct Transfer
    {
        QString what;
        int done = 0;
        int total = 0;
    };

    PlanDesk(std::shared_ptr<const msg::Schema> schema, const tree::VariableTree &tree, alarms::AlarmGraph &graph,
             Sender send, Scripts scripts = {}, const Clock *clock = &Clock::system(), QObject *parent = nullptr);

    void setMavlink(MavlinkSupport support);
    bool isMavlink(const QString &system) const;
    std::optional<Transfer> transfer(const QString &system) const;
    // Retries of the MAVLink mission protocol, scaled (tests shorten them).
    void setMavlinkTimeScale(double scale) { m_mavlinkScale = scale; }

    // The mission whose plans are offered; an error names the file and line.
    std::expected<void, QString> openMission(const QString &path);
    void setMission(mission::Mission mission, const QString &path = {});
    // Checks of a plan beyond mission::checkPlan that the console has (the
    // charts: charts::checkAgainstCharts); their errors keep a plan from being
    // sent as checkPlan's do. recheck() asks again (the charts were read).
    using ExtraCheck = std::function<QList<mission::PlanProblem>(const mission::Plan &, const mission::PlanGeometry &,
                                                                const mission::VehicleDefinition *)>;
    void setExtraCheck(ExtraCheck check);
    void recheck();
    const mission::Mission &mission() const { return m_mission; }
    // What is wrong with the open mission for running it: conditions that do
    // not compile ("meet: out → dive: condition '…' does not compile: …").
    QStringList problems() const { return m_problems; }
    QString missionPath() const { return m_missionPath; }

    // The mission's plans for a vehicle (each plan names its vehicle).
    QList<const mission::Plan *> missionPlans(const QString &system) const;
    // A plan by id: the mission's, the whole plan a stretch being supervised
    // belongs to, else the vehicle's own copy once fetched (GET).
    std::optional<mission::Plan> plan(const QString &system, const QString &planId);
    // What the vehicle's database held when last asked; empty until it answers.
    std::vector<StoredPlan> storedPlans(const QString &system) const;
    bool fetched(const QString &system) const;
    // The mission's plan against the vehicle's copy.
    Sync sync(const QString &system, const QString &planId) const;
    QStringList log(const QString &system) const;
    // The vehicle's Announce lists evaluatesConditionsService.
    bool evaluatesConditions(const QString &system) const;

    // Commands. An error says why nothing was sent; what the vehicle answers
    // (or its silence, after retries) comes to the log.
    std::expected<void, QString> refresh(const QString &system);
    // A console that replays a log asks vehicles nothing (its commands are refused by the console).
    void setQuiet(bool quiet) { m_quiet = quiet; }
    // What system `id` holds as `plan.id`, known otherwise than by asking it
    // (a replayed log's PlanSpecification): the map draws it while it runs.
    void learnPlan(quint16 id, mission::Plan plan);
    std::expected<void, QString> send(const QString &system, const QString &planId);
    std::expected<void, QString> remove(const QString &system, const QString &planId);
    std::expected<void, QString> start(const QString &system, const QString &planId);
    std::expected<void, QString> stop(const QString &system);
    std::expected<void, QString> abort(const QString &system);

    // A PlanDB, PlanControl or PlanControlState from the links (Console::planMessageReceived).
    void receive(const msg::Message &message);
    // Whether a plan of this vehicle's runs under supervision now.
    bool supervising(const QString &system) const;
    // Supervisors look at their vehicles and decide, and plan ends that
    // waited for the vehicle's reason are told (a timer does it every second
    // while there is something to do).
    void supervise();
    // The vehicle definitions read when the mission opened (shared with the
    // console's depth watch, so they are read once).
    const mission::VehicleCatalog &definitions() const { return m_definitions; }

    // Replies come within this or are asked again (tests shorten it).
    void setTimeout(std::chrono::milliseconds timeout) { m_timeout = timeout; }

signals:
    // A vehicle's stored plans, sync or log changed.
    void changed(const QString &system);
    // Another mission is open (or the same, changed).
    void missionChanged();
    // What the desk learnt of a vehicle's run beyond its reports, for other
    // trackers of the same runs (the database's): the run is known by another
    // name from now on (a MAVLink mission recognised as a plan); the vehicle
    // accepted a stop by other means than a PlanControl reply.
    void runRelabelled(quint16 system, const QString &plan);
    void stopAccepted(quint16 system);

private:
    struct Vehicle
    {
        std::unique_ptr<PlanClient> client;
        std::vector<StoredPlan> stored;
        bool fetched = false;
        std::map<QString, mission::Plan> copies; // its plans, fetched with GET
        QStringList log;
        bool asking = false; // a GET_DSTATE is on its way
        std::unique_ptr<Supervisor> supervisor;
        QString supervisedPlan; // the plan whose stretches ("survey.2") it was last given
        // A MAVLink vehicle's: its mission client, what to do when each operation ends, the transfer shown.
        std::unique_ptr<MavlinkMissionClient> mission;
        std::map<int, std::function<void(const MavlinkMissionClient::Result &)>> then;
        std::optional<Transfer> transfer;
        std::map<int, QString> transferNames; // by operation: what its progress is called
        std::vector<MissionItem> held; // the mission it holds, as read back
        QString heldPlan;               // the plan it was recognised as ("" when none)
    };

    std::expected<Vehicle *, QString> vehicle(const QString &system);
    Vehicle &vehicleFor(quint16 id); // made with its plan client on first use
    Vehicle *known(const QString &system);
    const Vehicle *known(const QString &system) const;
    std::expected<msg::Message, QString> specification(const QString &system, const QString &planId) const;
    void note(quint16 id, const QString &line);
    void ask(Vehicle &v);
    void replied(quint16 id, const PlanClient::Reply &reply);
    // A plan started, or ended (PlanRuns): the log, the alarm event, the supervisor.
    void told(const PlanRuns::Event &event);
    bool isMavlink(quint16 id) const;
    alarms::AlarmGraph::NodeId planNode(quint16 id);
    void planAlarm(quint16 id, alarms::Level level, const QString &text);
    MavlinkMissionClient &missionClient(quint16 id);
    void after(quint16 id, int operation, std::function<void(const MavlinkMissionClient::Result &)> then);
    const std::expected<MavlinkPlan, QString> &mavlinkPlan(const mission::Plan &plan) const;
    const mission::Plan *missionPlan(const QString &system, const QString &planId) const;
    void heldMission(quint16 id, const std::vector<MissionItem> &items);
    std::expected<void, QString> sendMavlink(quint16 id, const mission::Plan &plan);
    // The geofence or rally points sent with a plan, read back and compared (nothing when none were sent).
    void readBack(quint16 id, const QString &planId, MissionType type, const std::vector<MissionItem> &sent);
    std::expected<void, QString> startMavlink(quint16 id, const QString &planId);
    std::expected<void, QString> stopMavlink(quint16 id);
    double heartbeatNumber(quint16 id, const QString &field) const;

    std::shared_ptr<const msg::Schema> m_schema;
    msg::Codec m_codec;
    const tree::VariableTree &m_tree;
    alarms::AlarmGraph &m_graph;
    Sender m_send;
    Scripts m_scripts;
    const Clock *m_clock;
    QTimer m_supervision;
    mission::Mission m_mission;
    QString m_missionPath;
    QStringList m_problems;
    QHash<QString, QStringList> m_planErrors; // plan id -> its errors (mission::checkPlan, m_extraCheck)
    ExtraCheck m_extraCheck;
    std::map<QString, QByteArray> m_md5; // the mission's plans' MD5s, by plan id
    std::map<quint16, Vehicle> m_vehicles;
    PlanRuns m_runs;
    bool m_quiet = false; // setQuiet
    std::chrono::milliseconds m_timeout{3000};
    MavlinkSupport m_mavlink;
    mutable std::map<QString, std::expected<MavlinkPlan, QString>> m_mavlinkPlans; // by plan id, for this mission
    mission::VehicleCatalog m_definitions; // read when a mission opens
    double m_mavlinkScale = 1.0;
};

} // namespace neptus::plans
