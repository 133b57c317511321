// Logs at mission scale.
//  - Record: a console's traffic (a mix of 10 message types from 3 vehicles)
//    handed to the recorder at a steady rate (1 M and 2 M messages a second,
//    a millisecond's worth at a time) for 3 s, then stopped (the queue
//    emptied, the part closed with its index); figures: messages recorded
//    per second, and lost (must be 0: the writer keeps up).
//  - RecordBurst: 200,000 messages handed over at once: how fast the writer
//    empties the queue.
//  - A generated 1-hour log of three vehicles (about 830 messages a second,
//    3 M messages) is then: indexed (opened without its index: every packet's
//    header and checksum read) and opened with its index; replayed whole
//    through a console (tree, health, names, statistics: what a review
//    console does), as fast as it goes; and seeked to random moments, each
//    seek giving the state at that time.
// Run: tools/bench log
#include "BenchMain.h"
#include "Paths.h"
#include "Schemas.h"
#include "log/LogFile.h"
#include "log/Recorder.h"
#include "log/Replay.h"
#include "messages/Codec.h"
#include "session/ConsoleReplay.h"

#include <QDir>
#include <QDirIterator>
#include <QElapsedTimer>
#include <QFile>
#include <QRandomGenerator>
#include <QTemporaryDir>

#include <algorithm>

using namespace neptus;

namespace {

constexpr double hour = 3600.0;

// One second of a vehicle's traffic: (message, how many a second).
std::vector<std::pair<msg::Message, int>> secondOfTraffic(quint16 system)
{
    const auto schema = test::shippedSchema();
    std::vector<std::pair<msg::Message, int>> mix;
    const std::pair<const char *, int> rates[] = {
        {"EstimatedState", 10}, {"EulerAngles", 100}, {"Rpm", 100}, {"Depth", 20}, {"EntityState", 20},
        {"Temperature", 10},    {"Voltage", 10},      {"CpuUsage", 5}, {"Heartbeat", 1}, {"GpsFix", 1},
    };
    for (const auto &[abbrev, rate] : rates) {
        msg::Message m(schema->byAbbrev(QString::fromLatin1(abbrev)));
        m.header.src = system;
        for (int f = 0; f < m.fieldCount(); ++f) {
            if (msg::isFloat(m.field(f).type))
                m.setNumber(f, 0.25 * f + system % 7);
        }
        mix.emplace_back(std::move(m), rate);
    }
    return mix;
}

// `seconds` of traffic from three vehicles, encoded, in time order.
std::vector<QByteArray> traffic(double seconds, double start = 1.7e9)
{
    const msg::Codec codec(test::shippedSchema());
    std::vector<std::vector<std::pair<msg::Message, int>>> vehicles;
    for (quint16 system : {quint16(0x0015), quint16(0x0016), quint16(0x0017)})
        vehicles.push_back(secondOfTraffic(system));
    std::vector<QByteArray> packets;
    packets.reserve(size_t(seconds * 835));
    for (int s = 0; s < int(seconds); ++s) {
        for (auto &vehicle : vehicles) {
            for (auto &[message, rate] : vehicle) {
                for (int i = 0; i < rate; ++i) {
                    message.header.timestamp = start + s + double(i) / rate;
                    message.header.srcEnt = quint8(i % 8);
                    packets.push_back(*codec.encode(message));
                }
            }
        }
    }
    std::stable_sort(packets.begin(), packets.end(), [](const QByteArray &a, const QByteArray &b) {
        return log::PacketHeader::read(a)->timestamp < log::PacketHeader::read(b)->timestamp;
    });
    return packets;
}

log::RecorderConfig configIn(const QString &root)
{
    log::RecorderConfig config;
    config.root = root;
    config.name = QStringLiteral("bench");
    config.system = 0x4001;
    config.definitionFiles = msg::Schema::filesIn(test::msgdefsDirectory());
    return config;
}

// The 1-hour log, recorded once per run.
struct HourLog
{
    QTemporaryDir root;
    QString folder;
    qint64 packets = 0;

    HourLog()
    {
        const auto packetsOfHour = traffic(hour);
        packets = qint64(packetsOfHour.size());
        log::RecorderConfig config = configIn(root.path());
        config.maxQueuedBytes = qint64(1) << 30; // handed over at once: all of it waits its turn
        log::Recorder recorder(config);
        if (!recorder.start())
            std::abort();
        for (const QByteArray &p : packetsOfHour)
            recorder.record(p);
        recorder.stop();
        folder = recorder.status().folder;
        if (recorder.status().packets != quint64(packets))
            std::abort();
        std::fprintf(stderr, "1-hour log: %lld messages, %.1f MB in %s\n", static_cast<long long>(packets),
                     QFileInfo(QDir(folder).filePath(QStringLiteral("Data.lsf"))).size() / 1e6, qPrintable(folder));
    }
};

HourLog &hourLog()
{
    static HourLog log;
    return log;
}

void BM_RecordSustained(benchmark::State &state)
{
    const qint64 rate = state.range(0);
    const auto packets = traffic(5);
    quint64 lost = 0, written = 0;
    std::vector<double> callNs;
    for (auto _ : state) {
        QTemporaryDir root;
        QElapsedTimer timer;
        timer.start();
        log::Recorder recorder(configIn(root.path()));
        if (!recorder.start())
            std::abort();
        qint64 sent = 0;
        while (timer.elapsed() < 3000) {
            const qint64 due = timer.nsecsElapsed() * rate / 1'000'000'000;
            for (; sent < due; ++sent) {
                // What a link's thread waits for: every 100th call timed.
                if (sent % 100 == 0) {
                    const qint64 before = timer.nsecsElapsed();
                    recorder.record(packets[size_t(sent) % packets.size()]);
                    callNs.push_back(double(timer.nsecsElapsed() - before));
                } else {
                    recorder.record(packets[size_t(sent) % packets.size()]);
                }
            }
        }
        recorder.stop();
        state.SetIterationTime(timer.nsecsElapsed() / 1e9);
        lost += recorder.status().lost;
        written += recorder.status().packets;
    }
    std::sort(callNs.begin(), callNs.end());
    state.counters["record() p99 ns"] = callNs.empty() ? 0 : callNs[size_t(double(callNs.size()) * 0.99)];
    state.counters["record() max us"] = callNs.empty() ? 0 : callNs.back() / 1000;
    state.counters["lost"] = double(lost);
    state.counters["recorded msgs/s"] = benchmark::Counter(double(written), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_RecordSustained)->Arg(1'000'000)->Arg(2'000'000)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(2);

void BM_RecordBurst(benchmark::State &state)
{
    const auto packets = traffic(state.range(0) / 830.0);
    quint64 lost = 0, written = 0;
    for (auto _ : state) {
        QTemporaryDir root;
        QElapsedTimer timer;
        timer.start();
        log::Recorder recorder(configIn(root.path()));
        if (!recorder.start())
            std::abort();
        for (const QByteArray &p : packets)
            recorder.record(p);
        recorder.stop(); // everything written, the part closed and indexed
        state.SetIterationTime(timer.nsecsElapsed() / 1e9);
        lost += recorder.status().lost;
        written += recorder.status().packets;
    }
    state.SetItemsProcessed(qint64(written));
    state.counters["lost"] = double(lost);
    state.counters["msgs/s"] = benchmark::Counter(double(written), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_RecordBurst)->Arg(200'000)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_IndexHourLog(benchmark::State &state)
{
    const bool reuse = state.range(0) != 0;
    const QString folder = hourLog().folder;
    log::LogFile::Options options;
    options.writeIndex = false;
    const QString index = QDir(folder).filePath(QStringLiteral("Data.lsf.index"));
    const QString aside = index + QStringLiteral(".aside");
    if (!reuse)
        QFile::rename(index, aside);
    qint64 count = 0;
    for (auto _ : state) {
        auto log = log::LogFile::open(folder, options);
        if (!log || (*log)->indexReused() != reuse)
            std::abort();
        count = (*log)->count();
        // The merged sequence and its checkpoints: what a replay builds on top.
        log::LogSet set(std::vector{*log});
        benchmark::DoNotOptimize(set.count());
    }
    if (!reuse)
        QFile::rename(aside, index);
    state.counters["messages"] = double(count);
    state.SetLabel(reuse ? "with its index" : "scanned (no index)");
}
BENCHMARK(BM_IndexHourLog)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_ReplayHourLog(benchmark::State &state)
{
    auto log = log::LogFile::open(hourLog().folder);
    const auto set = std::make_shared<const log::LogSet>(std::vector{*log});
    for (auto _ : state) {
        ManualClock clock;
        session::Console console(test::shippedSchema(), &clock);
        session::ConsoleReplay target(console, clock);
        log::Player player(set, &target);
        player.advanceTo(set->end());
        benchmark::DoNotOptimize(console.tree().nodeCount());
    }
    state.SetItemsProcessed(state.iterations() * set->count());
    state.counters["x real time"] = benchmark::Counter(double(state.iterations()) * (set->end() - set->begin()),
                                                       benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ReplayHourLog)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_SeekHourLog(benchmark::State &state)
{
    auto log = log::LogFile::open(hourLog().folder);
    const auto set = std::make_shared<const log::LogSet>(std::vector{*log});
    ManualClock clock;
    session::Console console(test::shippedSchema(), &clock);
    session::ConsoleReplay target(console, clock);
    log::Player player(set, &target);
    QRandomGenerator random(42);
    std::vector<double> millis;
    for (auto _ : state) {
        const double t = set->begin() + random.generateDouble() * (set->end() - set->begin());
        QElapsedTimer timer;
        timer.start();
        player.seek(t);
        millis.push_back(timer.nsecsElapsed() / 1e6);
    }
    std::sort(millis.begin(), millis.end());
    const auto at = [&](double q) { return millis[std::min(millis.size() - 1, size_t(q * double(millis.size())))]; };
    state.counters["p50 ms"] = at(0.50);
    state.counters["p99 ms"] = at(0.99);
    state.counters["max ms"] = millis.back();
}
BENCHMARK(BM_SeekHourLog)->Unit(benchmark::kMillisecond)->Iterations(500);

} // namespace

int main(int argc, char **argv)
{
    return neptus::test::runBenchmarks(argc, argv);
}
