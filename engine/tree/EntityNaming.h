#pragma once

#include "Clock.h"
#include "Message.h"
#include "VariableTree.h"

#include <QHash>
#include <QMutex>
#include <QSet>

#include <memory>

namespace neptus::tree {

// Asks every system it meets for the names of its entities, so that rows and
// alarms say "Navigation", not "61": on first contact an EntityList query
// (op QUERY), repeated every few seconds until the list comes, at most
// maxAttempts times; then a QueryEntityInfo for each entity that still has
// no name. Queries go through the tree's output branch (and so show under
// "system/out"); a system that cannot be reached yet is asked again later.
class EntityNaming
{
public:
    static constexpr int maxAttempts = 5;
    static constexpr qint64 retryMs = 3000;

    // Queries are made with `schema` (the transports put them into each system's own definitions).
    EntityNaming(VariableTree &tree, std::shared_ptr<const msg::Schema> schema, const Clock *clock = &Clock::system());

    // Every received message (any thread).
    void observe(const msg::Message &message);
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

    VariableTree &m_tree;
    std::shared_ptr<const msg::Schema> m_schema;
    const Clock *m_clock;
    QMutex m_mutex;
    QHash<quint16, System> m_systems;
};

} // namespace neptus::tree
