#pragma once

#include <QDateTime>
#include <QTimeZone>

namespace neptus {

// The time source of everything that depends on time (clocks, staleness,
// timeouts), so that tests drive time by hand instead of sleeping.
class Clock
{
public:
    virtual ~Clock() = default;
    virtual QDateTime now() const = 0;

    // The wall clock, in UTC. Lives for the whole program.
    static Clock &system();
};

// Milliseconds on the monotonic clock: for timeouts, rate windows and
// watchdogs, which must neither jump with the wall clock nor be driven by a
// test's Clock (cheap enough to read per packet).
qint64 monotonicMs();

// A clock that moves only when told to: for tests and for log replay.
class ManualClock final : public Clock
{
public:
    explicit ManualClock(QDateTime start = QDateTime::fromMSecsSinceEpoch(0, QTimeZone::UTC));
    QDateTime now() const override { return m_now; }
    void set(const QDateTime &time) { m_now = time.toUTC(); }
    void advance(qint64 milliseconds) { m_now = m_now.addMSecs(milliseconds); }

private:
    QDateTime m_now;
};

} // namespace neptus
