#pragma once

#include "alarms/AlarmGraph.h"
#include "core/Clock.h"
#include "database/Database.h"
#include "messages/Message.h"
#include "runs/PlanRuns.h"

#include <QHash>
#include <QMutex>
#include <QObject>
#include <QTimer>

namespace neptus::log { class Recorder; }

namespace neptus::session {

class Console;

// What a console (or the headless recorder node) tells the operation's
// database: the systems it hears (from their Announce, last heard kept
// current), their positions a few times a second, its alarms as they are
// raised, acknowledged and cleared, plans (requested, started, each maneuver,
// their outcome, the vehicles' replies), the vehicles' log-book entries and
// the logs it records. observe() is called by the Console for every message
// received or sent (any thread); the alarms are looked at on this object's
// thread. A problem of the database raises the "database" alarm. It also
// keeps the live picture the web page shows (live()), database or not.
class OperationsFeed : public QObject
{
    Q_OBJECT
public:
    // `writer` may be null: the live picture only.
    OperationsFeed(Console &console, db::Writer *writer, const Clock *clock = &Clock::system(), QObject *parent = nullptr);

    // What is known now of a system: its latest position (every EstimatedState),
    // its last 10 minutes of track (a point a second), its plan.
    struct LiveSystem
    {
        quint16 id = 0;
        QString name, kind;
        qint64 lastMs = 0;
        bool hasPosition = false;
        db::TrackPoint position;
        std::vector<db::TrackPoint> recent;
        QString planState, plan, maneuver;
        double progress = 0;
    };
    // Every system known, by name; `withTracks` copies their 10 minutes of track too (a page that opens).
    std::vector<LiveSystem> live(bool withTracks = false) const;
    Console &console() const { return m_console; }
    ~OperationsFeed() override;

    // Positions kept per system: at most one in this many milliseconds (default 500).
    void setPositionInterval(int ms) { m_positionIntervalMs = ms; }
    // The log being recorded goes into the catalogue (and its span is kept up to date).
    void setRecorder(const log::Recorder *recorder);

    void observe(const msg::Message &message, bool sent);
    // What the plan desk learnt of a run beyond the vehicle's reports (PlanDesk's
    // runRelabelled and stopAccepted), so the database says what the plan log says.
    void relabelRun(quint16 system, const QString &plan);
    void stopAccepted(quint16 system);
    // Raised, acknowledged and cleared alarms since the last look (a timer calls it; tests too).
    void checkAlarms();

private:
    void noteSystem(quint16 id, qint64 now);
    // The log being recorded, in the catalogue: its folder, span and counts, every 5 s.
    void noteLog();
    QString nameOf(quint16 id) const;
    void planControl(const msg::Message &m, bool sent, qint64 now);
    // Plan starts, maneuvers and ends as the plan desk tells them (the one tracker, plans::PlanRuns).
    void planEvents(const std::vector<plans::PlanRuns::Event> &events, double progress = 0);

    void put(db::Row row);

    Console &m_console;
    db::Writer *m_writer;
    const Clock *m_clock;
    int m_positionIntervalMs = 500;
    QTimer m_timer;

    mutable QMutex m_mutex;
    struct SystemState
    {
        QString name, kind;
        qint64 firstMs = 0, writtenMs = 0, lastMs = 0, positionMs = 0;
        LiveSystem live;
        std::vector<db::TrackPoint> recent; // the last 10 minutes, a point a second
    };
    QHash<quint16, SystemState> m_systems;
    plans::PlanRuns m_runs;

    struct AlarmState
    {
        alarms::Level level;
        QString message;
        bool acknowledged;
    };
    QHash<QString, AlarmState> m_alarms;
    quint64 m_alarmVersion = ~0ull;

    const log::Recorder *m_recorder = nullptr;
    QString m_logFolder;
    qint64 m_logBeganMs = 0, m_logWrittenMs = 0;
    quint64 m_logPacketsBefore = 0, m_logBytesBefore = 0;
};

} // namespace neptus::session
