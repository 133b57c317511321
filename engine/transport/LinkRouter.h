#pragma once

#include "VariableTree.h"

#include <QHash>
#include <QMutex>
#include <QString>

#include <vector>

namespace neptus::transport {

// The tree's output sink when a console has several links (IMC/UDP, DDS):
// each system is answered over the link it was last heard on. The tree does
// not care where a message came from; the router does.
class LinkRouter : public tree::VariableTree::OutputSink
{
public:
    void addLink(const QString &name, tree::VariableTree::OutputSink *sink);
    // `system` was heard on `link` (any thread).
    void heard(quint16 system, const QString &link);
    QString linkOf(quint16 system) const;

    // Over the system's link; false when it was never heard or the link cannot reach it.
    bool publish(quint16 system, const msg::Message &message) override;

private:
    mutable QMutex m_mutex;
    std::vector<std::pair<QString, tree::VariableTree::OutputSink *>> m_links;
    QHash<quint16, QString> m_systems;
};

} // namespace neptus::transport
