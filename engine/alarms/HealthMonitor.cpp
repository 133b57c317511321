#include "HealthMonitor.h"

#include <QMutexLocker>

namespace neptus::alarms {

HealthMonitor::HealthMonitor(AlarmGraph &graph, const tree::VariableTree &tree, const Clock *clock)
    : m_graph(graph)
    , m_tree(tree)
    , m_clock(clock)
{
}

void HealthMonitor::setCommsTimeout(double seconds)
{
    QMutexLocker lock(&m_mutex);
    m_timeoutMs = seconds * 1000;
}

Level HealthMonitor::levelOfEntityState(qint64 state)
{
    switch (state) {
    case 0: return Info;    // BOOT
    case 1: return Normal;  // NORMAL
    case 2: return Warning; // FAULT
    case 3: return Error;   // ERROR
    case 4: return Failure; // FAILURE
    default: return Unknown;
    }
}

HealthMonitor::System &HealthMonitor::systemLocked(quint16 id)
{
    System &system = m_systems[id];
    const QString name = m_tree.systemName(id);
    if (system.node == AlarmGraph::noNode) {
        system.name = name;
        system.node = m_graph.ensure(QStringLiteral("systems/") + name);
    } else if (system.name != name) {
        system.name = name;
        m_graph.rename(system.node, name);
    }
    return system;
}

void HealthMonitor::observe(const msg::Message &message)
{
    const qint64 now = m_clock->now().toMSecsSinceEpoch();
    QMutexLocker lock(&m_mutex);
    System &system = systemLocked(message.header.src);
    if (system.lastMs > 0) {
        const double gap = static_cast<double>(now - system.lastMs);
        system.intervalMs = system.intervalMs < 0 ? gap : 0.9 * system.intervalMs + 0.1 * gap;
    }
    system.lastMs = now;
    if (system.lost != Normal) {
        system.lost = Normal;
        m_graph.clear(system.node);
    }
    if (message.def() && message.def()->abbrev == u"EntityState") {
        const QString entity = m_tree.entityLabel(message.header.src, message.header.srcEnt);
        const AlarmGraph::NodeId node = m_graph.ensure(QStringLiteral("systems/%1/%2").arg(system.name, entity));
        m_graph.raise(node, levelOfEntityState(message.integer(u"state")), message.text(u"description"));
    }
}

void HealthMonitor::check()
{
    const qint64 now = m_clock->now().toMSecsSinceEpoch();
    QMutexLocker lock(&m_mutex);
    for (System &system : m_systems) {
        if (system.lastMs == 0)
            continue;
        const double silent = static_cast<double>(now - system.lastMs);
        // A system heard once has no interval yet: assume IMC's 1 s heartbeat.
        const double limit = (system.intervalMs < 0 ? 1000.0 : system.intervalMs) + m_timeoutMs;
        const Level level = silent > 3 * limit ? Error : silent > limit ? Warning : Normal;
        if (level == system.lost)
            continue;
        system.lost = level;
        if (level == Normal)
            m_graph.clear(system.node);
        else
            m_graph.raise(system.node, level,
                          QStringLiteral("communications lost: nothing heard for %1 s").arg(silent / 1000.0, 0, 'f', 1));
    }
}

} // namespace neptus::alarms
