// The operation's database end to end: two consoles write to one database at
// once — one in this process (it runs a plan on one simulated vehicle), one
// the `neptus` program (hearing both vehicles, one with a low battery). With
// PostgreSQL (a real server this test starts) the server is stopped for 60 s
// in the middle, during the plan, and started again: nothing written in
// between is lost. With the SQLite default both consoles share the file
// beside their logs.
#include "database/Database.h"
#include "session/OperationsFeed.h"

#include "PgServer.h"
#include "PlanRun.h"
#include "Ports.h"
#include "SimProcess.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QTemporaryDir>

using namespace neptus;
using namespace neptus::test;
using namespace Qt::StringLiterals;

namespace {

struct ConsoleProgram
{
    QProcess process;
    QByteArray output;
    void start(const QStringList &arguments)
    {
        process.setProcessChannelMode(QProcess::MergedChannels);
        QObject::connect(&process, &QProcess::readyRead, [this] { output += process.readAll(); });
        process.start(programPath(u"neptus"_s), arguments);
        ASSERT_TRUE(process.waitForStarted(5000));
        ASSERT_TRUE(QTest::qWaitFor([this] { return output.contains("neptus: database"); }, 15000)) << output.constData();
    }
    ~ConsoleProgram()
    {
        if (process.state() != QProcess::NotRunning) {
            process.kill();
            process.waitForFinished(5000);
        }
    }
};

QStringList consoleArguments(quint16 port, const QString &name, const QString &logDir, std::initializer_list<quint16> vehicles)
{
    QStringList arguments{u"--console"_s, sourcePath(u"qml/consoles/Inspector.qml"_s), u"--imc-port"_s, QString::number(port),
                          u"--imc-discovery"_s, u"off"_s, u"--dds-domain"_s, u"-1"_s, u"--console-name"_s, name,
                          u"--log-dir"_s, logDir, u"--quit-after"_s, u"600000"_s};
    for (quint16 v : vehicles)
        arguments << u"--imc-peer"_s << u"127.0.0.1:%1"_s.arg(v);
    return arguments;
}

db::Writer::Options writerOptions(const QString &spool, const QString &console)
{
    db::Writer::Options o;
    o.spoolFolder = spool;
    o.console = console;
    o.program = u"tst_e2e_database"_s;
    return o;
}

// Rows of a writer's session in a table.
qint64 rowsOf(const db::Location &location, db::Table table, const QString &session)
{
    auto reader = db::Reader::open(location);
    return reader ? (*reader)->count(table, session).value_or(-1) : -1;
}

} // namespace

TEST(Database, TwoConsolesWriteToOnePostgresServerAndA60sOutageLosesNothing)
{
    PgServer server;
    ASSERT_TRUE(server.ok()) << server.error().toStdString();
    const db::Location location = *db::Location::parse(server.url());
    QTemporaryDir dir;
    const quint16 programPort = freeUdpPort();
    SimProcess auv, other;
    auv.start({u"--id"_s, u"0x1f"_s, u"--name"_s, u"lauv-sim-1"_s, u"--port"_s, u"16170"_s, u"--time-factor"_s, u"30"_s,
               u"--console"_s, u"127.0.0.1:%1"_s.arg(programPort)});
    other.start({u"--id"_s, u"0x20"_s, u"--name"_s, u"lauv-sim-2"_s, u"--port"_s, u"16171"_s, u"--fault"_s, u"battery-low@20"_s,
                 u"--console"_s, u"127.0.0.1:%1"_s.arg(programPort)});

    ConsoleProgram program; // console B: the console program, as an operator runs it
    program.start(consoleArguments(programPort, u"ops-b"_s, dir.filePath(u"logs-b"_s), {16170, 16171})
                  + QStringList{u"--database"_s, server.url()});
    ASSERT_TRUE(program.output.contains("neptus: database postgresql://neptus@socket in")) << program.output.constData();

    session::Console console(shippedSchema()); // console A: in this process
    db::Writer writer(location, writerOptions(dir.filePath(u"spool-a"_s), u"ops-a"_s));
    auto feed = std::make_unique<session::OperationsFeed>(console, &writer);
    ASSERT_TRUE(console.startImc(imcTo({16170, 16171})));
    ASSERT_TRUE(QTest::qWaitFor([&] { return heard(console.tree(), u"lauv-sim-1"_s) && heard(console.tree(), u"lauv-sim-2"_s); }, 15000));
    ASSERT_TRUE(QTest::qWaitFor([&] { writer.flush(0); return writer.status().written > 10; }, 10000));
    auto reader = db::Reader::open(location);
    ASSERT_TRUE(reader.has_value()) << reader.error().toStdString();
    ASSERT_TRUE(QTest::qWaitFor([&] { return (*reader)->sessions()->size() == 2; }, 10000)) << program.output.constData();
    reader->reset();

    // The server goes away for 60 s; console A runs a plan meanwhile, an operator raises,
    // acknowledges and clears an alarm; vehicle 2's battery runs low.
    ASSERT_TRUE(server.stop());
    QElapsedTimer outage;
    outage.start();
    const qint64 outageFrom = QDateTime::currentMSecsSinceEpoch();
    auto &graph = console.alarmGraph();
    const auto node = graph.ensure(u"console/operator"_s);
    graph.raise(node, alarms::Error, u"diver in the water"_s);
    QTest::qWait(500);
    graph.acknowledge(node);
    QTest::qWait(500);
    runPlan(console, 0x1f, u"lauv-sim-1"_s, missionFor("lauv-sim-1", 2, "DEPTH"));
    graph.clear(node);
    ASSERT_TRUE(QTest::qWaitFor([&] { return outage.elapsed() >= 60000; }, 65000));
    writer.flush(0);
    const db::Status during = writer.status();
    EXPECT_FALSE(during.connected);
    EXPECT_GT(during.spooled, 100);
    EXPECT_EQ(during.lost, 0);
    EXPECT_EQ(graph.ownLevel(graph.find(u"database"_s)), alarms::Warning) << graph.message(graph.find(u"database"_s)).toStdString();
    const qint64 outageTo = QDateTime::currentMSecsSinceEpoch();

    ASSERT_TRUE(server.start()) << server.log().toStdString();
    ASSERT_TRUE(writer.flush(20000)) << writer.status().problem.toStdString();
    EXPECT_TRUE(writer.status().connected);
    ASSERT_TRUE(QTest::qWaitFor([&] { return graph.ownLevel(graph.find(u"database"_s)) == alarms::Normal; }, 3000));
    EXPECT_EQ(writer.status().lost, 0);

    // Console A: every row it made is there, once (counted once it stops feeding).
    feed.reset();
    ASSERT_TRUE(writer.flush());
    for (const db::Table table : {db::Table::Position, db::Table::Alarm, db::Table::PlanEvent, db::Table::LogBook})
        EXPECT_EQ(rowsOf(location, table, writer.session()), writer.status().queued[size_t(table)])
            << "table " << int(table) << ": rows of console A in the database = rows it wrote";
    EXPECT_GT(writer.status().queued[size_t(db::Table::Position)], 2 * 60); // two vehicles, a position a second or more each
    reader = db::Reader::open(location);
    ASSERT_TRUE(reader.has_value()) << reader.error().toStdString();
    db::Reader &r = **reader;
    // Console B (the program) catches up by itself: its positions of both vehicles through the outage, without a gap.
    const auto sessions = *r.sessions();
    ASSERT_EQ(sessions.size(), 2u);
    const QString sessionB = sessions[0].console == u"ops-b"_s ? sessions[0].session : sessions[1].session;
    ASSERT_TRUE(QTest::qWaitFor([&] { return rowsOf(location, db::Table::Position, sessionB) > 2 * 2 * 60; }, 20000))
        << program.output.constData();
    for (const QString &vehicle : {u"lauv-sim-1"_s, u"lauv-sim-2"_s}) {
        const auto track = *r.track(vehicle, outageFrom, outageTo);
        ASSERT_GT(track.size(), 100u) << vehicle.toStdString();
        qint64 gap = 0;
        for (size_t i = 1; i < track.size(); ++i)
            gap = std::max(gap, track[i].ms - track[i - 1].ms);
        EXPECT_LT(gap, 1500) << vehicle.toStdString() << ": the longest gap in the track through the outage";
        EXPECT_LT(track.front().ms - outageFrom, 1500);
        EXPECT_LT(outageTo - track.back().ms, 1500);
    }
    // What happened during the outage: the plan, maneuver by maneuver, to its end; the operator's alarm.
    QStringList plan;
    const auto planEvents = r.planEvents(outageFrom, outageTo);
    ASSERT_TRUE(planEvents.has_value());
    for (const auto &e : *planEvents)
        if (e.console == u"ops-a"_s && e.plan == u"survey"_s)
            plan.append(e.event + (e.maneuver.isEmpty() ? QString() : u' ' + e.maneuver));
    EXPECT_TRUE(plan.contains(u"sent"_s)) << plan.join(u", "_s).toStdString();
    EXPECT_TRUE(plan.contains(u"started go"_s)) << plan.join(u", "_s).toStdString();
    EXPECT_TRUE(plan.contains(u"maneuver circle"_s)) << plan.join(u", "_s).toStdString();
    EXPECT_TRUE(plan.contains(u"maneuver rows"_s)) << plan.join(u", "_s).toStdString();
    EXPECT_TRUE(plan.contains(u"completed rows"_s)) << plan.join(u", "_s).toStdString();
    QStringList operatorAlarm, battery;
    const auto alarms = r.alarms(outageFrom - 60000, QDateTime::currentMSecsSinceEpoch());
    ASSERT_TRUE(alarms.has_value());
    for (const auto &a : *alarms) {
        if (a.origin == u"console/operator"_s)
            operatorAlarm.append(a.console + u' ' + a.event);
        if (a.origin.startsWith(u"systems/lauv-sim-2"_s) && a.event == u"raised"_s)
            battery.append(a.console + u' ' + a.message);
    }
    EXPECT_EQ(operatorAlarm, (QStringList{u"ops-a raised"_s, u"ops-a acknowledged"_s, u"ops-a cleared"_s}));
    EXPECT_TRUE(battery.filter(u"ops-a"_s).size() > 0 && battery.filter(u"ops-b"_s).size() > 0) << battery.join(u"; "_s).toStdString();
    // Both vehicles, heard by both consoles, once each.
    QStringList systems;
    const auto systemsSeen = r.systems();
    ASSERT_TRUE(systemsSeen.has_value());
    for (const auto &s : *systemsSeen)
        systems.append(s.name);
    EXPECT_EQ(systems, (QStringList{u"lauv-sim-1"_s, u"lauv-sim-2"_s}));
    // Console B's log is in the catalogue.
    bool logB = false;
    const auto logs = r.logs();
    ASSERT_TRUE(logs.has_value());
    for (const auto &l : *logs)
        logB |= l.console == u"ops-b"_s && l.folder.startsWith(dir.filePath(u"logs-b"_s)) && l.packets > 0;
    EXPECT_TRUE(logB);
}

TEST(Database, TwoConsolesShareTheSqliteDefaultBesideTheirLogs)
{
    QTemporaryDir dir;
    const quint16 portA = freeUdpPort(), portB = freeUdpPort();
    SimProcess auv, other;
    auv.start({u"--id"_s, u"0x1f"_s, u"--name"_s, u"lauv-sim-1"_s, u"--port"_s, u"16172"_s, u"--console"_s,
               u"127.0.0.1:%1"_s.arg(portA), u"--console"_s, u"127.0.0.1:%1"_s.arg(portB)});
    other.start({u"--id"_s, u"0x20"_s, u"--name"_s, u"lauv-sim-2"_s, u"--port"_s, u"16173"_s, u"--fault"_s, u"battery-low"_s,
                 u"--console"_s, u"127.0.0.1:%1"_s.arg(portA), u"--console"_s, u"127.0.0.1:%1"_s.arg(portB)});
    const QString logs = dir.filePath(u"logs"_s);
    ConsoleProgram a, b;
    a.start(consoleArguments(portA, u"ops-a"_s, logs, {16172, 16173}));
    b.start(consoleArguments(portB, u"ops-b"_s, logs, {16172, 16173}));
    const QString file = logs + u"/operation.db"_s;
    EXPECT_TRUE(a.output.contains("neptus: database sqlite:" + file.toUtf8())) << a.output.constData();
    const db::Location location = *db::Location::parse(file);
    QString seen;
    ASSERT_TRUE(QTest::qWaitFor([&] {
        auto r = db::Reader::open(location);
        if (!r) {
            seen = r.error();
            return false;
        }
        const auto track1 = (*r)->track(u"lauv-sim-1"_s, 0, std::numeric_limits<qint64>::max());
        const auto alarms = (*r)->alarms(0, std::numeric_limits<qint64>::max());
        int batteryFromBoth = 0;
        for (const auto &console : {u"ops-a"_s, u"ops-b"_s})
            batteryFromBoth += std::any_of(alarms->begin(), alarms->end(), [&](const auto &x) {
                return x.console == console && x.origin.startsWith(u"systems/lauv-sim-2"_s);
            });
        seen = u"%1 sessions, %2 systems, %3 points of lauv-sim-1, battery alarm from %4 consoles"_s.arg((*r)->sessions()->size())
                   .arg((*r)->systems()->size()).arg(track1->size()).arg(batteryFromBoth);
        return (*r)->sessions()->size() == 2 && (*r)->systems()->size() == 2 && track1->size() > 20 && batteryFromBoth == 2;
    }, 30000)) << seen.toStdString() << "\n" << a.output.constData() << b.output.constData();
}

TEST(Database, TheHeadlessRecorderNodeRecordsAndWritesTheDatabaseUntilStopped)
{
    PgServer server;
    ASSERT_TRUE(server.ok()) << server.error().toStdString();
    QTemporaryDir dir;
    const quint16 port = freeUdpPort();
    SimProcess auv;
    auv.start({u"--id"_s, u"0x1f"_s, u"--name"_s, u"lauv-sim-1"_s, u"--port"_s, u"16174"_s, u"--console"_s, u"127.0.0.1:%1"_s.arg(port)});
    QProcess logd;
    logd.setProcessChannelMode(QProcess::MergedChannels);
    QByteArray output;
    QObject::connect(&logd, &QProcess::readyRead, [&] { output += logd.readAll(); });
    logd.start(programPath(u"neptus-logd"_s), {u"--imc-port"_s, QString::number(port), u"--imc-discovery"_s, u"off"_s,
                                               u"--imc-peer"_s, u"127.0.0.1:16174"_s, u"--log-dir"_s, dir.filePath(u"logs"_s),
                                               u"--database"_s, server.url(), u"--name"_s, u"ops-room"_s});
    ASSERT_TRUE(logd.waitForStarted(5000));
    const db::Location location = *db::Location::parse(server.url());
    ASSERT_TRUE(QTest::qWaitFor([&] { return rowsOf(location, db::Table::Position, {}) >= 6; }, 15000)) << output.constData();
    logd.terminate(); // SIGTERM: it stops cleanly, writing what it queued
    ASSERT_TRUE(logd.waitForFinished(10000));
    EXPECT_EQ(logd.exitStatus(), QProcess::NormalExit);
    EXPECT_EQ(logd.exitCode(), 0) << output.constData();
    EXPECT_TRUE(output.contains("neptus-logd: recording in")) << output.constData();
    EXPECT_TRUE(output.contains("neptus-logd: stopping")) << output.constData();
    auto reader = db::Reader::open(location);
    ASSERT_TRUE(reader.has_value());
    const auto sessions = (*reader)->sessions();
    ASSERT_EQ(sessions->size(), 1u);
    EXPECT_EQ(sessions->front().console, u"ops-room"_s);
    EXPECT_TRUE(sessions->front().program.startsWith(u"neptus-logd"_s));
    const auto systems = (*reader)->systems();
    ASSERT_EQ(systems->size(), 1u);
    EXPECT_EQ(systems->front().name, u"lauv-sim-1"_s);
    const auto logs = (*reader)->logs();
    ASSERT_EQ(logs->size(), 1u);
    EXPECT_GT(logs->front().packets, 10);
    EXPECT_TRUE(QFile::exists(logs->front().folder + u"/Data.lsf"_s)) << logs->front().folder.toStdString();
}
