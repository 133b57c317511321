#pragma once

#include "messages/Codec.h"
#include "mission/Mission.h"
#include "mission/PlanGeometry.h"
#include "sim/Kinematics.h"

#include <QJSEngine>
#include <QString>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace neptus::sim {

// A simulated vehicle's plan engine, answering as a DUNE vehicle does
// (src/Plan/Engine/Task.cpp and src/Supervisors/Vehicle/Task.cpp of LSTS
// DUNE; docs/plans.md lists what the console relies on and the test of each):
//  - a plan database (PlanDB SET, DEL, GET, GET_INFO, CLEAR, GET_STATE,
//    GET_DSTATE) keeping DUNE's MD5s per plan and for the whole database;
//  - plan control (PlanControl START with a stored plan id, with a
//    PlanSpecification or with one maneuver; STOP; LOAD; GET), and Abort;
//  - execution, maneuver by maneuver, moving the vehicle within its
//    Limits: every maneuver type the shipped vehicle definitions list;
//  - PlanControlState (INITIALIZING with the previous plan's id, EXECUTING,
//    READY, BLOCKED for a second after an Abort; the plan id kept after the
//    end, last_outcome SUCCESS or FAILURE), ManeuverControlState, VehicleState.
// Replies as DUNE's: a START is answered "plan loaded" then "<maneuver>:
// executing maneuver", and the plan's end is a third reply, "plan completed"
// or a FAILURE with the reason ("got abort request from system neptus-qt -
// 0x4001 @ 0xFF", "Goto maneuver error: ..."), each reusing the last
// request's sender, id and op; a STOP gets SUCCESS "OK" and the START
// nothing more; a START over a running plan fails that plan silently.
// After a maneuver it takes the first transition whose condition holds
// ("ManeuverIsDone" always does; it waits where it is while none holds), or,
// like DUNE, the first transition whatever its condition
// (Transitions::FirstOnly). It evaluates conditions itself, in JavaScript
// as the console's are written, over what it knows: its own state as
// sys["<its name>"].EstimatedState (x, y, z, depth, alt, height, psi, u),
// $elapsed (simulated seconds since the plan started) and $waited (since it
// began waiting at this transition), each run stopped after 50 ms. A
// condition on anything else (another vehicle) cannot be evaluated here and
// fails the plan, saying why; the console's supervisor is for those. An
// evaluator set with setEvaluator() replaces this.
class PlanEngine
{
public:
    enum class Transitions { Conditions, FirstOnly };
    // True or false for a transition's condition; empty when it cannot be evaluated (the plan fails).
    using Evaluator = std::function<std::optional<bool>(const QString &condition)>;

    // `latDeg`, `lonDeg`: the vehicle's reference point (its EstimatedState's lat/lon).
    PlanEngine(std::shared_ptr<const msg::Schema> schema, quint16 self, QString name, Limits limits, double latDeg,
               double lonDeg);

    void setTransitions(Transitions mode) { m_transitions = mode; }
    Transitions transitions() const { return m_transitions; }
    void setEvaluator(Evaluator evaluator) { m_evaluator = std::move(evaluator); }

    // A message addressed to this vehicle: the replies (none for others).
    std::vector<msg::Message> handle(const msg::Message &message, double wallTime);
    // Moves the vehicle `dt` seconds along the running plan (holding still
    // without one). Returns what to send now (a plan's end).
    std::vector<msg::Message> advance(Motion &motion, double dt, double wallTime);

    bool executing() const { return m_run.has_value(); }
    QString currentManeuver() const { return m_run ? m_run->maneuver : QString(); }
    QByteArray databaseMd5() const;

    msg::Message controlState(double wallTime) const;  // PlanControlState
    msg::Message maneuverState(double wallTime) const; // ManeuverControlState
    msg::Message vehicleState(double wallTime) const;  // VehicleState

private:
    struct Stored
    {
        msg::Message specification;
        QByteArray md5;
        int size = 0;
        double changeTime = 0;
        quint16 changeSource = 0;
    };
    enum class Stage { Going, Looping, Holding, Waiting };
    struct Run
    {
        mission::Plan plan;
        msg::Message specification;
        QString maneuver;
        mission::ManeuverGeometry geometry;
        std::vector<Eigen::Vector3d> points; // north, east, down (NaN: keep the depth it has)
        size_t next = 0;
        Stage stage = Stage::Going;
        double holdLeft = 0;
        bool endless = false;
        bool yoyoDown = true;
        int done = 0;     // maneuvers finished
        int total = 1;    // in the plan's execution order
        double maneuverStart = 0;
        double laterSeconds = 0; // what the maneuvers after this one take; -1: one never ends
    };

    msg::Message make(const char *abbrev, double wallTime) const;
    msg::Message reply(const msg::Message &request, const char *type, const QString &info, double wallTime) const;
    std::vector<msg::Message> planDb(const msg::Message &request, double wallTime);
    std::vector<msg::Message> planControl(const msg::Message &request, double wallTime);
    std::optional<QString> start(msg::Message specification, const Motion *motion);
    void startManeuver(const QString &id, const Motion &motion);
    // The maneuver after the current one, "" at the plan's end, nullopt to wait; an error fails the plan.
    std::expected<std::optional<QString>, QString> nextManeuver();
    // A PlanControl reply as DUNE words everything: to the last request's
    // sender, with its id and op (m_reply).
    msg::Message replyLast(const char *type, const QString &info, double wallTime) const;
    // The plan ends: the reply that says how, and the state.
    std::vector<msg::Message> end(bool success, const QString &info, double wallTime);
    msg::Message planDbState(bool detailed, double wallTime) const;
    double maneuverEta(const Motion &motion) const;
    mission::SpeedModel speeds() const; // its limits' (100 % is its top speed)
    std::optional<double> downOf(double z, const QString &units) const;
    // Its own evaluation of a condition; empty (with m_conditionError set) when it cannot.
    std::optional<bool> evaluate(const QString &condition);

    std::shared_ptr<const msg::Schema> m_schema;
    msg::Codec m_codec;
    quint16 m_self;
    QString m_name;
    Limits m_limits;
    double m_latDeg, m_lonDeg;
    Transitions m_transitions = Transitions::Conditions;
    Evaluator m_evaluator;
    std::map<QString, Stored> m_database;
    double m_databaseChange = 0;
    quint16 m_databaseChangeSource = 0;
    std::optional<msg::Message> m_loaded; // LOAD: ready to start
    std::optional<Run> m_run;
    struct ReplyTo
    {
        quint16 to = 0xFFFF;
        quint8 toEntity = 0xFF;
        qint64 requestId = 0;
        qint64 op = 0;
        QString planId;
    };
    ReplyTo m_reply; // the last plan control request: what every later word to it reuses
    bool m_initializing = false;
    double m_blockedUntil = -1; // simulated time: BLOCKED until then (after an abort)
    std::map<quint16, QString> m_names; // systems' names from their Announce
    Motion m_lastMotion;
    QString m_lastPlan;
    int m_lastOutcome = 0; // PlanControlState.last_outcome: NONE, SUCCESS, FAILURE
    QString m_lastInfo;
    double m_now = 0;
    double m_simTime = 0;      // simulated seconds, from advance()
    double m_planStart = 0, m_waitStart = 0;
    QString m_conditionError;
    std::unique_ptr<QJSEngine> m_js;
};

} // namespace neptus::sim
