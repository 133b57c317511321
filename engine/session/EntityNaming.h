#pragma once

#include "core/Clock.h"
#include "messages/Message.h"
#include "tree/VariableTree.h"

#include <QHash>
#include <QMutex>
#include <QSet>

#include <expected>
#include <functional>
#include <memory>

namespace neptus::session {

// Asks every system it meets for the names of its entities, so that rows and
// alarms say "Navigation", not "61": on first contact an EntityList query
// (op QUERY), repeated every few seconds until the list comes, at most
// maxAttempts times; then a QueryEntityInfo for each entity that still has
// no name. Queries go out through `send` (the console's, which records them
// under "system/out"); a system that cannot be reached yet is asked again later.
class EntityNaming
{
public:
    static constexpr int maxAttempts = 5;
    static constexpr qint64 retryMs = 3000;

    using Send = std::function<std::expected<void, QString>(quint16 system, msg::Message message)>;

    // Queries are made with `schema` (the transports put them into each
    // system's own definitions); labels come from `tree`.
    EntityNaming(const tree::VariableTree &tree, std::shared_ptr<const msg::Schema> schema, Send send,
                 const Clock *clock = &Clock::system());

    // Every received message (any thread).
    void observe(const msg::Message &message);
    // A system forgotten: met again, it is asked again.
    void forget(quint16 system);
    // Sends what is due; call a few times a second on the thread that sends.
    void check();

private:
    struct System
    {
        bool listed = false;          // an EntityList REPORT came
        int listQueries = 0;
        qint64 lastListQueryMs = 0;
        QSet<quint8> entities;        // entities heard from
        QHash<quint8, int> infoQueries;
        QHash<quint8, qint64> lastInfoQueryMs;
    };

    const tree::VariableTree &m_tree;
    std::shared_ptr<const msg::Schema> m_schema;
    Send m_send;
    const Clock *m_clock;
    QMutex m_mutex;
    QHash<quint16, System> m_systems;
};

} // namespace neptus::session
