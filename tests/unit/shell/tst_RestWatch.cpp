// Whether anybody uses the console (issue #39: a console nobody touches
// shows vehicles at a lower rate, for the battery): any touch, click, mouse
// movement, wheel or key, in any window, is use; a while without any is rest.
#include "RestWatch.h"

#include <QCoreApplication>
#include <QEvent>
#include <QSignalSpy>
#include <QTest>

#include <gtest/gtest.h>

using namespace std::chrono_literals;

TEST(RestWatch, RestsAfterAWhileWithoutInputAndWakesAtTheFirstTouchClickOrKey)
{
    RestWatch watch(150ms);
    QSignalSpy changed(&watch, &RestWatch::restingChanged);
    EXPECT_FALSE(watch.resting()) << "in use at start";
    QObject window; // any receiver: the filter sits on the application
    for (const QEvent::Type input : {QEvent::TouchBegin, QEvent::MouseButtonPress, QEvent::MouseMove, QEvent::Wheel,
                                     QEvent::KeyPress, QEvent::TouchUpdate}) {
        ASSERT_TRUE(QTest::qWaitFor([&] { return watch.resting(); }, 2000)) << "rests after a while without input";
        QEvent event(input);
        QCoreApplication::sendEvent(&window, &event);
        EXPECT_FALSE(watch.resting()) << "woken by event type " << int(input);
    }
    EXPECT_EQ(changed.count(), 12) << "each rest and each wake said once";

    // Other events (timers, paints, the mouse leaving) are not use.
    ASSERT_TRUE(QTest::qWaitFor([&] { return watch.resting(); }, 2000));
    for (const QEvent::Type other : {QEvent::Timer, QEvent::UpdateRequest, QEvent::Leave, QEvent::KeyRelease}) {
        QEvent event(other);
        QCoreApplication::sendEvent(&window, &event);
    }
    EXPECT_TRUE(watch.resting());

    // Input keeps it in use: a finger moving every 50 ms for longer than the rest.
    QEvent touch(QEvent::TouchBegin);
    QCoreApplication::sendEvent(&window, &touch);
    for (int i = 0; i < 8; ++i) {
        QTest::qWait(50);
        QEvent move(QEvent::TouchUpdate);
        QCoreApplication::sendEvent(&window, &move);
        EXPECT_FALSE(watch.resting()) << "after " << (i + 1) * 50 << " ms of moving";
    }
}
