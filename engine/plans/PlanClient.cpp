#include "plans/PlanClient.h"

#include "messages/Schema.h"

namespace neptus::plans {

using namespace Qt::StringLiterals;

PlanClient::PlanClient(std::shared_ptr<const msg::Schema> schema, quint16 vehicle, Sender send, QObject *parent)
    : QObject(parent), m_schema(std::move(schema)), m_vehicle(vehicle), m_send(std::move(send))
{
}

quint16 PlanClient::set(const msg::Message &specification)
{
    return request("PlanDB", u"SET"_s, specification.text(u"plan_id"), specification);
}

quint16 PlanClient::remove(const QString &planId)
{
    return request("PlanDB", u"DEL"_s, planId, std::nullopt);
}

quint16 PlanClient::get(const QString &planId)
{
    return request("PlanDB", u"GET"_s, planId, std::nullopt);
}

quint16 PlanClient::getState(bool detailed)
{
    return request("PlanDB", detailed ? u"GET_DSTATE"_s : u"GET_STATE"_s, {}, std::nullopt);
}

quint16 PlanClient::start(const QString &planId, quint16 flags)
{
    return request("PlanControl", u"START"_s, planId, std::nullopt, flags);
}

quint16 PlanClient::start(const msg::Message &specificationOrManeuver, const QString &planId, quint16 flags)
{
    return request("PlanControl", u"START"_s, planId, specificationOrManeuver, flags);
}

quint16 PlanClient::stop(const QString &planId)
{
    return request("PlanControl", u"STOP"_s, planId, std::nullopt);
}

quint16 PlanClient::load(const QString &planId)
{
    return request("PlanControl", u"LOAD"_s, planId, std::nullopt);
}

quint16 PlanClient::running()
{
    return request("PlanControl", u"GET"_s, {}, std::nullopt);
}

quint16 PlanClient::request(const char *abbrev, const QString &op, const QString &planId, std::optional<msg::Message> arg,
                            quint16 flags)
{
    const msg::MessageDef *def = m_schema->byAbbrev(QString::fromLatin1(abbrev));
    msg::Message message(def);
    // Skip ids still waiting (65,535 requests in flight would be a bug elsewhere).
    while (m_pending.contains(m_nextId) || m_nextId == 0)
        ++m_nextId;
    const quint16 id = m_nextId++;
    const auto enumerated = [&](const char *field, const QString &name) {
        const int index = def->indexOf(QString::fromLatin1(field));
        message.setInteger(index, message.field(index).enumeration->parse(name).value_or(0));
    };
    enumerated("type", u"REQUEST"_s);
    enumerated("op", op);
    message.setInteger(def->indexOf(u"request_id"), id);
    message.setBytes(def->indexOf(u"plan_id"), planId.toUtf8());
    message.setInlineMessage(def->indexOf(u"arg"), std::move(arg));
    if (const int f = def->indexOf(u"flags"); f >= 0)
        message.setInteger(f, flags);
    message.header.dst = m_vehicle; // IMC vehicles ignore the broadcast id
    message.header.dstEnt = 0xFF;

    Request &r = m_pending[id];
    r.message = std::move(message);
    r.op = op;
    r.timer.reset(new QTimer(this)); // a child too: none outlives the client
    r.timer->setSingleShot(true);
    connect(r.timer.get(), &QTimer::timeout, this, [this, id] {
        const auto found = m_pending.find(id);
        if (found == m_pending.end())
            return;
        const Request &r = found->second;
        if (r.attempts < m_attempts)
            send(id);
        else
            finish(id, Reply{id, r.message.abbrev(), r.op, r.message.text(u"plan_id"), false,
                             u"no answer from 0x%1 after %2 tries, %3 ms apart"_s.arg(m_vehicle, 4, 16, QChar(u'0'))
                                 .arg(r.attempts).arg(m_timeout.count()),
                             std::nullopt, r.attempts});
    });
    send(id);
    return id;
}

void PlanClient::send(quint16 id)
{
    Request &r = m_pending[id];
    ++r.attempts;
    r.timer->start(m_timeout);
    m_send(r.message);
}

void PlanClient::finish(quint16 id, Reply reply)
{
    m_pending.erase(id);
    emit replied(reply);
}

bool PlanClient::receive(const msg::Message &message)
{
    const bool control = message.abbrev() == u"PlanControl";
    if ((!control && message.abbrev() != u"PlanDB") || message.header.src != m_vehicle)
        return false;
    const QString type = message.enumText(message.def()->indexOf(u"type"));
    const QString op = message.enumText(message.def()->indexOf(u"op"));
    if (type == u"REQUEST")
        return false;
    const quint16 id = static_cast<quint16>(message.integer(u"request_id"));
    const auto found = m_pending.find(id);
    if (found == m_pending.end() || found->second.message.abbrev() != message.abbrev() || found->second.op != op)
        return false; // not an answer we wait for (DUNE's later words to a START, a duplicate)
    Request &r = found->second;
    if (type == u"IN_PROGRESS") {
        r.timer->start(m_timeout); // still working on it: wait again, without sending again
        return true;
    }
    std::optional<msg::Message> arg;
    if (const msg::Message *inner = message.inlineMessage(message.def()->indexOf(u"arg")))
        arg = *inner;
    finish(id, Reply{id, message.abbrev(), r.op, message.text(u"plan_id"), type == u"SUCCESS", message.text(u"info"),
                     std::move(arg), r.attempts});
    return true;
}

} // namespace neptus::plans
