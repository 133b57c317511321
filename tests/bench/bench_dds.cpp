// DDS benchmarks of the Neptus-Qt envelope path, each beside ddsperf in the
// same run on the same loopback configuration (dds/loopback.xml), taking
// turns with it several times so that both meet the same moods of the machine:
//   1. round trip: a pong process (this program, --pong) echoes LogBookEntry
//      envelopes; compared with `ddsperf ping` / `ddsperf pong`. ddsperf
//      prints a percentile line a second, so ours is cut into one-second
//      windows too; both report the median window. ddsperf prints HALF of
//      each round trip (ddsperf.c, process_pong: (now - sent) / 2), so its
//      figures are doubled here, and the run shows that they must be;
//   2. throughput: a publisher process (--pub) writes as fast as it can, this
//      process counts what arrives; compared with `ddsperf pub` / `ddsperf sub`;
//   3. end to end: a publisher process (--paced) stamps LogBookEntry.htime
//      with the monotonic clock, this process ingests into a variable tree
//      and watches a QML `Variable` bound to that field: publish → value
//      visible in QML, frames included.
// Both sides receive as the console does: on Cyclone's threads, straight
// into a thread-safe consumer (DdsTransport::setDirectReceiver).
// Run: tools/bench dds [--only roundtrip|throughput|qml]
#include "core/DataFiles.h"
#include "transport/dds/DdsTransport.h"
#include "Schemas.h"
#include "qmlmodels/Variable.h"
#include "qmlmodels/VariableTreeModel.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QProcess>
#include <QQmlComponent>
#include <QQmlEngine>
#include <QRegularExpression>
#include <QThread>
#include <QTimer>
#include <QtQml/qqmlextensionplugin.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <utility>

Q_IMPORT_QML_PLUGIN(Neptus_EnginePlugin)

using namespace neptus;
using Steady = std::chrono::steady_clock;
using namespace std::chrono_literals;

namespace {

constexpr dds_domainid_t benchDomain = 9;
constexpr quint16 pinger = 0x4001, ponger = 0x4002, publisher = 0x4003, pacer = 0x4004;
constexpr int pacedSamples = 400;
// Ours and ddsperf's take turns; round trips are short and noisy, so more of them.
constexpr int roundTripTurns = 5, throughputTurns = 3;

transport::DdsConfig configFor(quint16 system)
{
    transport::DdsConfig config;
    config.domain = benchDomain;
    config.systemId = system;
    return config;
}

double monotonicSeconds()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

msg::Message entryOfSize(int packetBytes)
{
    msg::Message m(test::shippedSchema()->byAbbrev(u"LogBookEntry"));
    m.setBytes(m.def()->indexOf(u"text"), QByteArray(std::max(0, packetBytes - 22 - 9 - 4), 'x'));
    return m;
}

struct Figures
{
    double p50 = 0, p99 = 0;
    int count = 0;
};

Figures percentiles(std::vector<double> values)
{
    if (values.empty())
        return {};
    std::sort(values.begin(), values.end());
    return {values[values.size() / 2], values[values.size() * 99 / 100], static_cast<int>(values.size())};
}

double median(std::vector<double> values)
{
    return percentiles(std::move(values)).p50;
}

// Round-trip percentiles per one-second window, as ddsperf prints them.
struct Windows
{
    std::vector<double> p50, p99;
    void add(const Figures &f)
    {
        p50.push_back(f.p50);
        p99.push_back(f.p99);
    }
    void add(const Windows &w)
    {
        p50.insert(p50.end(), w.p50.begin(), w.p50.end());
        p99.insert(p99.end(), w.p99.begin(), w.p99.end());
    }
};

// Child processes. ------------------------------------------------------------

int pong()
{
    transport::DdsTransport dds(test::shippedSchema(), configFor(ponger));
    dds.setDirectReceiver([&dds](const msg::Message &m, qsizetype) {
        if (m.header.src == pinger)
            dds.broadcast(m);
    });
    if (!dds.start())
        return 1;
    QThread::sleep(std::chrono::seconds(120)); // killed by the parent
    return 0;
}

int publishFlat(int packetBytes, int seconds)
{
    transport::DdsTransport dds(test::shippedSchema(), configFor(publisher));
    if (!dds.start())
        return 1;
    const std::vector<msg::Message> burst(100, entryOfSize(packetBytes));
    QElapsedTimer timer;
    timer.start();
    while (timer.elapsed() < seconds * 1000)
        dds.broadcast(burst); // one datagram per packet's worth, as ddsperf's batching does
    return 0;
}

int publishPaced()
{
    transport::DdsTransport dds(test::shippedSchema(), configFor(pacer));
    if (!dds.start())
        return 1;
    msg::Message entry = entryOfSize(64);
    const int htime = entry.def()->indexOf(u"htime");
    QThread::msleep(1000); // until discovered
    for (int i = 0; i < pacedSamples; ++i) {
        entry.setNumber(htime, monotonicSeconds());
        dds.broadcast(entry);
        QThread::msleep(27); // not a multiple of the 16 ms frame: samples land all over it
    }
    return 0;
}

// The parent's measurements. --------------------------------------------------

QProcess *startChild(const QStringList &arguments)
{
    auto *child = new QProcess;
    child->setProcessChannelMode(QProcess::ForwardedErrorChannel);
    child->start(QCoreApplication::applicationFilePath(), arguments);
    if (!child->waitForStarted(5000))
        std::fprintf(stderr, "cannot start %s\n", qPrintable(arguments.join(u' ')));
    return child;
}

void stopChild(QProcess *child)
{
    if (child->state() != QProcess::NotRunning) {
        child->kill();
        child->waitForFinished(5000);
    }
    delete child;
}

// What the parent's transport receives, on Cyclone's threads. Pings go out
// from the thread an echo arrives on, as ddsperf's do: the figure is the
// transport's, not a sleeping thread's wake-up.
struct Receiver
{
    transport::DdsTransport *dds = nullptr;
    tree::VariableTree *tree = nullptr;
    std::atomic<quint64> flat{0};

    std::mutex mutex;
    std::condition_variable done;
    msg::Message ping;
    bool pinging = false;
    Steady::time_point deadline, sent;
    std::vector<double> micros;
    std::vector<Steady::time_point> arrived; // when each echo came back

    void operator()(const msg::Message &m)
    {
        switch (m.header.src) {
        case ponger:
            echoed();
            break;
        case publisher:
            flat.fetch_add(1, std::memory_order_relaxed);
            break;
        case pacer:
            tree->ingest(m);
            break;
        default:
            break;
        }
    }

    void echoed()
    {
        const auto now = Steady::now();
        std::lock_guard lock(mutex);
        if (!pinging)
            return;
        micros.push_back(std::chrono::duration<double, std::micro>(now - sent).count());
        arrived.push_back(now);
        if (now >= deadline) {
            pinging = false;
            done.notify_one();
            return;
        }
        sent = Steady::now();
        dds->broadcast(ping);
    }

    // Pings one after the other until `duration` has passed (at least one
    // round); false if an echo stays away for a second.
    bool pingFor(const msg::Message &message, Steady::duration duration)
    {
        std::unique_lock lock(mutex);
        ping = message;
        micros.clear();
        arrived.clear();
        pinging = true;
        sent = Steady::now();
        deadline = sent + duration;
        dds->broadcast(ping);
        for (;;) {
            const std::size_t before = micros.size();
            if (done.wait_for(lock, 1s, [&] { return !pinging; }))
                return true;
            if (micros.size() == before) {
                pinging = false;
                return false;
            }
        }
    }

    // The round trips of the last pingFor, one-second window by window; a
    // last, partial window is left out.
    Windows windows() const
    {
        Windows w;
        std::vector<double> window;
        Steady::time_point start = arrived.empty() ? Steady::time_point() : arrived.front();
        for (std::size_t i = 0; i < micros.size(); ++i) {
            if (arrived[i] - start >= 1s) {
                w.add(percentiles(window));
                window.clear();
                while (arrived[i] - start >= 1s)
                    start += 1s;
            }
            window.push_back(micros[i]);
        }
        return w;
    }
};

// Three one-second windows of round trips (and a little: the first window
// starts at the first echo), after the pong has matched our writer and we its.
Windows roundTrip(Receiver &receiver, int packetBytes)
{
    const msg::Message entry = entryOfSize(packetBytes);
    QElapsedTimer waited;
    waited.start();
    bool matched = false;
    while (!matched && waited.elapsed() < 15000)
        matched = receiver.pingFor(entry, 0s);
    if (!matched || !receiver.pingFor(entry, 3100ms))
        return {};
    return receiver.windows();
}

// Samples per second arriving from a --pub process, over 3 s once it streams.
double throughput(Receiver &receiver, int packetBytes)
{
    receiver.flat = 0;
    QProcess *child = startChild({QStringLiteral("--pub"), QString::number(packetBytes), QStringLiteral("6")});
    QElapsedTimer waited;
    waited.start();
    while (receiver.flat == 0 && waited.elapsed() < 10000)
        QThread::msleep(10);
    QThread::msleep(1000);
    const quint64 first = receiver.flat;
    QElapsedTimer window;
    window.start();
    QThread::msleep(3000);
    const quint64 last = receiver.flat;
    const double rate = (last - first) / (window.nsecsElapsed() / 1e9);
    child->waitForFinished(15000);
    stopChild(child);
    return rate;
}

// ddsperf on domain 8 with the project's loopback configuration.
void startDdsperf(QProcess &process, const QStringList &arguments)
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("CYCLONEDDS_URI"), QStringLiteral("file://") + dataPath(QStringLiteral("dds/loopback.xml")));
    process.setProcessEnvironment(env);
    process.start(QStringLiteral("ddsperf"), QStringList{QStringLiteral("-i"), QStringLiteral("8")} + arguments);
}

// ddsperf's round trips, doubled: it prints half of each. `halfShare` gets,
// per line, its printed mean times its round trips in that second: the share
// of each second its printed figures account for. Pings go one after the
// other, so about 1 means it prints whole round trips and under 0.5 halves.
Windows ddsperfRoundTrip(int packetBytes, std::vector<double> &halfShare)
{
    QProcess pongProcess, pingProcess;
    startDdsperf(pongProcess, {QStringLiteral("-D"), QStringLiteral("10"), QStringLiteral("pong")});
    startDdsperf(pingProcess, {QStringLiteral("-D"), QStringLiteral("5"), QStringLiteral("-Qminmatch:1"), QStringLiteral("-Qinitwait:5"),
                               QStringLiteral("ping"), QStringLiteral("size"), QString::number(packetBytes)});
    pingProcess.waitForFinished(20000);
    pongProcess.kill();
    pongProcess.waitForFinished(5000);
    const QString output = QString::fromUtf8(pingProcess.readAllStandardOutput());
    // "... size 64 mean 29.7us min 11.5us 50% 26.3us 90% 33.3us 99% 83.9us max ... cnt 16699", a line a second.
    static const QRegularExpression line(
        QStringLiteral(R"(mean ([\d.]+)us min [\d.]+us 50% ([\d.]+)us 90% [\d.]+us 99% ([\d.]+)us .* cnt (\d+))"));
    Windows w;
    bool first = true;
    for (auto it = line.globalMatch(output); it.hasNext();) {
        const auto m = it.next();
        if (std::exchange(first, false))
            continue; // discovery and warm-up
        w.add({2 * m.captured(2).toDouble(), 2 * m.captured(3).toDouble(), m.captured(4).toInt()});
        halfShare.push_back(m.captured(1).toDouble() * m.captured(4).toDouble() / 1e6);
    }
    return w;
}

// Samples per second `ddsperf sub` reports while `ddsperf pub` writes as fast
// as it can: the median of its whole-second lines.
double ddsperfThroughput(int packetBytes)
{
    QProcess sub, pub;
    startDdsperf(sub, {QStringLiteral("-D"), QStringLiteral("7"), QStringLiteral("sub")});
    startDdsperf(pub, {QStringLiteral("-D"), QStringLiteral("6"), QStringLiteral("pub"), QStringLiteral("size"), QString::number(packetBytes)});
    pub.waitForFinished(20000);
    sub.waitForFinished(20000);
    // "[10] 3.000  size 64 total 2533036 lost 0 delta 531408 lost 0 rate 531.42 kS/s 272.09 Mb/s (...)"
    static const QRegularExpression line(QStringLiteral(R"(rate ([\d.]+) kS/s)"));
    std::vector<double> rates;
    auto it = line.globalMatch(QString::fromUtf8(sub.readAllStandardOutput()));
    while (it.hasNext())
        rates.push_back(it.next().captured(1).toDouble() * 1000);
    if (rates.size() > 2) { // the first and last seconds are partial
        rates.erase(rates.begin());
        rates.pop_back();
    }
    return percentiles(rates).p50;
}

// Publish (monotonic time in the sample) → the QML Variable bound to it changes.
Figures publishToQml(QQmlEngine &engine, tree::VariableTreeModel &model)
{
    QQmlComponent component(&engine);
    component.setData("import Neptus.Engine\nVariable { path: \"0x4004/LogBookEntry/htime\" }", QUrl());
    std::unique_ptr<QObject> object(component.createWithInitialProperties({{QStringLiteral("tree"), QVariant::fromValue(&model)}}));
    auto *variable = qobject_cast<tree::Variable *>(object.get());
    if (!variable) {
        std::fprintf(stderr, "%s\n", qPrintable(component.errorString()));
        return {};
    }
    std::vector<double> micros;
    double last = 0;
    QObject::connect(variable, &tree::Variable::changed, [&] {
        const double stamp = variable->value().toDouble();
        if (variable->present() && stamp != last)
            micros.push_back((monotonicSeconds() - stamp) * 1e6);
        last = stamp;
    });
    QProcess *child = startChild({QStringLiteral("--paced")});
    QEventLoop loop;
    QObject::connect(child, &QProcess::finished, &loop, &QEventLoop::quit);
    QTimer::singleShot(60000, &loop, &QEventLoop::quit);
    loop.exec();
    QTimer::singleShot(200, &loop, &QEventLoop::quit); // the last sample's frame
    loop.exec();
    stopChild(child);
    return percentiles(std::move(micros));
}

double ratio(double a, double b)
{
    return b > 0 ? a / b : 0.0;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    if (args.contains(QStringLiteral("--pong")))
        return pong();
    if (args.size() == 4 && args[1] == QStringLiteral("--pub"))
        return publishFlat(args[2].toInt(), args[3].toInt());
    if (args.contains(QStringLiteral("--paced")))
        return publishPaced();
    const QString only = args.size() == 3 && args[1] == QStringLiteral("--only") ? args[2] : QString();

    auto schema = test::shippedSchema();
    tree::VariableTree tree;
    tree::VariableTreeModel model(&tree);
    // The pipeline as fast as it goes: every frame, not the console's display
    // rate (at most 10 updates a second while values keep changing).
    model.setDisplayRate(0);
    transport::DdsTransport dds(schema, configFor(pinger));
    Receiver receiver;
    receiver.tree = &tree;
    receiver.dds = &dds;
    dds.setDirectReceiver([&receiver](const msg::Message &m, qsizetype) { receiver(m); });
    if (!dds.start())
        return 1;

    std::printf("DDS on loopback (dds/loopback.xml); both sides receive on Cyclone's threads (direct receiver);\n"
                "ours and ddsperf take turns: %d times each for round trips, %d for throughput\n\n", roundTripTurns, throughputTurns);
    if (only.isEmpty() || only == u"roundtrip") {
        std::printf("Round trip in microseconds: median over one-second windows of each window's p50 and p99\n");
        std::printf("%-7s %-30s %-30s %s\n", "packet", "Neptus-Qt envelope", "ddsperf ping/pong (doubled)", "ratio p50 / p99");
        QProcess *echo = startChild({QStringLiteral("--pong")});
        std::vector<double> halfShare;
        for (int size : {64, 1024}) {
            Windows ours, theirs;
            for (int turn = 0; turn < roundTripTurns; ++turn) {
                ours.add(roundTrip(receiver, size));
                theirs.add(ddsperfRoundTrip(size, halfShare));
            }
            const double a50 = median(ours.p50), a99 = median(ours.p99), b50 = median(theirs.p50), b99 = median(theirs.p99);
            std::printf("%-7d %7.1f / %7.1f (%2zu windows)  %7.1f / %7.1f (%2zu windows)  %.2fx / %.2fx\n", size, a50, a99,
                        ours.p50.size(), b50, b99, theirs.p50.size(), ratio(a50, b50), ratio(a99, b99));
            // Every window's p99, in the order measured (turns alternate): a
            // noisy spell of the machine shows as a run of high ones on both sides.
            const auto list = [](const std::vector<double> &v) {
                QStringList out;
                for (double x : v)
                    out << QString::number(x, 'f', 0);
                return out.join(u' ');
            };
            std::printf("        window p99s, ours:    %s\n        window p99s, ddsperf: %s\n", qPrintable(list(ours.p99)),
                        qPrintable(list(theirs.p99)));
            std::fflush(stdout);
        }
        stopChild(echo);
        std::printf("ddsperf's printed mean x its round trips per second = %.2f s of each second (median of %zu lines):\n"
                    "pings go one at a time, so it prints half of each round trip (whole ones would make about 1)\n",
                    median(halfShare), halfShare.size());
    }

    if (only.isEmpty() || only == u"throughput") {
        std::printf("\nThroughput, samples/s received (publisher writing as fast as it can, reliable): median of %d turns\n", throughputTurns);
        std::printf("%-7s %-20s %-20s %-7s %s\n", "packet", "Neptus-Qt envelope", "ddsperf pub/sub", "ratio", "turns (ours / ddsperf)");
        for (int size : {64, 1024}) {
            std::vector<double> ours, theirs;
            QString each;
            for (int turn = 0; turn < throughputTurns; ++turn) {
                ours.push_back(throughput(receiver, size));
                theirs.push_back(ddsperfThroughput(size));
                each += QStringLiteral("%1/%2k ").arg(ours.back() / 1000, 0, 'f', 0).arg(theirs.back() / 1000, 0, 'f', 0);
            }
            std::printf("%-7d %10.0f           %10.0f           %.2fx   %s\n", size, median(ours), median(theirs),
                        ratio(median(ours), median(theirs)), qPrintable(each));
            std::fflush(stdout);
        }
    }
    if (!only.isEmpty() && only != u"qml")
        return 0;

    std::printf("\nPublish -> QML Variable changed (tree ingest + frame sync every 16 ms), microseconds\n");
    QQmlEngine engine;
    const Figures e2e = publishToQml(engine, model);
    std::printf("p50 %.1f  p99 %.1f  (n=%d of %d published)\n", e2e.p50, e2e.p99, e2e.count, pacedSamples);
    return 0;
}
