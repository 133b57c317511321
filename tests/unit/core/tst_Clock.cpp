#include "core/Clock.h"
#include "qmlmodels/UtcClock.h"

#include <QSignalSpy>
#include <QTest>

#include <gtest/gtest.h>

using namespace neptus;

namespace {
QDateTime utc(const char *iso) { return QDateTime::fromString(QString::fromLatin1(iso), Qt::ISODateWithMs); }
}

TEST(ManualClock, MovesOnlyWhenTold)
{
    ManualClock clock(utc("2026-11-22T10:00:00.000Z"));
    EXPECT_EQ(clock.now(), utc("2026-11-22T10:00:00.000Z"));
    clock.advance(1500);
    EXPECT_EQ(clock.now(), utc("2026-11-22T10:00:01.500Z"));
    clock.set(utc("2026-11-22T12:00:00.000+02:00"));
    EXPECT_EQ(clock.now().timeSpec(), Qt::UTC);
    EXPECT_EQ(clock.now().time().hour(), 10);
}

TEST(SystemClock, IsUtcAndCurrent)
{
    const QDateTime before = QDateTime::currentDateTimeUtc();
    const QDateTime now = Clock::system().now();
    EXPECT_EQ(now.timeSpec(), Qt::UTC);
    EXPECT_GE(now, before);
    EXPECT_LE(now, QDateTime::currentDateTimeUtc());
}

TEST(UtcClock, ShowsTheClockTimeInUtc)
{
    ManualClock clock(utc("2026-11-22T14:03:27.250Z"));
    UtcClock display;
    display.setClock(&clock);
    EXPECT_EQ(display.text(), QStringLiteral("14:03:27 UTC"));
    clock.set(utc("2026-11-22T23:59:59.999+01:00"));
    display.tick();
    EXPECT_EQ(display.text(), QStringLiteral("22:59:59 UTC"));
}

TEST(UtcClock, TicksOnWholeSeconds)
{
    EXPECT_EQ(UtcClock::msUntilNextSecond(utc("2026-11-22T14:03:27.000Z")), 1000);
    EXPECT_EQ(UtcClock::msUntilNextSecond(utc("2026-11-22T14:03:27.250Z")), 750);
    EXPECT_EQ(UtcClock::msUntilNextSecond(utc("2026-11-22T14:03:27.999Z")), 1);
}

TEST(UtcClock, KeepsTickingOnItsOwn)
{
    UtcClock display;
    QSignalSpy ticks(&display, &UtcClock::ticked);
    // Two ticks need at most two seconds; the generous wait only bounds a hang.
    EXPECT_TRUE(QTest::qWaitFor([&] { return ticks.count() >= 2; }, 5000));
    EXPECT_EQ(display.time().time().msec() < 500, true) << "ticks should land just after a whole second";
}
