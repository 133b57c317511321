// The plan editor on software OpenGL (Mesa llvmpipe under Xvfb), 1280×800:
// a 1,000-maneuver plan drawn on Map2D. Frame times (p50 / p99) while a
// marker is dragged (its item moves a pixel a frame, as the DragHandler
// moves it) and while the map pans, against the same map with the editor
// closed; and what a drop costs (the model moved, checked, and every marker
// and leg drawn again). Issue "Drawing the environment and planning on the
// map". Run: tools/bench editor [--drops N] [--shot FILE]
#include "FrameTimes.h"
#include "qmlmodels/ConsoleSession.h"
#include "Schemas.h"

#include <QElapsedTimer>
#include <QFile>
#include <QGuiApplication>
#include <QQmlEngine>
#include <QQuickItem>
#include <QQuickWindow>
#include <QTemporaryDir>
#include <QTimer>
#include <QEventLoop>
#include <QtQml/qqmlextensionplugin.h>

#include <algorithm>
#include <cstdio>
#include <ctime>

Q_IMPORT_QML_PLUGIN(Neptus_EnginePlugin)
Q_IMPORT_QML_PLUGIN(Neptus_ComponentsPlugin)

using namespace neptus;

namespace {

// 1,000 Gotos in a 25 × 40 grid 20 m apart (a lawn-mower by waypoints), in an operating area.
QByteArray bigPlan(int count)
{
    QByteArray xml = R"(<?xml version="1.0" encoding="UTF-8"?>
<mission format="1" id="big" name="Editor benchmark"><home lat="41.1405" lon="-8.6110" height="0"/><vehicle id="lauv-sim-1"/>
<map id="m"><polygon id="ops" role="operating-area"><point lat="41.135" lon="-8.620"/><point lat="41.150" lon="-8.620"/>
<point lat="41.150" lon="-8.600"/><point lat="41.135" lon="-8.600"/></polygon></map>
<plan id="big" vehicle="lauv-sim-1" start="m0"><maneuvers>
)";
    for (int i = 0; i < count; ++i) {
        const int row = i / 40, col = row % 2 ? 39 - i % 40 : i % 40;
        xml += "<Goto id=\"m" + QByteArray::number(i) + "\" lat=\"" + QByteArray::number(41.1390 + col * 0.00018, 'f', 6)
               + "\" lon=\"" + QByteArray::number(-8.6150 + row * 0.00024, 'f', 6)
               + "\" z=\"2\" z_units=\"DEPTH\" speed=\"1.5\" speed_units=\"METERS_PS\"/>\n";
    }
    xml += "</maneuvers>\n";
    for (int i = 1; i < count; ++i)
        xml += "<transition from=\"m" + QByteArray::number(i - 1) + "\" to=\"m" + QByteArray::number(i) + "\"/>\n";
    xml += "</plan></mission>\n";
    return xml;
}

bool waitFor(const std::function<bool()> &done, int ms)
{
    QElapsedTimer t;
    t.start();
    while (!done() && t.elapsed() < ms)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    return done();
}

} // namespace

int main(int argc, char **argv)
{
    QGuiApplication app(argc, argv);
    const bool smoke = app.arguments().contains(QStringLiteral("--smoke"));
    const int frames = smoke ? 5 : 200, count = smoke ? 50 : 1000;

    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("big.xml"));
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(bigPlan(count)) < 0)
        return 1;
    file.close();
    ConsoleSession session(test::shippedSchema());
    if (const QString why = session.plansModel()->openMission(path); !why.isEmpty()) {
        std::fprintf(stderr, "bench_editor: %s\n", qPrintable(why));
        return 1;
    }

    QQmlEngine engine;
    engine.singletonInstance<QObject *>("Neptus.Components", "Session")->setProperty("session", QVariant::fromValue(&session));
    QQuickWindow window;
    const auto map = neptus::test::showInWindow(engine, window, "import QtQuick\nimport Neptus.Components\n"
        "Map2D { width: 1280; height: 800; initialZoomLevel: 16; follow: \"\"; showCoastline: false }");
    if (!map)
        return 1;
    QMetaObject::invokeMethod(map.get(), "centreAt", Q_ARG(double, 41.1425), Q_ARG(double, -8.6100));

    auto pan = [&] { QMetaObject::invokeMethod(map.get(), "pan", Q_ARG(double, 1), Q_ARG(double, 0)); };
    std::printf("Map2D 1280x800, software OpenGL (%s), plan of %d maneuvers\n", qgetenv("QT_QPA_PLATFORM").constData(), count);
    auto print = [](const char *what, const neptus::test::FrameTimes &r) {
        std::printf("%-48s p50 %6.2f ms  p99 %6.2f ms  max %6.2f ms  (%d frames)\n", what, r.p50, r.p99, r.max, r.frames);
    };
    neptus::test::measureFrames(window, smoke ? 2 : 20, pan);
    print("editor closed, panning", neptus::test::measureFrames(window, frames, pan));

    map->setProperty("editingPlan", true);
    QObject *model = nullptr;
    QElapsedTimer opened;
    opened.start();
    if (!waitFor([&] {
            model = map->findChild<QObject *>(QStringLiteral("planEditorModel"));
            return model && model->property("maneuvers").toList().size() == count;
        }, 20000)) {
        std::fprintf(stderr, "bench_editor: the editor did not open the plan\n");
        return 1;
    }
    std::printf("  (editor opened with %d markers in %lld ms)\n", count, static_cast<long long>(opened.elapsed()));
    neptus::test::measureFrames(window, smoke ? 2 : 20, pan);
    print("editor open, panning", neptus::test::measureFrames(window, frames, pan));
    // Where an open editor's frame goes: the same without its panel, without the plan.
    for (const char *part : {"planEditorPanel", "planOverlay"}) {
        QQuickItem *item = map->findChild<QQuickItem *>(QString::fromLatin1(part));
        if (!item)
            continue;
        item->setVisible(false);
        neptus::test::measureFrames(window, 2, pan);
        print(qPrintable(QStringLiteral("  (the same without %1)").arg(QString::fromLatin1(part))),
              neptus::test::measureFrames(window, frames / 2, pan));
        item->setVisible(true);
    }

    // The middle maneuver, selected (a big plan has dots, and a draggable
    // marker for the selected maneuver), and its marker.
    QObject *planEditor = map->property("planEditor").value<QObject *>();
    if (!planEditor)
        return 1;
    planEditor->setProperty("selected", QStringLiteral("m%1").arg(count / 2));
    neptus::test::measureFrames(window, 2, [] {});
    QQuickItem *marker = nullptr;
    const QString wanted = QStringLiteral("maneuver:m%1").arg(count / 2);
    std::function<void(QQuickItem *)> look = [&](QQuickItem *item) {
        if (item->objectName() == wanted)
            marker = item;
        for (QQuickItem *child : item->childItems())
            look(child);
    };
    look(map.get());
    if (!marker) {
        std::fprintf(stderr, "bench_editor: no marker %s\n", qPrintable(wanted));
        return 1;
    }
    print("editor open, dragging a marker", neptus::test::measureFrames(window, frames, [&] { marker->setX(marker->x() + 1); }));

    // (--shot FILE: the window as it is now, the editor open with a maneuver selected.)
    if (const int shot = int(app.arguments().indexOf(QStringLiteral("--shot"))); shot > 0 && shot + 1 < app.arguments().size()) {
        QMetaObject::invokeMethod(map.get(), "centreAt", Q_ARG(double, 41.1425), Q_ARG(double, -8.6130));
        neptus::test::nextFrame(window);
        window.grabWindow().save(app.arguments()[shot + 1]);
    }

    // Nothing changing, nothing drawn (frames in a second with the editor open and idle).
    {
        neptus::test::nextFrame(window);
        int idle = 0;
        auto counting = QObject::connect(&window, &QQuickWindow::frameSwapped, &window, [&] { ++idle; });
        QEventLoop loop;
        QTimer::singleShot(1000, &loop, &QEventLoop::quit);
        loop.exec();
        QObject::disconnect(counting);
        std::printf("%-48s %d\n", "  (frames drawn in an idle second)", idle);
    }

    // A drop: the model moved and checked, then the frame that shows it
    // (its leg, its marker, the problems and statistics) on screen.
    // (Of which the model and the QML bound to it: the move's call itself.)
    std::vector<double> drops, calls, cpu;
    const auto threadCpuMs = [] {
        timespec t{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
        return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
    };
    // (--drops N: more of them, to profile.)
    const int dropArg = int(app.arguments().indexOf(QStringLiteral("--drops")));
    const int dropCount = dropArg > 0 && dropArg + 1 < app.arguments().size() ? app.arguments()[dropArg + 1].toInt() : smoke ? 2 : 10;
    for (int i = 0; i < dropCount; ++i) {
        neptus::test::nextFrame(window); // nothing else under way
        QElapsedTimer t;
        t.start();
        const double cpuBefore = threadCpuMs();
        QMetaObject::invokeMethod(model, "moveManeuver", Q_ARG(QString, QStringLiteral("m%1").arg(count / 2)),
                                  Q_ARG(double, 41.1430 + i * 1e-5), Q_ARG(double, -8.6100));
        calls.push_back(double(t.nsecsElapsed()) / 1e6);
        cpu.push_back(threadCpuMs() - cpuBefore);
        neptus::test::nextFrame(window);
        drops.push_back(double(t.nsecsElapsed()) / 1e6);
    }
    if (qEnvironmentVariableIsSet("NEPTUS_BENCH_EACH")) {
        for (size_t i = 0; i < drops.size(); ++i)
            std::printf("  drop %zu: %.1f ms, call %.1f ms, cpu %.1f ms\n", i, drops[i], calls[i], cpu[i]);
    }
    std::sort(drops.begin(), drops.end());
    std::sort(calls.begin(), calls.end());
    std::sort(cpu.begin(), cpu.end());
    std::printf("%-48s median %6.1f ms  max %6.1f ms  (%zu drops)\n", "a drop (move, check, its frame on screen)", drops[drops.size() / 2],
                drops.back(), drops.size());
    std::printf("%-48s median %6.1f ms  max %6.1f ms\n", "  (of which the model and its bindings)", calls[calls.size() / 2], calls.back());
    std::printf("%-48s median %6.1f ms  max %6.1f ms\n", "  (the same, CPU time of the GUI thread)", cpu[cpu.size() / 2], cpu.back());
    return 0;
}
