#include "LinkRouter.h"

#include <QMutexLocker>

namespace neptus::transport {

void LinkRouter::addLink(const QString &name, tree::VariableTree::OutputSink *sink)
{
    QMutexLocker lock(&m_mutex);
    m_links.emplace_back(name, sink);
}

void LinkRouter::heard(quint16 system, const QString &link)
{
    QMutexLocker lock(&m_mutex);
    m_systems.insert(system, link);
}

QString LinkRouter::linkOf(quint16 system) const
{
    QMutexLocker lock(&m_mutex);
    return m_systems.value(system);
}

bool LinkRouter::publish(quint16 system, const msg::Message &message)
{
    tree::VariableTree::OutputSink *sink = nullptr;
    {
        QMutexLocker lock(&m_mutex);
        const QString link = m_systems.value(system);
        for (const auto &[name, candidate] : m_links) {
            if (name == link)
                sink = candidate;
        }
    }
    return sink && sink->publish(system, message);
}

} // namespace neptus::transport
