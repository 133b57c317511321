#include "qmlmodels/UtcClock.h"

namespace neptus {

UtcClock::UtcClock(QObject *parent)
    : QObject(parent)
{
    m_timer.setSingleShot(true);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &UtcClock::tick);
    tick();
}

void UtcClock::setClock(const Clock *clock)
{
    m_clock = clock ? clock : &Clock::system();
    tick();
}

QString UtcClock::text() const
{
    return m_time.toString(QStringLiteral("HH:mm:ss")) + QStringLiteral(" UTC");
}

int UtcClock::msUntilNextSecond(const QDateTime &time)
{
    return 1000 - static_cast<int>(time.time().msec());
}

void UtcClock::tick()
{
    m_time = m_clock->now().toUTC();
    m_timer.start(msUntilNextSecond(m_time));
    emit ticked();
}

} // namespace neptus
