#include "ConsoleSession.h"

#include "MessageJson.h"

#include <QJsonObject>

ConsoleSession::ConsoleSession(std::shared_ptr<const neptus::msg::Schema> schema, QObject *parent)
    : QObject(parent)
    , m_schema(std::move(schema))
    , m_scripts(std::make_unique<neptus::scripting::ScriptHost>(m_tree, m_graph))
{
    m_tree.setOutputSink(&m_router);
    m_healthCheck.setInterval(250);
    connect(&m_healthCheck, &QTimer::timeout, this, [this] { m_health.check(); });
    m_healthCheck.start();
}

ConsoleSession::~ConsoleSession() = default;

QString ConsoleSession::send(const QString &system, const QVariantMap &json)
{
    auto message = neptus::msg::fromJson(*m_schema, QJsonObject::fromVariantMap(json));
    if (!message)
        return message.error();
    if (!m_tree.write(system, std::move(*message)))
        return tr("not sent: no link to '%1'").arg(system);
    return {};
}

void ConsoleSession::addLink(const QString &name, neptus::tree::VariableTree::OutputSink *sink)
{
    m_router.addLink(name, sink);
}

void ConsoleSession::definitionsDiffer(quint16 system, const QString &theirDigest, const QString &ourDigest)
{
    const auto node = m_graph.ensure(QStringLiteral("systems/%1/definitions").arg(m_tree.systemName(system)));
    m_graph.raise(node, neptus::alarms::Warning,
                  tr("speaks other message definitions (digest %1, ours %2): its values may be misread")
                      .arg(theirDigest.left(8), ourDigest.left(8)));
}

void ConsoleSession::ingest(const neptus::msg::Message &message, const QString &link)
{
    if (!link.isEmpty() && m_router.linkOf(message.header.src) != link) {
        m_router.heard(message.header.src, link);
        m_tree.setSystemLink(message.header.src, link);
    }
    m_tree.ingest(message);
    m_health.observe(message);
}
