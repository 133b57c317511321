#include "session/EntityNaming.h"

#include <QMutexLocker>

namespace neptus::session {

EntityNaming::EntityNaming(const tree::VariableTree &tree, std::shared_ptr<const msg::Schema> schema, Send send,
                           const Clock *clock)
    : m_tree(tree)
    , m_schema(std::move(schema))
    , m_send(std::move(send))
    , m_clock(clock)
{
}

void EntityNaming::forget(quint16 system)
{
    QMutexLocker lock(&m_mutex);
    m_systems.remove(system);
}

void EntityNaming::observe(const msg::Message &message)
{
    QMutexLocker lock(&m_mutex);
    System &system = m_systems[message.header.src];
    const quint8 entity = message.header.srcEnt;
    if (entity != 0xFF)
        system.entities.insert(entity);
    if (message.def() && message.def()->abbrev == u"EntityList" && message.integer(u"op") == 0)
        system.listed = true;
}

void EntityNaming::check()
{
    const qint64 now = m_clock->now().toMSecsSinceEpoch();
    struct Query
    {
        quint16 system;
        int entity; // -1: the list
    };
    std::vector<Query> due;
    {
        QMutexLocker lock(&m_mutex);
        for (auto it = m_systems.begin(); it != m_systems.end(); ++it) {
            System &system = *it;
            if (!system.listed && system.listQueries < maxAttempts) {
                if (now - system.lastListQueryMs >= retryMs)
                    due.push_back({it.key(), -1});
                continue; // the list may name them all: ask for single entities after it
            }
            for (quint8 entity : std::as_const(system.entities)) {
                if (m_tree.entityLabel(it.key(), entity) != QString::number(entity))
                    continue; // named
                if (system.infoQueries.value(entity) < maxAttempts && now - system.lastInfoQueryMs.value(entity) >= retryMs)
                    due.push_back({it.key(), entity});
            }
        }
    }
    for (const Query &query : due) {
        msg::Message request;
        const msg::Schema *schema = m_schema.get();
        if (query.entity < 0) {
            const msg::MessageDef *def = schema->byAbbrev(u"EntityList");
            if (!def)
                continue;
            request = msg::Message(def);
            request.setInteger(def->indexOf(u"op"), 1); // QUERY
        } else {
            const msg::MessageDef *def = schema->byAbbrev(u"QueryEntityInfo");
            if (!def)
                continue;
            request = msg::Message(def);
            request.setInteger(def->indexOf(u"id"), query.entity);
        }
        // Unreachable (no link yet): not counted, asked again at the next check.
        if (!m_send(query.system, std::move(request)))
            continue;
        QMutexLocker lock(&m_mutex);
        System &system = m_systems[query.system];
        if (query.entity < 0) {
            ++system.listQueries;
            system.lastListQueryMs = now;
        } else {
            const auto entity = static_cast<quint8>(query.entity);
            system.infoQueries[entity] += 1;
            system.lastInfoQueryMs[entity] = now;
        }
    }
}

} // namespace neptus::session
