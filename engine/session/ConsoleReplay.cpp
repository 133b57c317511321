#include "session/ConsoleReplay.h"

#include <QTimeZone>

namespace neptus::session {

ConsoleReplay::ConsoleReplay(Console &console, ManualClock &clock)
    : m_console(console)
    , m_clock(clock)
{
    m_console.setReplaying(true);
}

void ConsoleReplay::clear()
{
    for (const quint16 system : m_console.tree().systemIds())
        m_console.forget(system);
}

void ConsoleReplay::setTime(double t)
{
    m_clock.set(QDateTime::fromMSecsSinceEpoch(qint64(std::llround(t * 1000.0)), QTimeZone::UTC));
}

void ConsoleReplay::deliver(const msg::Message &message, bool sent)
{
    if (sent) {
        // The links' own upkeep (Announce, Heartbeat) is recorded but never shown under "out".
        const QString abbrev = message.abbrev();
        if (abbrev != u"Announce" && abbrev != u"Heartbeat")
            m_console.tree().recordSent(message.header.dst, message);
    } else
        m_console.ingest(message);
}

} // namespace neptus::session
