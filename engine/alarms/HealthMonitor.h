#pragma once

#include "alarms/AlarmGraph.h"
#include "messages/Message.h"
#include "tree/VariableTree.h"

#include <QHash>
#include <QMutex>

namespace neptus::alarms {

// Turns what systems say and fail to say into alarms:
//  - each EntityState sets the level of node "systems/<system>/<entity>"
//    (BOOT → Info, NORMAL → Normal, FAULT → Warning, ERROR → Error,
//    FAILURE → Failure) with the entity's description as the message;
//  - a system silent for longer than its usual interval plus the comms
//    timeout (default 2 s) gets Warning "communications lost" on its node,
//    Error after three times that, with the silence so far in the text
//    (updated as it grows); both clear when traffic returns. Silence is
//    counted from when a system can be expected to stream: a stock DUNE
//    announces itself (every 10 s) seconds before it streams to a console
//    it has just heard of, so until something other than an Announce comes
//    (at first, and again after its stream stopped, as when it restarts)
//    only its Announces are awaited, at their own period; if they are all
//    it sends for `waitForStreamMs`, a Warning says so;
//  - a system that was never named (no Announce, no configuration) and was
//    heard for under 5 s gets no alarm of its own when it falls silent: one
//    Warning on "links/short-lived systems" counts them all (a burst of
//    forged ids must not bury the real vehicles' alarms), and they are
//    forgotten after 10 min of silence (or forgetAfter, if shorter);
//  - any other system is forgotten after forgetAfter of silence, if set
//    (0, the default, keeps them: an AUV may dive for hours); its alarms
//    and its entities' go to Unknown;
//  - entity alarms are renamed in place when the entity's label is learned.
// Names come from the variable tree (Announce, EntityList, configuration).
class HealthMonitor
{
public:
    HealthMonitor(AlarmGraph &graph, const tree::VariableTree &tree, const Clock *clock = &Clock::system());

    // Every received message (any thread).
    void observe(const msg::Message &message);
    // Checks for silence; call a few times a second (the console does).
    // Returns the systems it forgot, for the console to forget everywhere.
    QList<quint16> check();
    void setCommsTimeout(double seconds);
    void setForgetAfter(double seconds); // 0: only short-lived systems are forgotten
    // Forgets a system now (its alarms to Unknown); heard again, it starts anew.
    void forget(quint16 id);

    static Level levelOfEntityState(qint64 state);
    // A vehicle heard announcing for this long without streaming gets a Warning.
    static constexpr qint64 waitForStreamMs = 20000;

private:
    struct Entity
    {
        AlarmGraph::NodeId node = AlarmGraph::noNode;
        QString label;
    };
    struct System
    {
        AlarmGraph::NodeId node = AlarmGraph::noNode;
        QString name;
        qint64 firstMs = 0;
        qint64 lastMs = 0;
        double intervalMs = -1;   // running average between messages of its stream; -1 until two were heard
        bool streaming = false;   // it sends more than its Announce
        qint64 streamMs = 0;      // its last message other than an Announce
        qint64 waitingSinceMs = 0; // when it was last heard announcing without streaming
        qint64 announceMs = 0;
        double announceIntervalMs = -1;
        bool console = false;     // it announces itself as a console (CCU): it streams to nobody
        Level lost = Normal;
        bool unstreamed = false;  // `lost` is "heard only its Announce", not a silence
        QHash<quint8, Entity> entities; // those that reported an EntityState
    };

    System &systemLocked(quint16 id);
    bool establishedLocked(quint16 id, const System &system) const;
    // How long a silence it may keep before its alarm: its stream's cadence, or its Announces'.
    double limitLocked(const System &system) const;
    void updateShortLivedLocked(const QList<quint16> &silent);
    Entity &entityLocked(System &system, quint16 id, quint8 entity);
    // "12 s", "3 min 05 s", "2 h 10 min": how long a system has been silent.
    static QString silenceText(double ms);

    AlarmGraph &m_graph;
    const tree::VariableTree &m_tree;
    const Clock *m_clock;
    QMutex m_mutex;
    double m_timeoutMs = 2000;
    qint64 m_forgetAfterMs = 0;
    QHash<quint16, System> m_systems;
    AlarmGraph::NodeId m_shortLived = AlarmGraph::noNode;
    QString m_shortLivedText;
};

} // namespace neptus::alarms
