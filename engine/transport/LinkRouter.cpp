#include "transport/LinkRouter.h"

#include "messages/Message.h"

#include <QMutexLocker>

namespace neptus::transport {

void LinkRouter::addLink(const QString &name, OutputSink *sink)
{
    QMutexLocker lock(&m_mutex);
    m_links.emplace_back(name, sink);
}

void LinkRouter::heard(quint16 system, const QString &link)
{
    QMutexLocker lock(&m_mutex);
    m_systems.insert(system, link);
}

void LinkRouter::forget(quint16 system)
{
    QMutexLocker lock(&m_mutex);
    m_systems.remove(system);
}

QString LinkRouter::linkOf(quint16 system) const
{
    QMutexLocker lock(&m_mutex);
    return m_systems.value(system);
}

std::expected<void, QString> LinkRouter::publish(quint16 system, const msg::Message &message)
{
    OutputSink *sink = nullptr;
    QString link;
    {
        QMutexLocker lock(&m_mutex);
        link = m_systems.value(system);
        for (const auto &[name, candidate] : m_links) {
            if (name == link)
                sink = candidate;
        }
    }
    if (link.isEmpty())
        return std::unexpected(QStringLiteral("no link to %1: it was never heard").arg(msg::systemLabel(system)));
    if (!sink)
        return std::unexpected(QStringLiteral("no link to %1: %2 is not open").arg(msg::systemLabel(system), link));
    return sink->publish(system, message);
}

} // namespace neptus::transport
