#pragma once

#include "core/Clock.h"
#include "geo/Geodesy.h"
#include "mission/Mission.h"
#include "plans/PlanClient.h"
#include "scripting/ScriptHost.h"
#include "tree/VariableTree.h"

#include <QObject>

#include <functional>
#include <optional>

namespace neptus::plans {

// Carries out a plan whose transitions have conditions for a vehicle whose
// plan engine takes the first transition out of a maneuver whatever its
// condition (DUNE does): the console supervises. The plan is cut into
// stretches — maneuvers joined by plain transitions ("ManeuverIsDone") —
// and each stretch goes to the vehicle as a plan of its own ("survey.1",
// "survey.2", … started with PlanControl START and the specification),
// ending in a wait: keeping station at the surface where the stretch ends
// (a loiter at the same height for an aircraft). Once the vehicle waits, the
// supervisor evaluates the conditions of the transitions out of the
// stretch's last maneuver, in order, about once a second; the first that
// holds starts the next stretch. Each decision is logged with the values
// that made it.
//
// Conditions are JavaScript expressions over the variable tree, run as alarm
// scripts are (ScriptHost: its own process, read tracking, time limit):
//   sys["caravela-sim"].EstimatedState.depth < 2 && $elapsed > 60
//   distance("caravela-sim", "pier") < 50
// with $elapsed (seconds since the plan started), $waited (seconds waiting at
// this transition) and distance(system, mark) (metres from a system's
// position to a mark of the mission's maps). A condition that fails (a
// syntax error, a runtime error) is logged and leaves the vehicle waiting.
// If the link drops, the vehicle finishes the stretch it has and waits there.
class Supervisor : public QObject
{
    Q_OBJECT

public:
    using Log = std::function<void(const QString &line)>;

    Supervisor(PlanClient &client, const tree::VariableTree &tree, scripting::ScriptHost *scripts,
               const alarms::AlarmGraph &graph, const mission::Mission &mission, mission::Plan plan, std::shared_ptr<const msg::Schema> schema,
               Log log, const Clock *clock = &Clock::system(), QObject *parent = nullptr);
    ~Supervisor() override;

    // Whether a plan needs supervising: some transition has a condition
    // other than ManeuverIsDone.
    static bool needed(const mission::Plan &plan);
    // Why a vehicle that evaluates conditions itself cannot be given the
    // whole plan: a condition names something only the console sees (another
    // system, a mark's distance); empty when every condition reads only the
    // vehicle's own state, $elapsed and $waited.
    static QString beyondVehicle(const mission::Plan &plan, const QString &system);
    // The maneuvers of the stretch that begins at `first`.
    static QStringList stretch(const mission::Plan &plan, const QString &first);
    // A condition as the script it runs as: `prelude` (three lines: $elapsed,
    // $waited, marks and distance()) then the expression on line 4.
    static QString conditionScript(const QString &expression, const QString &prelude);
    // Where a condition does not compile, line and column within the
    // expression itself (1-based), for an editor checking as one types;
    // none when it compiles.
    static std::optional<scripting::CompileError> conditionProblem(const QString &expression);
    // conditionProblem's message ("" if it compiles).
    static QString conditionError(const QString &expression);
    // What does not compile among a plan's conditions, one line each ("a → b: …").
    static QStringList conditionErrors(const mission::Plan &plan);

    const mission::Plan &plan() const { return m_plan; }
    QString part() const { return m_part; }
    bool finished() const { return m_finished; }

    // Sends the first stretch.
    std::expected<void, QString> begin();
    // Looks at the vehicle's PlanControlState and decides (the desk calls it every second).
    void check();
    // The vehicle's plan `planId` ended (PlanRuns); the desk says how.
    void ended(const QString &planId);

    // A transition taken when its maneuver is done, with no condition to evaluate.
    static bool plain(const mission::Transition &t);

private:
    std::expected<void, QString> startStretch(const QString &first);
    QString scriptName(int exit) const;
    QString conditionSource(const QString &expression) const;
    void setConditions();
    void clearConditions();
    QString valuesIn(const QString &expression) const;
    std::map<QString, geo::Geodetic> marks() const; // the mission's marks by id
    QString text(const QString &field) const;

    PlanClient &m_client;
    const tree::VariableTree &m_tree;
    scripting::ScriptHost *m_scripts;
    const alarms::AlarmGraph &m_graph;
    const mission::Mission &m_mission;
    mission::Plan m_plan;
    std::shared_ptr<const msg::Schema> m_schema;
    Log m_log;
    const Clock *m_clock;
    QString m_system;
    QString m_part;          // the stretch the vehicle has: "survey.2"
    int m_parts = 0;
    QStringList m_stretch;
    QList<mission::Transition> m_exits; // out of the stretch's last maneuver, with conditions
    qint64 m_startMs = 0, m_waitSinceMs = 0;
    bool m_waiting = false;
    bool m_conditionsSet = false; // installed in the script host for this wait
    bool m_final = false;    // the stretch has no exits: its end is the plan's
    bool m_finished = false;
};

} // namespace neptus::plans
