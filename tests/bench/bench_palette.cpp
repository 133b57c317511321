// How long a component dropped into a watched directory takes to be in the
// designer's palette (ready to place), and an edited one to be recompiled:
// the issue asks for "within a second". A ComponentPalette on a QML engine
// watches a temporary directory; each round writes a new component (and then
// edits it) and waits for the palette to list it. Prints p50 / p99 / max.
// Run: tools/bench palette
#include "ComponentPalette.h"

#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QGuiApplication>
#include <QQmlEngine>
#include <QTemporaryDir>
#include <QTimer>
#include <QtQml/qqmlextensionplugin.h>

#include <algorithm>
#include <cstdio>
#include <vector>

Q_IMPORT_QML_PLUGIN(Neptus_EnginePlugin)
Q_IMPORT_QML_PLUGIN(Neptus_ComponentsPlugin)

namespace {

void write(const QString &path, const QByteArray &text)
{
    QFile file(path);
    if (file.open(QIODevice::WriteOnly))
        file.write(text);
}

// Milliseconds until `done` holds, polled as the event loop runs; -1 after 10 s.
template<class Done>
double waitFor(Done done)
{
    QElapsedTimer timer;
    timer.start();
    QEventLoop loop;
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, &loop, [&] {
        if (done() || timer.elapsed() > 10000)
            loop.quit();
    });
    poll.start(1);
    loop.exec();
    return done() ? timer.nsecsElapsed() / 1e6 : -1;
}

void report(const char *what, std::vector<double> ms)
{
    std::sort(ms.begin(), ms.end());
    const bool lost = !ms.empty() && ms.front() < 0;
    std::printf("%-40s p50 %6.1f ms  p99 %6.1f ms  max %6.1f ms  (n=%zu)%s\n", what, ms[ms.size() / 2],
                ms[ms.size() * 99 / 100], ms.back(), ms.size(), lost ? "  SOME NEVER CAME" : "");
}

} // namespace

int main(int argc, char **argv)
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QGuiApplication app(argc, argv);
    QQmlEngine engine;
    QTemporaryDir directory;
    ComponentPalette palette;
    palette.setDirectories({directory.path()});
    palette.setEngine(&engine);

    const int rounds = 50;
    std::vector<double> added, edited;
    for (int i = 0; i < rounds; ++i) {
        const QString name = QStringLiteral("Gauge%1").arg(i);
        const QString file = directory.filePath(name + QStringLiteral(".qml"));
        write(file, "import QtQuick\nRectangle {\n    property string path: \"\"\n    color: \"#336699\"\n}\n");
        added.push_back(waitFor([&] { return palette.entry(name).value(QStringLiteral("status")).toString() == QStringLiteral("ready"); }));
        const int revision = palette.revision();
        write(file, "import QtQuick\nRectangle {\n    property string path: \"\"\n    color: \"#aa0000\"\n}\n");
        edited.push_back(waitFor([&] { return palette.revision() > revision; }));
    }
    std::printf("Drop-in components, %d rounds, a directory that grows to %d components\n", rounds, rounds);
    report("new file -> in the palette", added);
    report("edited file -> recompiled (revision)", edited);
    return 0;
}
