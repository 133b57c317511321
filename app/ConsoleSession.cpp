#include "ConsoleSession.h"

ConsoleSession::ConsoleSession(std::shared_ptr<const neptus::msg::Schema> schema, QObject *parent)
    : QObject(parent)
    , m_schema(std::move(schema))
    , m_scripts(std::make_unique<neptus::scripting::ScriptHost>(m_tree, m_graph))
{
    m_healthCheck.setInterval(250);
    connect(&m_healthCheck, &QTimer::timeout, this, [this] { m_health.check(); });
    m_healthCheck.start();
}

ConsoleSession::~ConsoleSession() = default;

void ConsoleSession::ingest(const neptus::msg::Message &message)
{
    m_tree.ingest(message);
    m_health.observe(message);
}
