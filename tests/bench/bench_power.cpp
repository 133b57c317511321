// What the console costs a tablet's battery (issue "speed where users feel
// it"): the console program with the default console at 1280x800 on the
// software renderer (llvmpipe, as here under Xvfb) while N simulated
// vehicles stream their state at 10 Hz over IMC, as tools/run shows it. After
// 10 s to settle it counts, over SECONDS, the CPU the process used (per
// thread: the rasteriser threads, the render thread, the GUI thread, the
// rest) and the frames it drew (the scene graph's own timing log).
//
//   bench_power [SECONDS=30] [--vehicles N=2] [--display-rate HZ] [--resting-rate HZ] [--idle]
//   bench_power --startup [--starts N=5] [--vehicles N=2]
//
// Nobody touches the console here, so it rests (20 s after start) and shows
// vehicles at its resting rate: the figure is a tablet on a boat nobody
// touches. `--resting-rate 0` is a console in use (the display rate).
// --idle: no vehicles at all (goal: no frames).
// --startup: how long the console takes from its start until its window is on
// screen, and until the console layout is drawn in it (the console's own
// startup steps, QT_LOGGING_RULES=neptus.startup=true), where that time goes,
// and its resident memory then and 10 s later, over N starts (goal: ≤ 0.5 s,
// ≤ 200 MB).
#include "Paths.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <unistd.h>

#include <cstdio>
#include <algorithm>
#include <map>
#include <memory>
#include <vector>

using namespace Qt::StringLiterals;

namespace {

constexpr quint16 firstVehiclePort = 17600, consolePort = 17690;

// CPU clock ticks of each of a process's threads, by thread name.
std::map<QString, qint64> ticksByThread(qint64 pid)
{
    std::map<QString, qint64> ticks;
    for (const QString &task : QDir(u"/proc/%1/task"_s.arg(pid)).entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
        QFile stat(u"/proc/%1/task/%2/stat"_s.arg(pid).arg(task));
        if (!stat.open(QIODevice::ReadOnly))
            continue;
        const QByteArray text = stat.readAll();
        const qsizetype open = text.indexOf('('), close = text.lastIndexOf(')');
        const QString name = QString::fromUtf8(text.mid(open + 1, close - open - 1));
        const QList<QByteArray> fields = text.mid(close + 2).split(' ');
        ticks[name] += fields.value(11).toLongLong() + fields.value(12).toLongLong();
    }
    return ticks;
}

// A process's resident memory, in MB: all of it (VmRSS), or its anonymous
// part (RssAnon: heap, stacks, GL buffers) or its files' (RssFile: libraries).
double residentMegabytes(qint64 pid, const QByteArray &which = "VmRSS")
{
    QFile status(u"/proc/%1/status"_s.arg(pid));
    if (!status.open(QIODevice::ReadOnly))
        return 0;
    for (const QByteArray &line : status.readAll().split('\n'))
        if (line.startsWith(which + ':'))
            return line.mid(which.size() + 1).trimmed().split(' ').value(0).toDouble() / 1024;
    return 0;
}

QString groupOf(const QString &thread)
{
    if (thread.startsWith(u"llvmpipe"))
        return u"rasteriser threads (llvmpipe)"_s;
    if (thread == u"QSGRenderThread")
        return u"render thread"_s;
    if (thread == u"neptus")
        return u"GUI thread"_s;
    return u"the rest (links, recorder, scripts, …)"_s;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    const bool idle = args.contains(u"--idle"_s);
    const auto option = [&](const QString &name, const QString &fallback) {
        const qsizetype i = args.indexOf(name);
        return i > 0 && i + 1 < args.size() ? args[i + 1] : fallback;
    };
    const int vehicles = idle ? 0 : option(u"--vehicles"_s, u"2"_s).toInt();
    const QString displayRate = option(u"--display-rate"_s, QString());
    const QString restingRate = option(u"--resting-rate"_s, QString());
    const bool rests = restingRate.isEmpty() || restingRate.toDouble() > 0;
    double seconds = 30;
    for (qsizetype i = 1; i < args.size(); ++i)
        if (bool ok = false; !args[i - 1].startsWith(u"--") && (args[i].toDouble(&ok), ok))
            seconds = args[i].toDouble();
    const QString bin = QCoreApplication::applicationDirPath();

    // Each vehicle in a process of its own, as tools/run starts them: their
    // messages come out of step, as real vehicles' do.
    QTemporaryDir dir;
    std::vector<std::unique_ptr<QProcess>> sims;
    for (int i = 0; i < vehicles; ++i) {
        QFile scenario(dir.filePath(u"vehicle-%1.json"_s.arg(i)));
        const QString text = u"{\"vehicles\": [{\"id\": %1, \"name\": \"power-%2\", \"kind\": \"%3\", \"port\": %4, "
                             u"\"lat\": 41.1855, \"lon\": -8.7060, \"phase\": %5}]}"_s
                                 .arg(90 + i).arg(i + 1).arg(i % 2 ? u"asv"_s : u"auv"_s).arg(firstVehiclePort + i).arg(i * 360 / vehicles);
        if (!scenario.open(QIODevice::WriteOnly) || scenario.write(text.toUtf8()) < 0)
            return 1;
        scenario.close();
        auto &sim = sims.emplace_back(std::make_unique<QProcess>());
        sim->setProcessChannelMode(QProcess::ForwardedErrorChannel);
        sim->start(bin + u"/neptus-sim"_s, {u"--scenario"_s, scenario.fileName()});
        QTest::qWait(37); // out of step with the others (10 Hz: 100 ms a step)
    }
    QStringList arguments{u"--console"_s, neptus::test::sourcePath(u"qml/consoles/Default.qml"_s), u"--size"_s, u"1280x800"_s,
                          u"--no-record"_s, u"--dds-domain"_s, u"-1"_s, u"--imc-port"_s, QString::number(consolePort),
                          u"--imc-discovery"_s, u"off"_s, u"--log-dir"_s, dir.filePath(u"logs"_s)};
    for (int i = 0; i < vehicles; ++i)
        arguments << u"--imc-peer"_s << u"127.0.0.1:%1"_s.arg(firstVehiclePort + i);
    if (vehicles > 0)
        arguments << u"--system"_s << u"power-1"_s;
    if (!displayRate.isEmpty())
        arguments << u"--display-rate"_s << displayRate;
    if (!restingRate.isEmpty())
        arguments << u"--resting-rate"_s << restingRate;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(u"QT_LOGGING_RULES"_s, u"qt.scenegraph.time.renderloop=true"_s); // a line for every frame drawn
    if (args.contains(u"--startup"_s)) {
        // The console says each step of its start (neptus.startup: milliseconds since its
        // main() began); the steps' medians show where the time goes.
        QProcessEnvironment startupEnv = env;
        startupEnv.insert(u"QT_LOGGING_RULES"_s, u"neptus.startup=true"_s);
        startupEnv.insert(u"QT_MESSAGE_PATTERN"_s, u"%{category}: %{message}"_s);
        const int starts = std::max(1, option(u"--starts"_s, u"5"_s).toInt());
        std::vector<double> toFrame, toConsole, rssAtConsole, rssLater;
        std::vector<QString> stepNames;
        std::map<QString, std::vector<double>> steps;
        for (int n = 0; n < starts; ++n) {
            QProcess console;
            console.setProcessEnvironment(startupEnv);
            QElapsedTimer clock;
            double firstFrame = -1, consoleShown = -1, sinceMain = -1;
            QByteArray pending;
            QObject::connect(&console, &QProcess::readyReadStandardError, [&] {
                pending += console.readAllStandardError();
                for (qsizetype end; (end = pending.indexOf('\n')) >= 0; pending.remove(0, end + 1)) {
                    const QString line = QString::fromUtf8(pending.left(end));
                    static const QString prefix = u"neptus.startup: "_s;
                    if (!line.startsWith(prefix))
                        continue;
                    const qsizetype cut = line.indexOf(u" ms: "_s);
                    const double ms = line.mid(prefix.size(), cut - prefix.size()).toDouble();
                    const QString step = line.mid(cut + 5);
                    if (!steps.contains(step))
                        stepNames.push_back(step);
                    steps[step].push_back(ms);
                    const double now = double(clock.nsecsElapsed()) / 1e6;
                    if (step == u"application"_s)
                        sinceMain = now - ms; // what passed before main(): loading the libraries
                    if (step == u"first frame on screen"_s)
                        firstFrame = now;
                    if (step == u"console on screen"_s) {
                        consoleShown = now;
                        rssAtConsole.push_back(residentMegabytes(console.processId()));
                    }
                }
            });
            clock.start();
            console.start(bin + u"/neptus"_s, arguments);
            if (!QTest::qWaitFor([&] { return consoleShown >= 0; }, 30000)) {
                std::fprintf(stderr, "bench_power: the console was not on screen within 30 s\n");
                return 1;
            }
            steps[u"(before main: the program and its libraries loaded)"_s].push_back(sinceMain);
            toFrame.push_back(firstFrame);
            toConsole.push_back(consoleShown);
            QTest::qWait(10000);
            rssLater.push_back(residentMegabytes(console.processId()));
            const double anonymous = residentMegabytes(console.processId(), "RssAnon"), files = residentMegabytes(console.processId(), "RssFile");
            console.terminate();
            console.waitForFinished(5000);
            std::printf("  start %d: window on screen after %.0f ms, the console in it after %.0f ms; RSS %.1f MB then, %.1f MB 10 s later (%.1f anonymous, %.1f files)\n",
                        n + 1, firstFrame, consoleShown, rssAtConsole.back(), rssLater.back(), anonymous, files);
        }
        const auto median = [](std::vector<double> v) { std::ranges::sort(v); return v[v.size() / 2]; };
        std::printf("  where a start goes (medians; milliseconds since main() began, the first row before it):\n");
        std::printf("    %-52s %6.0f ms\n", "before main (the program and its libraries loaded)",
                    median(steps[u"(before main: the program and its libraries loaded)"_s]));
        for (const QString &step : stepNames)
            std::printf("    %-52s %6.0f ms\n", qPrintable(step), median(steps[step]));
        std::printf("bench_power --startup: the default console at 1280x800 (software OpenGL), %d simulated vehicle%s, %d starts: "
                    "window on screen after %.0f ms, the console in it after %.0f ms (medians; %.0f–%.0f), "
                    "RSS %.1f MB then and %.1f MB 10 s later (medians)\n",
                    vehicles, vehicles == 1 ? "" : "s", starts, median(toFrame), median(toConsole), *std::ranges::min_element(toConsole),
                    *std::ranges::max_element(toConsole), median(rssAtConsole), median(rssLater));
        for (auto &sim : sims)
            sim->terminate();
        for (auto &sim : sims)
            sim->waitForFinished(5000);
        return 0;
    }
    QProcess console;
    console.setProcessEnvironment(env);
    qint64 frames = 0;
    bool counting = false;
    QObject::connect(&console, &QProcess::readyReadStandardError, [&] {
        const QByteArray text = console.readAllStandardError();
        if (counting)
            frames += text.count("frame rendered in");
    });
    console.start(bin + u"/neptus"_s, arguments);
    if (!console.waitForStarted(5000) || std::any_of(sims.begin(), sims.end(), [](auto &p) { return !p->waitForStarted(5000); })) {
        std::fprintf(stderr, "bench_power: cannot start neptus or neptus-sim\n");
        return 1;
    }
    // Started, vehicles heard, first frames drawn; resting (20 s without input) when it rests.
    QTest::qWait(rests ? 22000 : 10000);
    const auto before = ticksByThread(console.processId());
    counting = true;
    QElapsedTimer clock;
    clock.start();
    QTest::qWait(int(seconds * 1000));
    const auto after = ticksByThread(console.processId());
    const double elapsed = clock.elapsed() / 1000.0;
    counting = false;
    const double rss = residentMegabytes(console.processId());

    std::map<QString, double> groups;
    double total = 0;
    const double tick = double(sysconf(_SC_CLK_TCK));
    for (const auto &[thread, t] : after) {
        const auto was = before.find(thread);
        const double used = double(t - (was == before.end() ? 0 : was->second)) / tick;
        groups[groupOf(thread)] += used;
        total += used;
    }
    std::printf("bench_power: the default console at 1280x800 (software OpenGL), %d simulated vehicle%s at 10 Hz over IMC, "
                "display rate %s, %s, %.0f s\n",
                vehicles, vehicles == 1 ? "" : "s", displayRate.isEmpty() ? "default" : qPrintable(displayRate),
                rests ? qPrintable(u"resting (rate %1)"_s.arg(restingRate.isEmpty() ? u"default"_s : restingRate)) : "in use",
                elapsed);
    std::printf("  CPU: %.1f %% of one core; %.1f frames a second; RSS %.1f MB\n", 100 * total / elapsed, double(frames) / elapsed, rss);
    for (const auto &[group, used] : groups)
        std::printf("    %-40s %5.1f %%\n", qPrintable(group), 100 * used / elapsed);
    console.terminate();
    console.waitForFinished(5000);
    for (auto &sim : sims)
        sim->terminate();
    for (auto &sim : sims)
        sim->waitForFinished(5000);
    return 0;
}
