// Layouts that never finish: `while (true)` in a binding hung the console
// forever with no message (also when typed in the designer, which rebuilds
// the live console from it). Bounded by the ctest TIMEOUT, like the other
// hostile tests: a regression is a timeout.
#include "JsWatchdog.h"

#include <QElapsedTimer>
#include <QQmlComponent>
#include <QQmlEngine>
#include <QSignalSpy>

#include <gtest/gtest.h>

#include <memory>

namespace {

// An engine watched with a 300 ms limit.
struct HostileLayouts : ::testing::Test
{
    std::unique_ptr<QObject> create(const char *qml, const char *file)
    {
        QQmlComponent component(&engine);
        component.setData(qml, QUrl::fromLocalFile(QString::fromLatin1(file)));
        return std::unique_ptr<QObject>(component.create());
    }

    QQmlEngine engine;
    JsWatchdog watchdog{engine, std::chrono::milliseconds(300)};
    QSignalSpy stopped{&watchdog, &JsWatchdog::stopped};
};

} // namespace

TEST_F(HostileLayouts, ABindingThatNeverEndsIsStoppedAndNamed)
{
    QElapsedTimer timer;
    timer.start();
    const auto spin = create("import QtQml\n"
                             "QtObject {\n"
                             "    property int depth: { while (true) {} return 1 }\n"
                             "    property string name: \"after the loop\"\n"
                             "}\n",
                             "/layouts/Spin.qml");
    std::printf("the endless binding was stopped after %lld ms (limit 300 ms)\n", static_cast<long long>(timer.elapsed()));
    ASSERT_NE(spin, nullptr) << "the rest of the layout is still made";
    EXPECT_EQ(spin->property("name").toString(), QStringLiteral("after the loop"));
    ASSERT_TRUE(stopped.wait(2000));
    const QString report = stopped.constFirst().constFirst().toString();
    EXPECT_TRUE(report.contains(QStringLiteral("/layouts/Spin.qml:3"))) << report.toStdString();
    EXPECT_TRUE(report.contains(QStringLiteral("was stopped"))) << report.toStdString();

    // The engine runs JavaScript again afterwards.
    const auto next = create("import QtQml\nQtObject { property int answer: { let a = 0; for (let i = 0; i < 42; ++i) ++a; return a } }\n",
                             "/layouts/Next.qml");
    ASSERT_NE(next, nullptr);
    EXPECT_EQ(next->property("answer").toInt(), 42);
}

TEST_F(HostileLayouts, AHandlerThatNeverEndsIsStopped)
{
    const auto spin = create("import QtQml\nQtObject {\n    Component.onCompleted: { for (;;) {} }\n}\n",
                             "/layouts/Handler.qml");
    ASSERT_NE(spin, nullptr);
    ASSERT_TRUE(stopped.wait(2000));
    EXPECT_TRUE(stopped.constFirst().constFirst().toString().contains(QStringLiteral("was stopped")));
}

TEST_F(HostileLayouts, AQuietConsoleIsNeverInterrupted)
{
    // Work in many short turns, each under the limit, for longer than it.
    QElapsedTimer timer;
    timer.start();
    int sum = 0;
    while (timer.elapsed() < 900) {
        const auto busy = create("import QtQml\nQtObject { property int n: { let t = Date.now(); while (Date.now() - t < 100) {} return 1 } }\n",
                                 "/layouts/Busy.qml");
        sum += busy ? busy->property("n").toInt() : 0;
        QCoreApplication::processEvents();
    }
    EXPECT_FALSE(stopped.wait(400));
    EXPECT_GE(sum, 5);
}
