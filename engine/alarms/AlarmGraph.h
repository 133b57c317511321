#pragma once

#include "alarms/AlarmLevel.h"
#include "core/Clock.h"

#include <QMutex>
#include <QString>
#include <QStringList>

#include <array>
#include <functional>
#include <vector>

namespace neptus::alarms {

// The console's alarms as a tree: the console at the root; components,
// scripts and systems below it; a system's entities below the system. Each
// node has its own level (with a message) and shows the highest of its own
// and its children's, recomputed incrementally up the path when one changes.
// Thread-safe: scripts, the health monitor and the GUI all raise and read.
class AlarmGraph
{
public:
    using NodeId = int;
    static constexpr NodeId noNode = -1;

    struct Alarm
    {
        NodeId node = noNode;
        QString origin;   // path, e.g. "systems/lauv/Navigation"
        Level level = Unknown;
        QString message;
        qint64 sinceMs = 0; // when it reached this level
        bool acknowledged = false;
    };

    explicit AlarmGraph(const Clock *clock = &Clock::system());

    NodeId root() const { return 0; }
    // The node at `path` ("systems/lauv/Navigation"), made with its parents if needed.
    NodeId ensure(const QString &path);
    NodeId find(const QString &path) const;
    QString path(NodeId node) const;
    // Renames a node in place (a system learns its name).
    void rename(NodeId node, const QString &name);

    // Sets a node's own level and message. Rising to Error or worse from
    // below announces once (onAnnounce); staying there does not repeat it.
    void raise(NodeId node, Level level, const QString &message = {});
    void clear(NodeId node) { raise(node, Normal); }
    // An event worth a line in the alarm window although nothing is wrong
    // ("plan survey completed"): Info, listed among the alarms until
    // acknowledged or until the node is raised again.
    void notify(NodeId node, const QString &message);
    // Unknown, without a message, for a node and everything under it (a
    // system forgotten): no alarm of it stays behind. The nodes stay.
    void forget(NodeId node);

    Level level(NodeId node) const;     // max(own, children)
    Level ownLevel(NodeId node) const;
    QString message(NodeId node) const;
    Level rootLevel() const { return level(root()); }

    // Alarms (own level Warning or above) and unacknowledged notices, in the order they were raised.
    std::vector<Alarm> activeAlarms() const;
    void acknowledge(NodeId node);
    void acknowledgeAll();

    // A counter that grows with every change; views compare it to know when to look again.
    quint64 version() const;

    // Called, outside the graph's lock, when an alarm rises to Error or Failure.
    void setAnnouncer(std::function<void(const Alarm &)> announcer);

private:
    struct Node
    {
        QString name;
        NodeId parent = noNode;
        std::vector<NodeId> children;
        Level own = Unknown;
        Level effective = Unknown;
        std::array<int, levelCount> childLevels{}; // children counted by effective level
        QString message;
        qint64 sinceMs = 0;
        bool acknowledged = false;
        bool notice = false; // own level Info set by notify()
        quint64 raisedOrder = 0;
    };
    static bool listed(const Node &n) { return isAlarm(n.own) || (n.notice && !n.acknowledged); }

    NodeId childNamed(NodeId parent, const QString &name) const;
    QString pathLocked(NodeId node) const;
    void propagateLocked(NodeId node);

    mutable QMutex m_mutex;
    const Clock *m_clock;
    std::vector<Node> m_nodes;
    quint64 m_version = 0;
    quint64 m_order = 0;
    std::function<void(const Alarm &)> m_announcer;
};

} // namespace neptus::alarms
