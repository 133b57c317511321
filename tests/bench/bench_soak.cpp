// The console over hours: the console program (the default console, as
// tools/run shows it, recording its logs and writing its database) with two
// simulated vehicles that run their plans in a loop — a second console here
// starts each plan again as soon as the vehicle is ready — and a real DUNE
// vehicle's traffic (../shared/fixtures/dune-log, 61 message types, replayed
// at its own pace over and over, when the fixture is there). Prints the
// console's resident memory every minute and, at the end, at 10 minutes and
// at the end and the growth between them (goal: ≤ 5 MB after the first 10
// minutes).
//
//   bench_soak [MINUTES=120]     (--smoke: 1 minute)
//
// The AUV's link is cut for 10 s one minute in (a fault of the simulator):
// the console's first alarm opens its sound system (Qt Multimedia, FFmpeg,
// the audio server's client: about 4 MB of heap and 17 MB of libraries, once),
// so that one-time step falls in the first 10 minutes of every run instead of
// whenever the machine's load first made a vehicle late (minute 44 in one run).
//
// NEPTUS_SOAK_WRAP runs the console under another program to see where its
// memory goes, e.g. NEPTUS_SOAK_WRAP="heaptrack -o /work/main/build/soak/heap"
// (the figures are then the wrapper's, not to be compared).
#include "mission/MissionXml.h"
#include "plans/PlanDesk.h"
#include "session/Console.h"

#include "Paths.h"
#include "Schemas.h"
#include "core/Gzip.h"
#include "messages/Codec.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUdpSocket>
#include <QtEndian>

#include <unistd.h>

#include <cstdio>
#include <map>

using namespace neptus;
using namespace Qt::StringLiterals;

namespace {

constexpr quint16 auvPort = 17500, asvPort = 17501, consolePort = 17510;

const char *const missionText = R"X(<?xml version="1.0" encoding="UTF-8"?>
<mission format="1" id="soak" name="Soak">
  <home lat="41.1855" lon="-8.7060" height="0"/>
  <vehicle id="lauv-soak"/>
  <vehicle id="caravela-soak"/>
  <plan id="auv-loop" vehicle="lauv-soak" start="out">
    <maneuvers>
      <Goto id="out" lat="41.1865" lon="-8.7060" z="3" z_units="DEPTH" speed="1.6" speed_units="METERS_PS"/>
      <Loiter id="circle" lat="41.1865" lon="-8.7060" z="2" z_units="DEPTH" speed="1.6" speed_units="METERS_PS"
              duration="60" radius="20" type="CIRCULAR" direction="CLOCKW"/>
      <Rows id="rows" lat="41.1868" lon="-8.7050" z="4" z_units="DEPTH" speed="1.6" speed_units="METERS_PS"
            width="60" length="80" hstep="20" bearing="0"/>
      <Goto id="back" lat="41.1855" lon="-8.7060" z="0" z_units="DEPTH" speed="1.6" speed_units="METERS_PS"/>
    </maneuvers>
    <transition from="out" to="circle"/>
    <transition from="circle" to="rows"/>
    <transition from="rows" to="back"/>
  </plan>
  <plan id="asv-loop" vehicle="caravela-soak" start="a">
    <maneuvers>
      <Goto id="a" lat="41.1850" lon="-8.7075" z="0" z_units="DEPTH" speed="2" speed_units="METERS_PS"/>
      <Goto id="b" lat="41.1845" lon="-8.7050" z="0" z_units="DEPTH" speed="2" speed_units="METERS_PS"/>
      <StationKeeping id="hold" lat="41.1845" lon="-8.7050" z="0" z_units="DEPTH" speed="2" speed_units="METERS_PS"
                      duration="30" radius="10"/>
      <Goto id="c" lat="41.1855" lon="-8.7060" z="0" z_units="DEPTH" speed="2" speed_units="METERS_PS"/>
    </maneuvers>
    <transition from="a" to="b"/>
    <transition from="b" to="hold"/>
    <transition from="hold" to="c"/>
  </plan>
</mission>
)X";

qint64 rssKb(qint64 pid)
{
    QFile status(u"/proc/%1/status"_s.arg(pid));
    if (!status.open(QIODevice::ReadOnly))
        return -1;
    static const QRegularExpression rss(u"VmRSS:\\s+(\\d+) kB"_s);
    const auto match = rss.match(QString::fromLatin1(status.readAll()));
    return match.hasMatch() ? match.captured(1).toLongLong() : -1;
}

// A vehicle's packets of an IMC log and when each was sent, seconds from the first.
struct Recorded
{
    std::vector<QByteArray> packets;
    std::vector<double> at;
    double span = 0;
};

Recorded vehiclePackets(const QString &log, quint16 vehicle)
{
    Recorded out;
    const auto bytes = readFileMaybeGzip(log, qsizetype(64) << 20);
    if (!bytes)
        return out;
    double first = -1;
    for (qsizetype at = 0; at + msg::Codec::headerSize + msg::Codec::footerSize <= bytes->size();) {
        const qsizetype size = msg::Codec::headerSize + qFromLittleEndian<quint16>(bytes->constData() + at + 4) + msg::Codec::footerSize;
        const QByteArray packet = bytes->mid(at, size);
        at += size;
        if (qFromLittleEndian<quint16>(packet.constData() + 14) != vehicle)
            continue;
        const double time = qFromLittleEndian<double>(packet.constData() + 6);
        if (first < 0)
            first = time;
        out.packets.push_back(packet);
        out.at.push_back(std::max(0.0, time - first)); // a few it queued before the log opened are older
    }
    out.span = out.at.empty() ? 0 : out.at.back() + 1;
    return out;
}

// Resident memory by kind (/proc/PID/smaps_rollup), kB: anonymous (the heap,
// thread stacks, GL buffers) and file-backed (libraries, mapped files).
std::pair<qint64, qint64> anonAndFileKb(qint64 pid)
{
    QFile rollup(u"/proc/%1/smaps_rollup"_s.arg(pid));
    if (!rollup.open(QIODevice::ReadOnly))
        return {-1, -1};
    const QString text = QString::fromLatin1(rollup.readAll());
    static const QRegularExpression anon(u"Pss_Anon:\\s+(\\d+) kB"_s), file(u"Pss_File:\\s+(\\d+) kB"_s);
    const auto a = anon.match(text), f = file.match(text);
    return {a.hasMatch() ? a.captured(1).toLongLong() : -1, f.hasMatch() ? f.captured(1).toLongLong() : -1};
}

double cpuSeconds(qint64 pid)
{
    QFile stat(u"/proc/%1/stat"_s.arg(pid));
    if (!stat.open(QIODevice::ReadOnly))
        return -1;
    const QByteArray text = stat.readAll();
    const QList<QByteArray> fields = text.mid(text.lastIndexOf(')') + 2).split(' ');
    return (fields.value(11).toDouble() + fields.value(12).toDouble()) / static_cast<double>(sysconf(_SC_CLK_TCK));
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const bool smoke = app.arguments().contains(u"--smoke"_s);
    const QStringList numbers = app.arguments().mid(1).filter(QRegularExpression(u"^\\d+(\\.\\d+)?$"_s));
    const double minutes = smoke ? 1 : numbers.value(0, u"120"_s).toDouble();
    const QString bin = QCoreApplication::applicationDirPath();

    QTemporaryDir dir;
    QFile scenario(dir.filePath(u"scenario.json"_s));
    const QByteArray vehicles = QStringLiteral(
        R"({"timeFactor": 5, "vehicles": [
          {"id": 80, "name": "lauv-soak", "kind": "auv", "port": %1, "lat": 41.1855, "lon": -8.7060, "faults": ["comms-loss@60:10"]},
          {"id": 81, "name": "caravela-soak", "kind": "asv", "port": %2, "lat": 41.1855, "lon": -8.7060, "phase": 180, "dds": true}]})")
        .arg(auvPort).arg(asvPort).toUtf8();
    QFile missionFile(dir.filePath(u"soak.xml"_s));
    if (!scenario.open(QIODevice::WriteOnly) || scenario.write(vehicles) < 0 || !missionFile.open(QIODevice::WriteOnly)
        || missionFile.write(missionText) < 0)
        return 1;
    scenario.close();
    missionFile.close();

    QProcess sim;
    sim.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    sim.start(bin + u"/neptus-sim"_s, {u"--scenario"_s, scenario.fileName()});
    // The DUNE vehicle, decoded with its own definitions as an operator would (--defs-for).
    const QString duneLog = test::sharedPath(u"fixtures/dune-log/Data.lsf.gz"_s);
    const QString duneDefinitions = test::sharedPath(u"fixtures/dune-log/IMC.xml.gz"_s);
    const Recorded dune = vehiclePackets(duneLog, 0x00d1);
    QStringList arguments{u"--system"_s, u"lauv-soak"_s, u"--mission"_s, missionFile.fileName(), u"--imc-port"_s,
                          QString::number(consolePort), u"--imc-discovery"_s, u"off"_s, u"--imc-peer"_s,
                          u"127.0.0.1:%1"_s.arg(auvPort), u"--imc-peer"_s, u"127.0.0.1:%1"_s.arg(asvPort), u"--log-dir"_s,
                          dir.filePath(u"logs"_s)};
    if (!dune.packets.empty())
        arguments << u"--defs-for"_s << u"0x00d1"_s << duneDefinitions;
    QProcess console;
    console.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    const QStringList wrap = qEnvironmentVariable("NEPTUS_SOAK_WRAP").split(u' ', Qt::SkipEmptyParts);
    if (wrap.isEmpty())
        console.start(bin + u"/neptus"_s, arguments);
    else
        console.start(wrap.front(), wrap.mid(1) + QStringList{bin + u"/neptus"_s} + arguments);
    if (!sim.waitForStarted(5000) || !console.waitForStarted(5000)) {
        std::fprintf(stderr, "bench_soak: cannot start neptus-sim or neptus\n");
        return 1;
    }

    // The second console: it sends each vehicle its plan once, then starts it again whenever the vehicle is ready.
    session::Console driver(test::shippedSchema());
    transport::ImcUdpConfig config;
    config.port = 0;
    config.discovery = false;
    config.systemId = 0x4022;
    config.systemName = u"soak-driver"_s;
    config.destinations = {{QHostAddress::LocalHost, auvPort}, {QHostAddress::LocalHost, asvPort}};
    if (auto started = driver.startImc(config); !started) {
        std::fprintf(stderr, "bench_soak: %s\n", qPrintable(started.error()));
        return 1;
    }
    plans::PlanDesk desk(test::shippedSchema(), driver.tree(), driver.alarmGraph(),
                         [&](quint16 id, const msg::Message &m) { return driver.send(id, m); });
    QObject::connect(&driver, &session::Console::planMessageReceived, &desk, &plans::PlanDesk::receive);
    auto read = mission::readMission(missionText, u"soak.xml"_s);
    if (!read)
        return 1;
    desk.setMission(*read);
    const std::map<QString, QString> plans{{u"lauv-soak"_s, u"auv-loop"_s}, {u"caravela-soak"_s, u"asv-loop"_s}};
    std::map<QString, int> runs;

    // The DUNE log, at its own pace, over and over.
    QUdpSocket duneSocket;
    QElapsedTimer duneClock;
    std::size_t duneNext = 0;
    quint64 duneSent = 0;
    QTimer duneTimer;
    QObject::connect(&duneTimer, &QTimer::timeout, [&] {
        const double now = duneClock.elapsed() / 1000.0;
        while (duneNext < dune.packets.size() && dune.at[duneNext] <= now) {
            duneSocket.writeDatagram(dune.packets[duneNext++], QHostAddress::LocalHost, consolePort);
            ++duneSent;
        }
        if (duneNext == dune.packets.size()) {
            duneNext = 0;
            duneClock.restart();
        }
    });
    if (!dune.packets.empty()) {
        duneClock.start();
        duneTimer.start(10);
    }

    std::printf("bench_soak: the console program with 2 simulated vehicles looping their plans%s, %.1f min\n",
                dune.packets.empty() ? " (no DUNE log: ../shared/fixtures is absent)"
                                     : qPrintable(u" and a DUNE vehicle (%1 packets in %2 s, again and again)"_s
                                                      .arg(dune.packets.size()).arg(dune.span, 0, 'f', 1)),
                minutes);
    std::printf("%8s %10s %10s %8s %8s %8s %s\n", "minute", "RSS MB", "growth", "anon MB", "file MB", "CPU %", "plans started");
    std::fflush(stdout);
    QElapsedTimer clock;
    clock.start();
    qint64 rssAt10 = -1, first = -1, last = -1;
    double cpuBefore = cpuSeconds(console.processId());
    qint64 lastPrintMs = 0;
    while (clock.elapsed() < qint64(minutes * 60000) && console.state() == QProcess::Running) {
        QTest::qWait(1000);
        for (const auto &[vehicle, plan] : plans) {
            if (driver.tree().systemId(vehicle) == std::nullopt)
                continue;
            if (!desk.fetched(vehicle)) {
                desk.refresh(vehicle);
                continue;
            }
            if (desk.sync(vehicle, plan) != plans::Sync::Same) {
                desk.send(vehicle, plan);
                continue;
            }
            const tree::NodeId state = driver.tree().find(vehicle + u"/PlanControlState/state"_s);
            if (state != tree::noNode && driver.tree().snapshot(state).text == u"READY" && desk.start(vehicle, plan))
                ++runs[vehicle];
        }
        const qint64 now = clock.elapsed();
        if (now - lastPrintMs < 60000 && !(smoke && now - lastPrintMs >= 10000))
            continue;
        lastPrintMs = now;
        const qint64 rss = rssKb(console.processId());
        const double cpu = cpuSeconds(console.processId());
        if (first < 0)
            first = rss;
        last = rss;
        if (rssAt10 < 0 && now >= 10 * 60000)
            rssAt10 = rss;
        const auto [anonKb, fileKb] = anonAndFileKb(console.processId());
        std::printf("%8.1f %10.1f %+10.1f %8.1f %8.1f %8.1f %d + %d\n", now / 60000.0, rss / 1024.0, (rss - first) / 1024.0,
                    anonKb / 1024.0, fileKb / 1024.0, 100.0 * (cpu - cpuBefore) / (smoke ? 10.0 : 60.0), runs[u"lauv-soak"_s], runs[u"caravela-soak"_s]);
        std::fflush(stdout);
        cpuBefore = cpu;
    }
    const bool alive = console.state() == QProcess::Running;
    console.terminate();
    sim.terminate();
    console.waitForFinished(10000);
    sim.waitForFinished(5000);
    if (!alive) {
        std::printf("bench_soak: the console ended early (exit %d)\n", console.exitCode());
        return 1;
    }
    std::printf("RSS at 1 min %.1f MB", first / 1024.0);
    if (rssAt10 >= 0)
        std::printf(", at 10 min %.1f MB, at %.0f min %.1f MB: %+.1f MB after the first 10 minutes", rssAt10 / 1024.0,
                    minutes, last / 1024.0, (last - rssAt10) / 1024.0);
    std::printf("; plans run: %d (AUV) + %d (ASV); DUNE packets sent: %llu\n", runs[u"lauv-soak"_s], runs[u"caravela-soak"_s],
                static_cast<unsigned long long>(duneSent));
    return 0;
}
