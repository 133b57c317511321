#pragma once

#include "messages/Message.h"

#include <QHash>
#include <QString>

#include <optional>
#include <vector>

namespace neptus::plans {

// Follows the plans vehicles run from what they report, so that each run's
// start and end is told exactly once, with the vehicle's own words.
//
// A plan's progress and end come from the vehicle's PlanControlState (state
// EXECUTING, then READY or BLOCKED with last_outcome SUCCESS or FAILURE),
// never from counting PlanControl replies: DUNE answers a START three times
// ("plan loaded", "<maneuver>: executing maneuver", then "plan completed" or
// a FAILURE with the reason), each reply reusing whatever request id and op
// the vehicle last answered (src/Plan/Engine/Task.cpp, m_reply), and a STOP
// gets its own SUCCESS "OK" while the START gets nothing more. The replies
// only lend the words: the last FAILURE heard during a run is why it failed
// (DUNE sends it just before the state changes; over DDS the two travel on
// different topics, so an end without its reason waits `reasonWaitMs` for
// it), and a STOP answered with SUCCESS makes a FAILURE outcome "stopped".
//
// A run starts when the vehicle first reports EXECUTING a plan (a console
// that joins, or restarts, in the middle of one learns of it from the first
// state it hears: `joined`); INITIALIZING is not a start (DUNE reports it
// with the previous plan's id). EXECUTING another plan ends the run as
// replaced. Not thread-safe: fed from one thread.
class PlanRuns
{
public:
    enum class Outcome { Completed, Failed, Stopped, Replaced, Unreported, StillRunning /* when the stream ended: finish() */ };
    struct Event
    {
        enum class Kind { Started, Maneuver, Ended };
        Kind kind = Kind::Started;
        quint16 system = 0;
        QString plan;
        QString maneuver;
        bool joined = false;           // Started: it was running before this console heard the vehicle
        Outcome outcome = Outcome::Unreported; // Ended
        QString reason;                // Ended: the vehicle's words, or what replaced it
        qint64 ms = 0;                 // when the vehicle's state said it (an end told later keeps its moment)
    };
    struct Run
    {
        QString plan;
        QString maneuver;
        qint64 sinceMs = 0;
        bool joined = false;
    };

    // How long an end reported FAILURE waits for the vehicle's reason.
    static constexpr qint64 reasonWaitMs = 1500;

    // A PlanControlState, or a PlanControl from a vehicle (requests are ignored).
    std::vector<Event> observe(const msg::Message &message, qint64 nowMs);
    // The vehicle accepted a Stop by other means than a PlanControl reply (a
    // MAVLink vehicle's stop mode): its run's end is "stopped", as after a STOP's SUCCESS.
    std::vector<Event> stopAnswered(quint16 system);
    // Ends whose reason did not come in time, told without it.
    std::vector<Event> poll(qint64 nowMs);
    // The stream ends (a log's last packet): every end still waiting is told,
    // and every run still open is told as StillRunning here, with the last
    // words the vehicle said during it (DUNE closes its log as a plan ends,
    // after its last reply "plan completed" and before the state says so).
    std::vector<Event> finish(qint64 nowMs);
    bool waiting() const;
    // The run a vehicle is in, if any.
    std::optional<Run> running(quint16 system) const;
    void forget(quint16 system);
    // The run a vehicle is in is known by another name from now on (a MAVLink
    // vehicle's mission, recognised as the plan it came from): no new run.
    void relabel(quint16 system, const QString &plan);

    // "completed", "failed", "stopped", "replaced", "ended", "still running".
    static QString outcomeName(Outcome outcome);

private:
    struct Vehicle
    {
        bool heard = false; // a state was heard before
        std::optional<Run> run;
        QString said;       // the last words of any reply during this run
        QString failure;    // the last FAILURE reply's words during this run, and when
        qint64 failureMs = 0;
        bool stopAnswered = false;
        std::optional<Event> pending; // an end waiting for its reason
        qint64 pendingUntilMs = 0;
    };

    void state(Vehicle &v, const msg::Message &m, qint64 nowMs, std::vector<Event> &out);
    void reply(Vehicle &v, const msg::Message &m, qint64 nowMs, std::vector<Event> &out);
    static void stopped(Vehicle &v, std::vector<Event> &out);
    void end(Vehicle &v, quint16 system, Outcome outcome, QString reason, qint64 nowMs, std::vector<Event> &out);

    QHash<quint16, Vehicle> m_vehicles;
};

} // namespace neptus::plans
