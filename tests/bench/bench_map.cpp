// Frame times of the Map2D component with two trails of 100,000 points each
// on software OpenGL (Mesa llvmpipe under Xvfb), 1280x800, no tiles (grid):
// every frame the map pans by a pixel (or turns by a degree) and each trail
// gains a point, so every frame redraws everything. Prints p50 / p99 of the
// frame-to-frame time, and the same window with the trails hidden.
// Run: tools/bench map
#include "FrameTimes.h"
#include "Geodesy.h"
#include "Tracks.h"
#include "VariableTreeModel.h"

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

using namespace neptus;

namespace {

constexpr double homeLat = 41.18, homeLon = -8.70;

// A lawn-mower survey: legs `leg` metres long, `spacing` apart, a fix every 0.5 m.
geo::Tracks::Fix surveyFix(int i, double eastOffset)
{
    const double step = 0.5, leg = 2000, spacing = 20;
    const int perLeg = int(leg / step);
    const int legIndex = i / perLeg;
    const double along = (i % perLeg) * step;
    const double north = legIndex % 2 == 0 ? along - leg / 2 : leg / 2 - along;
    const auto p = geo::fromNed({north, eastOffset + legIndex * spacing, 0},
                                {geo::radians(homeLat), geo::radians(homeLon), 0});
    return {double(i), p.lat, p.lon, 0, 0, 0, 0, legIndex % 2 == 0 ? 0.0f : 3.14159f};
}

} // namespace

int main(int argc, char **argv)
{
    QGuiApplication app(argc, argv);
    ManualClock clock;
    tree::VariableTree tree(&clock);
    tree::VariableTreeModel model(&tree);
    geo::Tracks tracks(&model);
    tracks.setHome({{QStringLiteral("lat"), homeLat}, {QStringLiteral("lon"), homeLon}});
    const int points = 100'000;
    for (int i = 0; i < points; ++i) {
        tracks.append(QStringLiteral("alpha"), surveyFix(i, -1100));
        tracks.append(QStringLiteral("bravo"), surveyFix(i, 100));
    }

    QQmlEngine engine;
    QQmlComponent sessionComponent(&engine);
    sessionComponent.setData("import QtQuick\nQtObject { property var tree; property var tracks }", QUrl());
    std::unique_ptr<QObject> session(sessionComponent.create());
    session->setProperty("tree", QVariant::fromValue(&model));
    session->setProperty("tracks", QVariant::fromValue(&tracks));
    engine.singletonInstance<QObject *>("Neptus.Components", "Session")->setProperty("session", QVariant::fromValue(session.get()));

    QQmlComponent component(&engine);
    component.setData("import QtQuick\nimport Neptus.Components\n"
                      "Map2D { width: 1280; height: 800; initialZoomLevel: 13.2; follow: \"\" }",
                      QUrl());
    QQuickWindow window;
    window.resize(1280, 800);
    std::unique_ptr<QObject> object(component.create());
    auto *map2d = qobject_cast<QQuickItem *>(object.get());
    if (!map2d) {
        std::fprintf(stderr, "%s\n", qPrintable(component.errorString()));
        return 1;
    }
    map2d->setParentItem(window.contentItem());
    auto *map = map2d->property("map").value<QObject *>();
    window.show();

    int next = points;
    auto grow = [&] {
        tracks.append(QStringLiteral("alpha"), surveyFix(next, -1100));
        tracks.append(QStringLiteral("bravo"), surveyFix(next, 100));
        ++next;
        emit tracks.updated();
    };
    auto pan = [&] {
        QMetaObject::invokeMethod(map, "pan", Q_ARG(int, 1), Q_ARG(int, 0));
        grow();
    };
    auto turn = [&] {
        map->setProperty("bearing", map->property("bearing").toDouble() + 1);
        grow();
    };
    // Warm up: the first frames upload the trails.
    neptus::test::measureFrames(window, 30, pan);
    std::printf("Map2D, 1280x800, software OpenGL (%s), 2 trails x %d points, no tiles (grid)\n",
                qPrintable(QString::fromLatin1(qgetenv("QT_QPA_PLATFORM"))), points);
    auto print = [](const char *what, const neptus::test::FrameTimes &r) {
        std::printf("%-52s p50 %6.2f ms  p99 %6.2f ms  max %6.2f ms  (%d frames)\n", what, r.p50, r.p99, r.max, r.frames);
    };
    print("both survey areas in view, panning, trails growing", neptus::test::measureFrames(window, 300, pan));
    print("both in view, rotating, trails growing", neptus::test::measureFrames(window, 300, turn));
    map->setProperty("bearing", 0);
    map->setProperty("zoomLevel", 17.0);
    print("zoomed in (zoom 17), panning, trails growing", neptus::test::measureFrames(window, 300, pan));
    map->setProperty("zoomLevel", 13.2);
    map2d->setProperty("showTrails", false);
    print("baseline: same map and panning, trails hidden", neptus::test::measureFrames(window, 300, pan));
    return 0;
}
