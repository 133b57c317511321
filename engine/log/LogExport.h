#pragma once

#include "log/Replay.h"
#include "runs/PlanRuns.h"

#include <QHash>
#include <QString>
#include <QStringList>

#include <expected>
#include <functional>
#include <map>

namespace neptus::log {

// Progress of a long export, 0 to 1; return false to stop it.
using Progress = std::function<bool(double fraction)>;

// What a log holds: for `neptus-log info` and the review's summary.
struct LogSummary
{
    struct System
    {
        quint16 id = 0;
        QString name;      // from its Announce, else "0x00d1"
        qint64 packets = 0;
    };
    double begin = 0, end = 0;
    qint64 packets = 0;
    QList<System> systems;                 // by id
    QList<std::pair<QString, qint64>> types; // message abbrev and count, most frequent first
    QStringList damage;                    // each log's damage, if any
};
LogSummary summarize(const LogSet &logs);

// What the plans in the log did, in time order, as the console tells them
// live (plans::PlanRuns: each run's start, maneuvers and end from the
// vehicles' PlanControlState, the words from their replies); a run still
// open when the log ends is told there as StillRunning. Times (`ms`) are log
// times in milliseconds.
std::vector<plans::PlanRuns::Event> planEvents(const LogSet &logs);

// What a review's timeline marks: the vehicles' log-book entries (errors
// and critical ones as alarms), entities going to fault, error or failure,
// and plans starting and ending (planEvents), in time order.
struct LogMarker
{
    enum Kind { Note, Alarm, PlanStart, PlanEnd };
    double time = 0;
    Kind kind = Note;
    QString text; // "lauv-simulator-1: plan goto-and-wait started"
};
// `plans`: planEvents(logs), worked out once by the caller for the markers and the runs.
std::vector<LogMarker> markersOf(const LogSet &logs, const std::vector<plans::PlanRuns::Event> &plans);

// A numeric field's values against time (the messages' own timestamps),
// from a tree path: "system/Message/field", the system by the name it
// announces or its id ("0x001f"), "Message@Entity" for one entity (by label
// or number; all entities otherwise). An error says which part is unknown.
std::expected<std::vector<std::pair<double, double>>, QString> fieldSeries(const LogSet &logs, const QString &path);

// Each system's track: its EstimatedState positions (degrees, metres).
struct TrackPoint
{
    double time, lat, lon, depth, altitude;
};
std::map<quint16, std::vector<TrackPoint>> tracks(const LogSet &logs);

// The plans the vehicles ran (planEvents: executing from … to), with what
// their tracks say of them.
struct PlanRun
{
    quint16 system = 0;
    QString systemName, plan;
    QString outcome;                   // PlanRuns::outcomeName: completed, failed, …, "still running" when the log ends
    QString reason;                    // the vehicle's words, or the plan that replaced it
    double begin = 0, end = 0;         // log times (LogSet::time)
    double distance = 0;               // metres along the track
    double maxDepth = 0;
};
std::vector<PlanRun> planRuns(const LogSet &logs, const std::vector<plans::PlanRuns::Event> &plans,
                              const std::map<quint16, std::vector<TrackPoint>> &tracks);

// Every plan specification the log holds, whoever sent it (a console's
// PlanDB SET or PlanControl START, a vehicle's PlanDB answer, a bare
// PlanSpecification), with the vehicle it is for, in log order.
std::vector<std::pair<quint16, msg::Message>> planSpecifications(const LogSet &logs);

// One CSV file per message type in `folder` (<Abbrev>.csv): time (s since
// 1970, UTC), system, entity, then a column per field (numbers as numbers,
// enumerations by value, text quoted, nested messages as JSON). Returns the
// files written.
std::expected<QStringList, QString> exportCsv(const LogSet &logs, const QString &folder, const Progress &progress = {});

// Each system's track (its EstimatedState positions) as one file:
enum class TrackFormat { Kml, GeoJson, Gpx };
std::expected<void, QString> exportTracks(const LogSet &logs, TrackFormat format, const QString &file,
                                          const Progress &progress = {});
std::optional<TrackFormat> trackFormat(const QString &name); // "kml", "geojson", "gpx"

// A new log in `folder` (which must not exist or be empty) of the packets
// between `from` and `to` (log times, inclusive), with the definitions of
// the first log: a slice, or with the whole span, the logs merged.
std::expected<qint64, QString> writeLog(const LogSet &logs, double from, double to, const QString &folder,
                                        const Progress &progress = {});

} // namespace neptus::log
