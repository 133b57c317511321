#include "transport/LinkStatistics.h"

#include <QMutexLocker>

#include <algorithm>

namespace neptus::transport {

int LinkStatistics::System::unknownTypes() const
{
    return static_cast<int>(std::count_if(types.begin(), types.end(), [](const Type &t) { return !t.known; }));
}

LinkStatistics::LinkStatistics(const Clock *clock)
    : m_clock(clock)
    , m_lastTickMs(clock->now().toMSecsSinceEpoch())
{
}

LinkStatistics::Counter &LinkStatistics::counterLocked(quint16 system)
{
    auto it = m_counters.find(system);
    if (it == m_counters.end()) {
        it = m_counters.insert(system, Counter{});
        it->system.id = system;
        ++m_version;
    }
    return *it;
}

void LinkStatistics::received(quint16 system, const QString &link, quint16 messageId, const QString &abbrev,
                              bool known, qsizetype bytes, bool mavlink)
{
    QMutexLocker lock(&m_mutex);
    Counter &counter = counterLocked(system);
    if (counter.system.link != link)
        counter.system.link = link;
    ++counter.system.messages;
    counter.system.bytes += static_cast<quint64>(bytes);
    const quint32 key = messageId | (mavlink ? 0x10000u : 0u);
    auto type = counter.types.find(key);
    if (type == counter.types.end()) {
        type = counter.types.insert(key, TypeCounter{});
        type->type.id = messageId;
        type->type.abbrev = abbrev;
        type->type.known = known;
        ++m_version;
    }
    ++type->type.count;
}

void LinkStatistics::decodeFailed(quint16 system, const QString &link, const QString &peer, const QString &reason)
{
    QMutexLocker lock(&m_mutex);
    Counter &counter = counterLocked(system);
    if (counter.system.link.isEmpty())
        counter.system.link = link;
    counter.system.peer = peer;
    ++counter.system.decodeErrors;
    counter.system.lastError = reason;
    counter.system.lastErrorMs = m_clock->now().toMSecsSinceEpoch();
}

void LinkStatistics::setSources(quint16 system, const QStringList &sources, const QString &destination)
{
    QMutexLocker lock(&m_mutex);
    Counter &counter = counterLocked(system);
    counter.system.sources = sources;
    counter.system.destination = destination;
}

void LinkStatistics::forget(quint16 system)
{
    QMutexLocker lock(&m_mutex);
    if (m_counters.remove(system))
        ++m_version;
}

void LinkStatistics::tick()
{
    const qint64 now = m_clock->now().toMSecsSinceEpoch();
    QMutexLocker lock(&m_mutex);
    const double seconds = static_cast<double>(now - m_lastTickMs) / 1000.0;
    m_lastTickMs = now;
    ++m_version;
    if (seconds <= 0)
        return;
    for (Counter &counter : m_counters) {
        counter.system.messageRate = static_cast<double>(counter.system.messages - counter.messagesAtTick) / seconds;
        counter.system.byteRate = static_cast<double>(counter.system.bytes - counter.bytesAtTick) / seconds;
        counter.messagesAtTick = counter.system.messages;
        counter.bytesAtTick = counter.system.bytes;
        for (TypeCounter &type : counter.types) {
            type.type.rate = static_cast<double>(type.type.count - type.countAtTick) / seconds;
            type.countAtTick = type.type.count;
        }
    }
}

LinkStatistics::System LinkStatistics::snapshotLocked(const Counter &counter) const
{
    System system = counter.system;
    system.types.reserve(static_cast<size_t>(counter.types.size()));
    for (const TypeCounter &type : counter.types)
        system.types.push_back(type.type);
    std::sort(system.types.begin(), system.types.end(), [](const Type &a, const Type &b) { return a.id < b.id; });
    return system;
}

std::vector<LinkStatistics::System> LinkStatistics::systems() const
{
    QMutexLocker lock(&m_mutex);
    std::vector<System> result;
    result.reserve(static_cast<size_t>(m_counters.size()));
    for (const Counter &counter : m_counters)
        result.push_back(snapshotLocked(counter));
    std::sort(result.begin(), result.end(), [](const System &a, const System &b) { return a.id < b.id; });
    return result;
}

LinkStatistics::System LinkStatistics::system(quint16 id) const
{
    QMutexLocker lock(&m_mutex);
    const auto it = m_counters.constFind(id);
    if (it == m_counters.cend()) {
        System none;
        none.id = id;
        return none;
    }
    return snapshotLocked(*it);
}

quint64 LinkStatistics::version() const
{
    QMutexLocker lock(&m_mutex);
    return m_version;
}

} // namespace neptus::transport
