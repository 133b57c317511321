// How many simulated vehicles one core carries, end to end: one neptus-sim
// process runs N vehicles from a scenario (AUV, ASV, UAV in turn), each
// executing a plan and streaming its 10 Hz state and 1 Hz reports over
// IMC/UDP to a console (session::Console here) that heartbeats them all.
// Prints the simulator's CPU (user + system, from /proc) over the
// measurement, the vehicles one core carries at that rate, and how much of
// what the vehicles should say the console received.
//
//   bench_sim_process [VEHICLES=100] [SECONDS=20]     (--smoke: 5 vehicles, 3 s)
#include "mission/ImcPlan.h"
#include "mission/MissionXml.h"
#include "session/Console.h"

#include "Schemas.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <unistd.h>

#include <cstdio>

using namespace neptus;
using namespace Qt::StringLiterals;

namespace {

constexpr quint16 firstPort = 17000;

// utime + stime of a process, in seconds.
double cpuSeconds(qint64 pid)
{
    QFile stat(u"/proc/%1/stat"_s.arg(pid));
    if (!stat.open(QIODevice::ReadOnly))
        return -1;
    const QByteArray text = stat.readAll();
    const QList<QByteArray> fields = text.mid(text.lastIndexOf(')') + 2).split(' ');
    return (fields.value(11).toDouble() + fields.value(12).toDouble()) / static_cast<double>(sysconf(_SC_CLK_TCK));
}

quint64 received(session::Console &console)
{
    quint64 total = 0;
    for (const auto &system : console.linkStatistics().systems())
        total += system.messages;
    return total;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const bool smoke = app.arguments().contains(u"--smoke"_s);
    const QStringList numbers = app.arguments().mid(1).filter(QRegularExpression(u"^\\d+$"_s));
    const int vehicles = smoke ? 5 : numbers.value(0, u"100"_s).toInt();
    const int seconds = smoke ? 3 : numbers.value(1, u"20"_s).toInt();

    QTemporaryDir dir;
    QStringList entries;
    const char *kinds[] = {"auv", "asv", "uav"};
    for (int i = 0; i < vehicles; ++i)
        entries << u"{\"id\": %1, \"name\": \"sim-%2\", \"kind\": \"%3\", \"port\": %4, \"phase\": %5}"_s.arg(0x100 + i).arg(i).arg(
            QLatin1StringView(kinds[i % 3])).arg(firstPort + i).arg(i * 360.0 / vehicles);
    QFile scenario(dir.filePath(u"scenario.json"_s));
    if (!scenario.open(QIODevice::WriteOnly) || scenario.write(u"{\"vehicles\": [%1]}"_s.arg(entries.join(u",\n"_s)).toUtf8()) < 0)
        return 1;
    scenario.close();

    QProcess sim;
    sim.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    sim.start(QCoreApplication::applicationDirPath() + u"/neptus-sim"_s, {u"--scenario"_s, scenario.fileName()});
    if (!sim.waitForStarted(5000)) {
        std::fprintf(stderr, "bench_sim_process: cannot start neptus-sim\n");
        return 1;
    }

    transport::ImcUdpConfig config;
    config.port = 0;
    config.discoveryPort = 0;
    config.heartbeatMs = 1000;
    for (int i = 0; i < vehicles; ++i)
        config.destinations.append({QHostAddress::LocalHost, static_cast<quint16>(firstPort + i)});
    session::Console console(test::shippedSchema());
    if (auto started = console.startImc(config); !started) {
        std::fprintf(stderr, "bench_sim_process: %s\n", qPrintable(started.error()));
        return 1;
    }
    QElapsedTimer wait;
    wait.start();
    while (console.tree().systemIds().size() < static_cast<size_t>(vehicles) && wait.elapsed() < 30000)
        QTest::qWait(200);
    if (console.tree().systemIds().size() < static_cast<size_t>(vehicles)) {
        std::fprintf(stderr, "bench_sim_process: heard %zu of %d vehicles\n", console.tree().systemIds().size(), vehicles);
        return 1;
    }

    // Every vehicle gets a plan that never ends: a loiter.
    const auto schema = test::shippedSchema();
    for (int i = 0; i < vehicles; ++i) {
        const QString name = u"sim-%1"_s.arg(i);
        auto mission = mission::readMission(QStringLiteral(R"X(<?xml version="1.0" encoding="UTF-8"?>
<mission format="1" id="b" name="b"><home lat="41.1705" lon="-8.7150" height="0"/><vehicle id="%1"/>
<plan id="circle" vehicle="%1" start="l"><maneuvers>
<Loiter id="l" lat="41.1710" lon="-8.7150" z="%2" z_units="%3" speed="%4" speed_units="METERS_PS" duration="0" radius="60" type="CIRCULAR" direction="CLOCKW"/>
</maneuvers></plan></mission>)X").arg(name).arg(i % 3 == 2 ? 100 : 2).arg(i % 3 == 2 ? u"HEIGHT"_s : u"DEPTH"_s).arg(i % 3 == 2 ? 18 : 1.5).toUtf8(), u"b.xml"_s);
        const auto spec = mission::planSpecification(mission->plans.first(), *schema);
        msg::Message start(schema->byAbbrev(u"PlanControl"));
        start.setInteger(start.def()->indexOf(u"op"), 0); // START
        start.setInteger(start.def()->indexOf(u"request_id"), i + 1);
        start.setBytes(start.def()->indexOf(u"plan_id"), "circle");
        start.setInlineMessage(start.def()->indexOf(u"arg"), *spec);
        if (auto sent = console.send(static_cast<quint16>(0x100 + i), start); !sent)
            std::fprintf(stderr, "bench_sim_process: %s\n", qPrintable(sent.error()));
    }
    QTest::qWait(3000); // plans running, streams steady

    const double cpu0 = cpuSeconds(sim.processId());
    const quint64 messages0 = received(console);
    QElapsedTimer clock;
    clock.start();
    QTest::qWait(seconds * 1000);
    const double wall = clock.elapsed() / 1000.0;
    const double cpu = cpuSeconds(sim.processId()) - cpu0;
    const double got = static_cast<double>(received(console) - messages0);
    int executing = 0;
    for (int i = 0; i < vehicles; ++i) {
        const tree::NodeId state = console.tree().find(u"sim-%1/PlanControlState/state"_s.arg(i));
        executing += state != tree::noNode && console.tree().snapshot(state).text == u"EXECUTING" ? 1 : 0;
    }
    const double perVehicle = cpu / wall / vehicles; // fraction of a core
    std::printf("vehicles %d (executing plans: %d), %.1f s measured\n", vehicles, executing, wall);
    std::printf("neptus-sim CPU: %.1f %% of one core (%.3f %% per vehicle)\n", 100 * cpu / wall, 100 * perVehicle);
    std::printf("vehicles one core carries at 10 Hz: %.0f\n", perVehicle > 0 ? 1.0 / perVehicle : 0.0);
    std::printf("console received %.0f messages/s, %.1f per vehicle (each says 20 + announcements)\n", got / wall, got / wall / vehicles);
    sim.terminate();
    sim.waitForFinished(5000);
    return executing == vehicles ? 0 : 1;
}
