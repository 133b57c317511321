// DDS benchmarks of the Neptus-Qt envelope path, each beside ddsperf in the
// same run on the same loopback configuration (dds/loopback.xml):
//   1. round trip: a pong process (this program, --pong) echoes LogBookEntry
//      envelopes; compared with `ddsperf ping` / `ddsperf pong`;
//   2. throughput: a publisher process (--pub) writes as fast as it can, this
//      process counts what arrives; compared with `ddsperf pub` / `ddsperf sub`;
//   3. end to end: a publisher process (--paced) stamps LogBookEntry.htime
//      with the monotonic clock, this process ingests into a variable tree
//      and watches a QML `Variable` bound to that field: publish → value
//      visible in QML, frames included.
// Both sides receive as the console does: on Cyclone's threads, straight
// into a thread-safe consumer (DdsTransport::setDirectReceiver).
// Run: tools/bench dds
#include "DdsTransport.h"
#include "Schemas.h"
#include "Variable.h"
#include "VariableTreeModel.h"

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

Q_IMPORT_QML_PLUGIN(Neptus_EnginePlugin)

using namespace neptus;

namespace {

constexpr dds_domainid_t benchDomain = 9;
constexpr quint16 pinger = 0x4001, ponger = 0x4002, publisher = 0x4003, pacer = 0x4004;
constexpr int pacedSamples = 400;

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

// Child processes. ------------------------------------------------------------

int pong()
{
    transport::DdsTransport dds(test::shippedSchema(), configFor(ponger));
    dds.setDirectReceiver([&dds](const msg::Message &m) {
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
    int pingsLeft = 0;
    std::chrono::steady_clock::time_point sent;
    std::vector<double> micros;

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
        const auto now = std::chrono::steady_clock::now();
        std::lock_guard lock(mutex);
        if (pingsLeft <= 0)
            return;
        micros.push_back(std::chrono::duration<double, std::micro>(now - sent).count());
        if (--pingsLeft == 0) {
            done.notify_one();
            return;
        }
        sent = std::chrono::steady_clock::now();
        dds->broadcast(ping);
    }

    // Sends `rounds` pings one after the other; false if an echo stays away for a second.
    bool pingPong(const msg::Message &message, int rounds)
    {
        std::unique_lock lock(mutex);
        ping = message;
        pingsLeft = rounds;
        micros.clear();
        sent = std::chrono::steady_clock::now();
        dds->broadcast(ping);
        for (;;) {
            const std::size_t before = micros.size();
            if (done.wait_for(lock, std::chrono::seconds(1), [&] { return pingsLeft == 0; }))
                return true;
            if (micros.size() == before) {
                pingsLeft = 0;
                return false;
            }
        }
    }
};

Figures roundTrip(Receiver &receiver, int packetBytes, int rounds)
{
    const msg::Message entry = entryOfSize(packetBytes);
    // Until the pong has matched our writer and we its.
    QElapsedTimer waited;
    waited.start();
    bool matched = false;
    while (!matched && waited.elapsed() < 15000)
        matched = receiver.pingPong(entry, 1);
    if (!matched || !receiver.pingPong(entry, rounds))
        return {};
    return percentiles(receiver.micros);
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
    env.insert(QStringLiteral("CYCLONEDDS_URI"), QStringLiteral("file://" NEPTUS_DDS_CONFIG));
    process.setProcessEnvironment(env);
    process.start(QStringLiteral("ddsperf"), QStringList{QStringLiteral("-i"), QStringLiteral("8")} + arguments);
}

Figures ddsperfRoundTrip(int packetBytes)
{
    QProcess pongProcess, pingProcess;
    startDdsperf(pongProcess, {QStringLiteral("-D"), QStringLiteral("8"), QStringLiteral("pong")});
    startDdsperf(pingProcess, {QStringLiteral("-D"), QStringLiteral("5"), QStringLiteral("-Qminmatch:1"), QStringLiteral("-Qinitwait:5"),
                               QStringLiteral("ping"), QStringLiteral("size"), QString::number(packetBytes)});
    pingProcess.waitForFinished(20000);
    pongProcess.kill();
    pongProcess.waitForFinished(5000);
    const QString output = QString::fromUtf8(pingProcess.readAllStandardOutput());
    // "... size 64 mean 29.7us min 11.5us 50% 26.3us 90% 33.3us 99% 83.9us max ... cnt 16699": the last second's line.
    static const QRegularExpression line(QStringLiteral(R"(50% ([\d.]+)us 90% [\d.]+us 99% ([\d.]+)us .* cnt (\d+))"));
    Figures f;
    auto it = line.globalMatch(output);
    while (it.hasNext()) {
        const auto m = it.next();
        f = {m.captured(1).toDouble(), m.captured(2).toDouble(), m.captured(3).toInt()};
    }
    return f;
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

    auto schema = test::shippedSchema();
    tree::VariableTree tree;
    tree::VariableTreeModel model(&tree);
    transport::DdsTransport dds(schema, configFor(pinger));
    Receiver receiver;
    receiver.tree = &tree;
    receiver.dds = &dds;
    dds.setDirectReceiver([&receiver](const msg::Message &m) { receiver(m); });
    if (!dds.start())
        return 1;

    std::printf("DDS on loopback (dds/loopback.xml); both sides receive on Cyclone's threads (direct receiver)\n\n");
    std::printf("Round trip, p50 / p99 in microseconds\n");
    std::printf("%-8s %-28s %-28s %s\n", "packet", "Neptus-Qt envelope", "ddsperf ping/pong", "ratio p50 / p99");
    QProcess *echo = startChild({QStringLiteral("--pong")});
    for (int size : {64, 1024}) {
        const Figures a = roundTrip(receiver, size, 50000);
        const Figures b = ddsperfRoundTrip(size);
        std::printf("%-8d %7.1f / %7.1f (n=%5d)   %7.1f / %7.1f (n=%6d)   %.2fx / %.2fx\n", size, a.p50, a.p99, a.count,
                    b.p50, b.p99, b.count, ratio(a.p50, b.p50), ratio(a.p99, b.p99));
        std::fflush(stdout);
    }
    stopChild(echo);

    std::printf("\nThroughput, samples/s received (publisher writing as fast as it can, reliable)\n");
    std::printf("%-8s %-20s %-20s %s\n", "packet", "Neptus-Qt envelope", "ddsperf pub/sub", "ratio");
    for (int size : {64, 1024}) {
        const double a = throughput(receiver, size);
        const double b = ddsperfThroughput(size);
        std::printf("%-8d %10.0f           %10.0f           %.2fx\n", size, a, b, ratio(a, b));
        std::fflush(stdout);
    }

    std::printf("\nPublish -> QML Variable changed (tree ingest + frame sync every 16 ms), microseconds\n");
    QQmlEngine engine;
    const Figures e2e = publishToQml(engine, model);
    std::printf("p50 %.1f  p99 %.1f  (n=%d of %d published)\n", e2e.p50, e2e.p99, e2e.count, pacedSamples);
    return 0;
}
