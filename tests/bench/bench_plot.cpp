// Frame times of the Plot component with 500,000 points (2 series of 250,000)
// on software OpenGL (Mesa llvmpipe under Xvfb), 1280x800: every frame adds a
// point to each series and the live window scrolls, so every frame redraws.
// Also 2 x 250,000 points in a 24-hour span (all of them in view). Prints
// p50 / p99 of the frame-to-frame time and the render thread's share.
// Run: tools/bench plot
#include "FrameTimes.h"

#include <QGuiApplication>
#include <QQmlComponent>
#include <QQmlEngine>
#include <QQuickItem>
#include <QQuickWindow>
#include <QtQml/qqmlextensionplugin.h>

#include <cmath>
#include <cstdio>

Q_IMPORT_QML_PLUGIN(Neptus_EnginePlugin)
Q_IMPORT_QML_PLUGIN(Neptus_ComponentsPlugin)

namespace {

using neptus::test::FrameTimes;

FrameTimes measure(QQuickWindow &window, QObject *series, int frames, double &t)
{
    return neptus::test::measureFrames(window, frames, [&] {
        t += 0.02;
        QMetaObject::invokeMethod(series, "append", Q_ARG(int, 0), Q_ARG(double, t), Q_ARG(double, std::sin(t)));
        QMetaObject::invokeMethod(series, "append", Q_ARG(int, 1), Q_ARG(double, t), Q_ARG(double, std::cos(t)));
    });
}

} // namespace

int main(int argc, char **argv)
{
    QGuiApplication app(argc, argv);
    QQmlEngine engine;
    QQuickWindow window;
    const auto plot = neptus::test::showInWindow(engine, window, "import QtQuick\nimport Neptus.Components\n"
        "Plot { width: 1280; height: 800; span: 300; paths: [\"a/X/v\", \"b/X/v\"] }");
    if (!plot)
        return 1;
    auto *series = plot->property("series").value<QObject *>();

    const int points = 250'000;
    double t = 0;
    for (int i = 0; i < points; ++i, t += 0.02) {
        QMetaObject::invokeMethod(series, "append", Q_ARG(int, 0), Q_ARG(double, t), Q_ARG(double, std::sin(t)));
        QMetaObject::invokeMethod(series, "append", Q_ARG(int, 1), Q_ARG(double, t), Q_ARG(double, std::cos(t)));
    }
    std::printf("Plot, 1280x800, software OpenGL (%s), 2 series x %d points\n",
                qPrintable(QString::fromLatin1(qgetenv("QT_QPA_PLATFORM"))), points);
    const FrameTimes recent = measure(window, series, 300, t);
    std::printf("%-46s p50 %6.2f ms  p99 %6.2f ms  max %6.2f ms\n", "last 5 min in view (15,000 points), live", recent.p50,
                recent.p99, recent.max);
    plot->setProperty("span", 24 * 3600.0);
    const FrameTimes all = measure(window, series, 300, t);
    std::printf("%-46s p50 %6.2f ms  p99 %6.2f ms  max %6.2f ms\n", "all 500,000 points in view, live", all.p50, all.p99,
                all.max);
    // What the window costs without the plot's lines: the software renderer's floor.
    series->setProperty("visible", false);
    const FrameTimes floor = measure(window, series, 300, t);
    std::printf("%-46s p50 %6.2f ms  p99 %6.2f ms  max %6.2f ms\n", "baseline: same window, lines hidden", floor.p50,
                floor.p99, floor.max);
    return 0;
}
