#include "alarms/AlarmGraph.h"

#include <QMutexLocker>

#include <algorithm>

namespace neptus::alarms {

AlarmGraph::AlarmGraph(const Clock *clock)
    : m_clock(clock)
{
    Node console;
    console.name = QStringLiteral("console");
    m_nodes.push_back(console);
}

AlarmGraph::NodeId AlarmGraph::childNamed(NodeId parent, const QString &name) const
{
    for (NodeId child : m_nodes[static_cast<size_t>(parent)].children) {
        if (m_nodes[static_cast<size_t>(child)].name == name)
            return child;
    }
    return noNode;
}

AlarmGraph::NodeId AlarmGraph::ensure(const QString &path)
{
    QMutexLocker lock(&m_mutex);
    NodeId node = root();
    for (const QString &part : path.split(u'/', Qt::SkipEmptyParts)) {
        NodeId next = childNamed(node, part);
        if (next == noNode) {
            next = static_cast<NodeId>(m_nodes.size());
            Node child;
            child.name = part;
            child.parent = node;
            m_nodes.push_back(child);
            m_nodes[static_cast<size_t>(node)].children.push_back(next);
            m_nodes[static_cast<size_t>(node)].childLevels[Unknown]++;
            ++m_version;
        }
        node = next;
    }
    return node;
}

AlarmGraph::NodeId AlarmGraph::find(const QString &path) const
{
    QMutexLocker lock(&m_mutex);
    NodeId node = root();
    for (const QString &part : path.split(u'/', Qt::SkipEmptyParts)) {
        node = childNamed(node, part);
        if (node == noNode)
            return noNode;
    }
    return node;
}

QString AlarmGraph::pathLocked(NodeId node) const
{
    QStringList parts;
    for (; node > 0; node = m_nodes[static_cast<size_t>(node)].parent)
        parts.prepend(m_nodes[static_cast<size_t>(node)].name);
    return parts.join(u'/');
}

QString AlarmGraph::path(NodeId node) const
{
    QMutexLocker lock(&m_mutex);
    return pathLocked(node);
}

void AlarmGraph::rename(NodeId node, const QString &name)
{
    QMutexLocker lock(&m_mutex);
    m_nodes[static_cast<size_t>(node)].name = name;
    ++m_version;
}

void AlarmGraph::propagateLocked(NodeId node)
{
    // Recompute effective levels up the path while they change.
    while (node != noNode) {
        Node &n = m_nodes[static_cast<size_t>(node)];
        Level highest = n.own;
        for (int l = levelCount - 1; l > highest; --l) {
            if (n.childLevels[static_cast<size_t>(l)] > 0) {
                highest = static_cast<Level>(l);
                break;
            }
        }
        if (highest == n.effective)
            return;
        if (n.parent != noNode) {
            Node &p = m_nodes[static_cast<size_t>(n.parent)];
            p.childLevels[static_cast<size_t>(n.effective)]--;
            p.childLevels[static_cast<size_t>(highest)]++;
        }
        n.effective = highest;
        node = n.parent;
    }
}

void AlarmGraph::raise(NodeId node, Level level, const QString &message)
{
    QMutexLocker lock(&m_mutex);
    Node &n = m_nodes[static_cast<size_t>(node)];
    if (n.own == level && n.message == message && !n.notice)
        return;
    n.notice = false;
    const Level before = n.own;
    if (before != level) {
        n.sinceMs = m_clock->now().toMSecsSinceEpoch();
        if (level > before)
            n.acknowledged = false; // worse news needs a new acknowledgement
        if (!isAlarm(before) && isAlarm(level))
            n.raisedOrder = ++m_order;
    }
    n.own = level;
    n.message = message;
    propagateLocked(node);
    ++m_version;
    if (level >= Error && before < Error && m_announcer) {
        const Alarm alarm{node, pathLocked(node), level, message, n.sinceMs, false};
        auto announcer = m_announcer;
        lock.unlock();
        announcer(alarm);
    }
}

void AlarmGraph::notify(NodeId node, const QString &message)
{
    QMutexLocker lock(&m_mutex);
    Node &n = m_nodes[static_cast<size_t>(node)];
    n.own = Info;
    n.message = message;
    n.notice = true;
    n.acknowledged = false;
    n.sinceMs = m_clock->now().toMSecsSinceEpoch();
    n.raisedOrder = ++m_order;
    propagateLocked(node);
    ++m_version;
}

void AlarmGraph::forget(NodeId node)
{
    QMutexLocker lock(&m_mutex);
    std::vector<NodeId> below{node};
    for (size_t i = 0; i < below.size(); ++i) {
        const auto &children = m_nodes[static_cast<size_t>(below[i])].children;
        below.insert(below.end(), children.begin(), children.end());
    }
    const qint64 now = m_clock->now().toMSecsSinceEpoch();
    for (auto it = below.rbegin(); it != below.rend(); ++it) { // children first
        Node &n = m_nodes[static_cast<size_t>(*it)];
        if (n.own == Unknown && n.message.isEmpty())
            continue;
        if (n.own != Unknown)
            n.sinceMs = now;
        n.own = Unknown;
        n.message.clear();
        n.notice = false;
        propagateLocked(*it);
    }
    ++m_version;
}

Level AlarmGraph::level(NodeId node) const
{
    QMutexLocker lock(&m_mutex);
    return m_nodes[static_cast<size_t>(node)].effective;
}

Level AlarmGraph::ownLevel(NodeId node) const
{
    QMutexLocker lock(&m_mutex);
    return m_nodes[static_cast<size_t>(node)].own;
}

QString AlarmGraph::message(NodeId node) const
{
    QMutexLocker lock(&m_mutex);
    return m_nodes[static_cast<size_t>(node)].message;
}

std::vector<AlarmGraph::Alarm> AlarmGraph::activeAlarms() const
{
    QMutexLocker lock(&m_mutex);
    std::vector<std::pair<quint64, Alarm>> alarms;
    for (size_t i = 0; i < m_nodes.size(); ++i) {
        const Node &n = m_nodes[i];
        if (listed(n))
            alarms.push_back({n.raisedOrder, Alarm{static_cast<NodeId>(i), pathLocked(static_cast<NodeId>(i)), n.own,
                                                   n.message, n.sinceMs, n.acknowledged}});
    }
    std::sort(alarms.begin(), alarms.end(), [](const auto &a, const auto &b) { return a.first < b.first; });
    std::vector<Alarm> result;
    for (auto &entry : alarms)
        result.push_back(std::move(entry.second));
    return result;
}

void AlarmGraph::acknowledge(NodeId node)
{
    QMutexLocker lock(&m_mutex);
    m_nodes[static_cast<size_t>(node)].acknowledged = true;
    ++m_version;
}

void AlarmGraph::acknowledgeAll()
{
    QMutexLocker lock(&m_mutex);
    for (Node &n : m_nodes) {
        if (listed(n))
            n.acknowledged = true;
    }
    ++m_version;
}

quint64 AlarmGraph::version() const
{
    QMutexLocker lock(&m_mutex);
    return m_version;
}

void AlarmGraph::setAnnouncer(std::function<void(const Alarm &)> announcer)
{
    QMutexLocker lock(&m_mutex);
    m_announcer = std::move(announcer);
}

} // namespace neptus::alarms
