#pragma once

#include "transport/OutputSink.h"

#include <QHash>
#include <QMutex>
#include <QString>

#include <vector>

namespace neptus::transport {

// The tree's output sink when a console has several links (IMC/UDP, DDS):
// each system is answered over the link it was last heard on. The tree does
// not care where a message came from; the router does.
class LinkRouter : public OutputSink
{
public:
    void addLink(const QString &name, OutputSink *sink);
    // `system` was heard on `link` (any thread).
    void heard(quint16 system, const QString &link);
    void forget(quint16 system); // a system forgotten: never heard, until it is again
    QString linkOf(quint16 system) const;

    // Over the system's link; an error when it was never heard or the link cannot reach it.
    std::expected<void, QString> publish(quint16 system, const msg::Message &message) override;

private:
    mutable QMutex m_mutex;
    std::vector<std::pair<QString, OutputSink *>> m_links;
    QHash<quint16, QString> m_systems;
};

} // namespace neptus::transport
