// Frame times of the Map2D component with two trails of 100,000 points each
// on software OpenGL (Mesa llvmpipe under Xvfb), 1280x800, no tiles (grid):
// every frame the map pans by a pixel (or turns by a degree) and each trail
// gains a point, so every frame redraws everything. Prints p50 / p99 of the
// frame-to-frame time, and the same window with the trails hidden.
// Run: tools/bench map
#include "FrameTimes.h"
#include "geo/Geodesy.h"
#include "FakeVehicle.h"
#include "Paths.h"
#include "qmlmodels/ConsoleSession.h"

#include <QElapsedTimer>
#include <QFileInfo>
#include <QGuiApplication>
#include <QQmlComponent>
#include <QQmlEngine>
#include <QQuickItem>
#include <QQuickWindow>
#include <QTemporaryDir>
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
    // --smoke: a few frames of small trails, so that ctest keeps it working.
    const bool smoke = app.arguments().contains(QStringLiteral("--smoke"));
    // --chart: only the nautical chart's cases (small trails, hidden), for work on the chart layer.
    const bool chartOnly = app.arguments().contains(QStringLiteral("--chart"));
    const int frames = smoke ? 5 : 300;
    // A real session (the Session singleton takes nothing else), its tracks fed directly.
    ConsoleSession session(test::shippedSchema());
    geo::Tracks &tracks = *session.tracks();
    tracks.setHome({{QStringLiteral("lat"), homeLat}, {QStringLiteral("lon"), homeLon}});
    const int points = smoke || chartOnly ? 2'000 : 100'000;
    for (int i = 0; i < points; ++i) {
        tracks.append(QStringLiteral("alpha"), surveyFix(i, -1100));
        tracks.append(QStringLiteral("bravo"), surveyFix(i, 100));
    }

    QQmlEngine engine;
    engine.singletonInstance<QObject *>("Neptus.Components", "Session")->setProperty("session", QVariant::fromValue(&session));

    QQuickWindow window;
    const auto map = neptus::test::showInWindow(engine, window, "import QtQuick\nimport Neptus.Components\n"
        "Map2D { width: 1280; height: 800; initialZoomLevel: 13.2; follow: \"\" }");
    if (!map)
        return 1;
    // The map opens at home, where the surveys are: otherwise nothing of them is timed.
    if (std::abs(map->property("centerLatitude").toDouble() - homeLat) > 1e-6) {
        std::fprintf(stderr, "bench_map: the map did not open at home (%f, %f)\n", map->property("centerLatitude").toDouble(),
                     map->property("centerLongitude").toDouble());
        return 1;
    }

    int next = points;
    auto grow = [&] {
        tracks.append(QStringLiteral("alpha"), surveyFix(next, -1100));
        tracks.append(QStringLiteral("bravo"), surveyFix(next, 100));
        ++next;
        emit tracks.updated();
    };
    auto pan = [&] {
        if (!QMetaObject::invokeMethod(map.get(), "pan", Q_ARG(double, 1), Q_ARG(double, 0)))
            qFatal("Map2D has no pan(dx, dy)");
        grow();
    };
    auto turn = [&] {
        map->setProperty("bearing", map->property("bearing").toDouble() + 1);
        grow();
    };
    // The world coastline is read on a worker thread: wait for it before timing.
    auto *coastline = map->findChild<QObject *>(QStringLiteral("coastline"));
    if (!coastline)
        qFatal("Map2D has no coastline item");
    auto coastRead = [&] {
        QElapsedTimer waited;
        waited.start();
        while ((coastline->property("loading").toBool() || coastline->property("resolution").toString().isEmpty())
               && waited.elapsed() < 20000)
            QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
        std::printf("  (coastline: %s resolution, %d shore points, read in %lld ms%s)\n",
                    qPrintable(coastline->property("resolution").toString()), coastline->property("pointCount").toInt(),
                    static_cast<long long>(waited.elapsed()), qPrintable(coastline->property("error").toString()));
    };
    // Warm up: the first frames upload the trails.
    neptus::test::measureFrames(window, smoke ? 2 : 30, pan);
    coastRead();
    std::printf("Map2D, 1280x800, software OpenGL (%s), 2 trails x %d points, no tiles (coastline and grid)\n",
                qPrintable(QString::fromLatin1(qgetenv("QT_QPA_PLATFORM"))), points);
    bool drew = true;
    auto print = [&](const char *what, const neptus::test::FrameTimes &r) {
        drew = drew && r.frames > 0;
        std::printf("%-52s p50 %6.2f ms  p99 %6.2f ms  max %6.2f ms  (%d frames)\n", what, r.p50, r.p99, r.max, r.frames);
    };
    if (!chartOnly) {
        print("both survey areas in view, panning, trails growing", neptus::test::measureFrames(window, frames, pan));
        print("both in view, rotating, trails growing", neptus::test::measureFrames(window, frames, turn));
        map->setProperty("bearing", 0);
        map->setProperty("zoomLevel", 17.0);
        print("zoomed in (zoom 17), panning, trails growing", neptus::test::measureFrames(window, frames, pan));
        map->setProperty("zoomLevel", 13.2);
        map->setProperty("showTrails", false);
        print("baseline: same map and panning, trails hidden", neptus::test::measureFrames(window, frames, pan));
        // The coastline's cost: the same map without it (the grid-only map it
        // replaced), and zoomed out over Iberia (intermediate resolution).
        map->setProperty("showCoastline", false);
        print("grid only (no coastline), panning, trails hidden", neptus::test::measureFrames(window, frames, pan));
        map->setProperty("zoomLevel", 6.0);
        print("zoom 6 (Iberia), grid only, panning", neptus::test::measureFrames(window, frames, pan));
        map->setProperty("showCoastline", true);
        coastRead();
        print("zoom 6 (Iberia), coastline, panning", neptus::test::measureFrames(window, frames, pan));
    }

    // Mission feature names placed clear of the systems (MapFeatureLayer.namePlaces): worked out
    // again at every move of a system; the time of one such placement with 30, 100 and 300 named
    // marks in view (the systems' cover moved a pixel each time).
    if (!chartOnly) {
        auto *layer = map->findChild<QQuickItem *>(QStringLiteral("missionMap"));
        if (!layer)
            qFatal("Map2D has no missionMap layer");
        for (const int count : {30, 100, 300}) {
            QVariantList features;
            for (int i = 0; i < count; ++i) {
                QVariant where;
                QMetaObject::invokeMethod(map.get(), "toCoordinate", Q_RETURN_ARG(QVariant, where), Q_ARG(double, (i * 37) % 1280),
                                          Q_ARG(double, (i * 53) % 800));
                const QVariantMap at = where.toMap();
                features.append(QVariantMap{{QStringLiteral("id"), QStringLiteral("f%1").arg(i)},
                                            {QStringLiteral("name"), QStringLiteral("Feature number %1").arg(i)},
                                            {QStringLiteral("kind"), QStringLiteral("mark")}, {QStringLiteral("role"), QString()},
                                            {QStringLiteral("layer"), QString()}, {QStringLiteral("color"), QString()},
                                            {QStringLiteral("lat"), at.value(QStringLiteral("lat"))},
                                            {QStringLiteral("lon"), at.value(QStringLiteral("lon"))},
                                            {QStringLiteral("points"), QVariantList()}, {QStringLiteral("outline"), QVariantList()}});
            }
            layer->setProperty("features", features);
            const int rounds = smoke ? 2 : 50;
            QElapsedTimer timer;
            timer.start();
            int placed = 0;
            for (int k = 0; k < rounds; ++k) {
                layer->setProperty("avoid", QVariantList{QRectF(600 + k, 380, 120, 40)});
                placed = int(layer->property("namePlaces").toList().size());
            }
            std::printf("%-52s %7.3f ms a placement  (%d names)\n",
                        qPrintable(QStringLiteral("names of %1 marks placed again (a system moved)").arg(count)),
                        double(timer.nsecsElapsed()) / 1e6 / rounds, placed);
        }
        layer->setProperty("features", QVariantList());
    }

    // A nautical chart (the NOAA cell of ../shared/fixtures/charts: depth areas, contours, symbols)
    // at harbour and approach zoom over Eastern Bay, next to grid only at the same place. This
    // machine's frame times drift by several ms from minute to minute, so the three cases take
    // turns, 60 frames at a time, five rounds, and each figure is of all its rounds' frames.
    const QString cell = test::sharedPath(QStringLiteral("fixtures/charts/US4MD81M"));
    if (!smoke && QFileInfo::exists(cell)) {
        map->setProperty("showCoastline", false);
        map->setProperty("showTrails", false);
        QMetaObject::invokeMethod(map.get(), "centreAt", Q_ARG(double, 38.8503), Q_ARG(double, -76.3129));
        auto *chart = map->findChild<QQuickItem *>(QStringLiteral("chart"));
        if (!chart)
            qFatal("Map2D has no chart item");
        map->setProperty("charts", cell);
        // Panning 60 pixels one way, then 60 back, so that the view stays on the chart.
        int swayed = 0;
        auto sway = [&] {
            if (!QMetaObject::invokeMethod(map.get(), "pan", Q_ARG(double, (swayed++ / 60) % 2 ? -1 : 1), Q_ARG(double, 0)))
                qFatal("Map2D has no pan(dx, dy)");
        };
        // Waits for the chart (read, areas painted), then draws its first frames (they upload it).
        auto settle = [&] {
            QElapsedTimer waited;
            waited.start();
            while ((chart->property("loading").toBool() || chart->property("cells").toStringList().isEmpty()
                    || chart->property("painting").toBool()) && waited.elapsed() < 60000)
                QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
            neptus::test::measureFrames(window, 10, sway);
            return waited.elapsed();
        };
        // The floor for anything that fills the view: an opaque image of the view's size, under
        // the grid, on the grid-only map (the chart hidden).
        QTemporaryDir scratch;
        QImage plain(1280, 800, QImage::Format_RGB32);
        plain.fill(QColor(0xd4, 0xe4, 0xf4));
        plain.save(scratch.filePath(QStringLiteral("plain.png")));
        QQmlComponent plainImage(&engine);
        plainImage.setData(QStringLiteral("import QtQuick\nImage { visible: false; source: \"%1\" }")
                               .arg(QUrl::fromLocalFile(scratch.filePath(QStringLiteral("plain.png"))).toString())
                               .toUtf8(),
                           QUrl());
        std::unique_ptr<QQuickItem> floor(qobject_cast<QQuickItem *>(plainImage.create()));
        if (!floor)
            qFatal("%s", qPrintable(plainImage.errorString()));
        floor->setParentItem(map.get());
        floor->stackBefore(map->childItems().constFirst());
        for (const auto &[zoom, name] : {std::pair{14.0, "harbour (zoom 14)"}, std::pair{11.5, "approach (zoom 11.5)"}}) {
            map->setProperty("zoomLevel", zoom);
            std::printf("  (chart read and its areas painted in %lld ms)\n", static_cast<long long>(settle()));
            std::vector<double> grid, drawn, symbols, image;
            const auto add = [](std::vector<double> &to, const std::vector<double> &frames) { to.insert(to.end(), frames.begin(), frames.end()); };
            for (int round = 0; round < 5; ++round) {
                chart->setVisible(false);
                neptus::test::measureFrames(window, 3, sway);
                add(grid, neptus::test::frameTimes(window, frames / 5, sway));
                floor->setVisible(true);
                neptus::test::measureFrames(window, 3, sway);
                add(image, neptus::test::frameTimes(window, frames / 5, sway));
                floor->setVisible(false);
                chart->setVisible(true);
                settle(); // (a pan of 300 pixels can leave the painted region)
                add(drawn, neptus::test::frameTimes(window, frames / 5, sway));
                // Where it goes: the painted image (areas and lines) apart from the symbols.
                chart->setProperty("imageShown", false);
                settle();
                add(symbols, neptus::test::frameTimes(window, frames / 5, sway));
                chart->setProperty("imageShown", true);
            }
            print(qPrintable(QStringLiteral("%1, grid only, panning").arg(QLatin1StringView(name))), neptus::test::summary(grid));
            print(qPrintable(QStringLiteral("%1, chart, panning").arg(QLatin1StringView(name))), neptus::test::summary(drawn));
            print(qPrintable(QStringLiteral("%1, chart's symbols alone").arg(QLatin1StringView(name))), neptus::test::summary(symbols));
            print(qPrintable(QStringLiteral("%1, an opaque image, no chart").arg(QLatin1StringView(name))), neptus::test::summary(image));
        }
    }
    if (!drew)
        std::fprintf(stderr, "bench_map: a run drew no frames\n");
    return drew ? 0 : 1;
}
