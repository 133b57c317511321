#include "qmlmodels/ConsoleSession.h"

#include "messages/MessageJson.h"

#include <QJsonObject>

using namespace neptus;

ConsoleSession::ConsoleSession(std::shared_ptr<const msg::Schema> schema, const Clock *clock, QObject *parent)
    : QObject(parent)
    , m_console(std::move(schema), clock)
    , m_planDesk(m_console.sharedSchema(), m_console.tree(), m_console.alarmGraph(),
                 [this](quint16 system, const msg::Message &message) { return m_console.send(system, message); },
                 [this] { return m_console.scripts(); }, clock)
{
    connect(&m_console, &session::Console::planMessageReceived, &m_planDesk, &plans::PlanDesk::receive);
}

ConsoleSession::~ConsoleSession() = default;

QString ConsoleSession::send(const QString &system, const QVariantMap &json)
{
    auto message = msg::fromJson(m_console.schema(), QJsonObject::fromVariantMap(json));
    if (!message)
        return message.error();
    if (auto sent = m_console.send(system, std::move(*message)); !sent)
        return tr("not sent: %1").arg(sent.error());
    return {};
}

void ConsoleSession::forgetSystem(int systemId)
{
    if (systemId < 0 || systemId >= 0xFFFF)
        return;
    m_console.forget(static_cast<quint16>(systemId));
    m_linksModel.refresh();
}

bool ConsoleSession::chooseSource(int systemId, const QString &host)
{
    if (systemId < 0 || systemId >= 0xFFFF)
        return false;
    const bool chosen = m_console.chooseSource(static_cast<quint16>(systemId), host);
    if (chosen)
        m_linksModel.refresh();
    return chosen;
}
