#pragma once

#include "log/LogFile.h"

#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QTimer>

#include <memory>
#include <vector>

namespace neptus::log {

// One or more logs of a mission as one sequence of packets in log time
// (merged: equal times keep the logs' order), with checkpoints every few
// seconds that hold, for each kind of message (sender, its entity,
// destination, message id), the last packet before them. The state at time
// t is then a checkpoint's packets plus the few after it: no full replay.
class LogSet
{
public:
    explicit LogSet(std::vector<std::shared_ptr<const LogFile>> logs, double checkpointSeconds = 10.0);

    const std::vector<std::shared_ptr<const LogFile>> &logs() const { return m_logs; }
    qsizetype count() const { return qsizetype(m_entries.size()); }
    double begin() const { return m_times.empty() ? 0 : m_times.front(); }
    double end() const { return m_times.empty() ? 0 : m_times.back(); }
    double time(qsizetype k) const { return m_times[size_t(k)]; }
    const LogFile &logOf(qsizetype k) const { return *m_logs[m_entries[size_t(k)].log]; }
    qsizetype indexInLog(qsizetype k) const { return m_entries[size_t(k)].index; }
    QByteArrayView packet(qsizetype k) const { return logOf(k).packet(indexInLog(k)); }
    std::expected<msg::Message, msg::CodecError> decode(qsizetype k) const { return logOf(k).decode(indexInLog(k)); }
    // Sent by the console that recorded its log (a command), not received.
    bool sentByRecorder(qsizetype k) const;
    // The first packet after `t` (count() if none): packets before it make the state at t.
    qsizetype upperBound(double t) const;
    // The packets whose values make the state at `t`, in log order: the
    // last of each kind of message at or before t.
    std::vector<qsizetype> stateAt(double t) const;
    // The names systems announce in the logs (their first Announce's sys_name), by id.
    const QHash<quint16, QString> &systemNames() const { return m_names; }
    // That name, else the id as the tree shows it ("0x001f").
    QString systemName(quint16 id) const;

private:
    static quint64 keyOf(const LogFile &log, qsizetype index);

    struct Entry
    {
        quint32 log;
        quint32 index;
    };
    struct Checkpoint
    {
        qsizetype position; // the first packet after the checkpoint's time
        std::vector<std::pair<quint64, qsizetype>> last; // kind → its last packet before position
    };
    std::vector<std::shared_ptr<const LogFile>> m_logs;
    std::vector<Entry> m_entries;
    std::vector<double> m_times;
    std::vector<Checkpoint> m_checkpoints;
    QHash<quint16, QString> m_names;
};

// Where a replay's packets go: a console's tree, alarms and health, fed as
// if by a link, with the clock the replay moves.
class ReplayTarget
{
public:
    virtual ~ReplayTarget() = default;
    // Forget everything (before going back in time).
    virtual void clear() = 0;
    // The replay clock, seconds since 1970.
    virtual void setTime(double t) = 0;
    // A message of the log; `sent`: the recording console sent it.
    virtual void deliver(const msg::Message &message, bool sent) = 0;
};

// Plays a LogSet into a target: play/pause, speed (0.1× to 100×, or as fast
// as possible), step, seek. Driven by a timer on its thread; advanceTo() and
// seek() also run it by hand (tests, tools).
class Player : public QObject
{
    Q_OBJECT

public:
    static constexpr double asFastAsPossible = 0; // a speed

    Player(std::shared_ptr<const LogSet> logs, ReplayTarget *target, QObject *parent = nullptr);

    const LogSet &logs() const { return *m_logs; }
    double position() const { return m_position; }
    bool playing() const { return m_timer.isActive(); }
    double speed() const { return m_speed; }
    // Packets that did not decode so far (each also said once by decodeFailed).
    qint64 decodeErrors() const { return m_decodeErrors; }

    void play();
    void pause();
    void setSpeed(double speed); // clamped to 0.1 … 100, or asFastAsPossible
    // The state at `t`: forward within a few seconds by playing on, else from a checkpoint.
    void seek(double t);
    // Moves on by `seconds` of log time, paused.
    void step(double seconds = 1.0);
    // Delivers every packet up to `t` in order (t at or after position()).
    void advanceTo(double t);

signals:
    void positionChanged(double position);
    void playingChanged(bool playing);
    void speedChanged(double speed);
    void decodeFailed(const QString &why);
    // The replay went to `t` from a checkpoint (back in time, or far ahead):
    // what accumulates over time (trails) is to be made again.
    void jumped(double t);
    void finished();

private:
    void tick();
    void deliver(qsizetype k);

    std::shared_ptr<const LogSet> m_logs;
    ReplayTarget *m_target;
    QTimer m_timer;
    QElapsedTimer m_wall;
    double m_wallStartPosition = 0;
    double m_speed = 1.0;
    double m_position = 0;
    qsizetype m_next = 0; // the next packet to deliver
    qint64 m_decodeErrors = 0;
};

} // namespace neptus::log
