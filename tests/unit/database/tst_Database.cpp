// The operation's database: the same tests against the SQLite default and a
// real PostgreSQL server (tests/common/PgServer.h) — every table written and
// read back, upserts, migrations, two writers at once, an outage with the
// rows kept on disk and written when the server returns, a crash during an
// outage, TimescaleDB hypertables.
#include "database/Database.h"

#include "PgServer.h"
#include "SmallDisk.h"

#include <QMutex>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QThread>

#include <gtest/gtest.h>

#include <thread>

using namespace neptus;
using namespace neptus::db;
using namespace Qt::StringLiterals;

namespace {

Row position(const QString &system, qint64 ms, double lat)
{
    return {Table::Position, {ms, system, 0x1f, lat, -8.7, 2.5, 10.0, 1.57, 1.2}};
}

std::vector<Row> positions(const QString &system, qint64 from, int n)
{
    std::vector<Row> rows;
    for (int i = 0; i < n; ++i)
        rows.push_back(position(system, from + i * 500, 41.0 + i * 1e-6));
    return rows;
}

Writer::Options options(const QString &spool, const QString &console = u"console-a"_s)
{
    Writer::Options o;
    o.spoolFolder = spool;
    o.console = console;
    o.host = u"test-host"_s;
    o.program = u"tst_database"_s;
    o.flushMs = 50;
    o.retryMs = 100;
    return o;
}

// Both engines run every test: SQLite in a file, PostgreSQL in a server of the test's own.
class Engines : public ::testing::TestWithParam<Location::Engine>
{
protected:
    void SetUp() override
    {
        if (GetParam() == Location::Postgres) {
            server = std::make_unique<test::PgServer>();
            ASSERT_TRUE(server->ok()) << server->error().toStdString();
            text = server->url();
        } else {
            text = dir.filePath(u"operation.db"_s);
        }
        location = *Location::parse(text);
    }
    QTemporaryDir dir;
    std::unique_ptr<test::PgServer> server;
    QString text;
    Location location;
};

} // namespace

TEST(DatabaseLocation, AddressesAreReadOrRefusedWithTheReason)
{
    auto pg = Location::parse(u"postgresql://ops:secret@10.0.0.5:5433/operation?sslmode=require"_s);
    ASSERT_TRUE(pg.has_value()) << pg.error().toStdString();
    EXPECT_EQ(pg->engine, Location::Postgres);
    EXPECT_EQ(pg->user, u"ops"_s);
    EXPECT_EQ(pg->password, u"secret"_s);
    EXPECT_EQ(pg->host, u"10.0.0.5"_s);
    EXPECT_EQ(pg->port, 5433);
    EXPECT_EQ(pg->database, u"operation"_s);
    EXPECT_EQ(pg->options, u"sslmode=require"_s);
    EXPECT_FALSE(pg->display().contains(u"secret"_s));
    auto socket = Location::parse(u"postgresql://neptus@/ops?host=/run/pg"_s);
    ASSERT_TRUE(socket.has_value());
    EXPECT_EQ(socket->host, u"/run/pg"_s);
    auto file = Location::parse(u"sqlite:/data/ops.db"_s);
    ASSERT_TRUE(file.has_value());
    EXPECT_EQ(file->engine, Location::Sqlite);
    EXPECT_EQ(file->file, u"/data/ops.db"_s);
    EXPECT_EQ(Location::parse(u"/data/ops.db"_s)->file, u"/data/ops.db"_s);

    EXPECT_NE(Location::parse(u"postgresql://neptus@host"_s).error().indexOf(u"names no database"_s), -1);
    EXPECT_NE(Location::parse(u"postgresql://h/db?colour=red"_s).error().indexOf(u"unknown parameter 'colour'"_s), -1);
    EXPECT_NE(Location::parse(u"postgresql://h/db?port=99999"_s).error().indexOf(u"not a port"_s), -1);
    EXPECT_NE(Location::parse(u"mysql://h/db"_s).error().indexOf(u"only postgresql://"_s), -1);
    EXPECT_FALSE(Location::parse(u"  "_s).has_value());
}

TEST_P(Engines, EveryKindOfRecordIsWrittenAndReadBack)
{
    const QString tricky = u"a \"quoted\" \\ back,slash {brace} NULL ção ✓ 'single'"_s;
    {
        Writer writer(location, options(dir.filePath(u"spool"_s)));
        writer.write(Row{Table::System, {0x1f, u"lauv-sim-1"_s, u"UUV"_s, 1000, 2000}});
        writer.write(Row{Table::System, {0x1f, u"lauv-sim-1"_s, QString(), 500, 1500}}); // earlier first, same key: merged
        writer.write(positions(u"lauv-sim-1"_s, 1000, 20));
        writer.write(Row{Table::Alarm, {1200, u"systems/lauv-sim-1/Navigation"_s, u"Error"_s, u"raised"_s, u"no fix"_s}});
        writer.write(Row{Table::Alarm, {1300, u"systems/lauv-sim-1/Navigation"_s, u"Error"_s, u"acknowledged"_s, tricky}});
        writer.write(Row{Table::PlanEvent, {1400, u"lauv-sim-1"_s, u"survey"_s, u"started"_s, u"goto1"_s, QString()}});
        writer.write(Row{Table::LogBook, {1500, u"lauv-sim-1"_s, u"ERROR"_s, u"Navigation"_s, u"no fix"_s}});
        writer.write(Row{Table::Log, {u"/logs/20261124/120000-Default"_s, 1000, 2000, 300, 12000}});
        writer.write(Row{Table::Log, {u"/logs/20261124/120000-Default"_s, 1000, 3000, 450, 18000}}); // grows
        ASSERT_TRUE(writer.flush());
        const Status status = writer.status();
        EXPECT_TRUE(status.connected) << status.problem.toStdString();
        EXPECT_TRUE(status.problem.isEmpty()) << status.problem.toStdString();
        EXPECT_EQ(status.spooled, 0);
    }
    auto reader = Reader::open(location);
    ASSERT_TRUE(reader.has_value()) << reader.error().toStdString();
    Reader &r = **reader;
    const auto systems = r.systems();
    ASSERT_TRUE(systems.has_value()) << systems.error().toStdString();
    ASSERT_EQ(systems->size(), 1u);
    EXPECT_EQ(systems->front().name, u"lauv-sim-1"_s);
    EXPECT_EQ(systems->front().kind, u"UUV"_s);
    EXPECT_EQ(systems->front().firstMs, 500);
    EXPECT_EQ(systems->front().lastMs, 2000);
    const auto track = r.track(u"lauv-sim-1"_s, 2000, 5000);
    ASSERT_TRUE(track.has_value()) << track.error().toStdString();
    ASSERT_EQ(track->size(), 7u); // 2000, 2500 ... 5000
    EXPECT_EQ(track->front().ms, 2000);
    EXPECT_DOUBLE_EQ(track->front().lat, 41.0 + 2 * 1e-6);
    EXPECT_DOUBLE_EQ(track->front().lon, -8.7);
    EXPECT_DOUBLE_EQ(track->front().depth, 2.5);
    EXPECT_DOUBLE_EQ(track->front().heading, 1.57);
    const auto alarms = r.alarms(0, 10000);
    ASSERT_TRUE(alarms.has_value());
    ASSERT_EQ(alarms->size(), 2u);
    EXPECT_EQ(alarms->at(0).event, u"raised"_s);
    EXPECT_EQ(alarms->at(1).event, u"acknowledged"_s);
    EXPECT_EQ(alarms->at(1).message, tricky) << "text comes back as written, whatever it holds";
    EXPECT_EQ(alarms->at(0).console, u"console-a"_s);
    const auto plans = r.planEvents(0, 10000);
    ASSERT_TRUE(plans.has_value());
    ASSERT_EQ(plans->size(), 1u);
    EXPECT_EQ(plans->front().plan, u"survey"_s);
    EXPECT_EQ(plans->front().maneuver, u"goto1"_s);
    const auto book = r.logBook(0, 10000);
    ASSERT_TRUE(book.has_value());
    ASSERT_EQ(book->size(), 1u);
    EXPECT_EQ(book->front().text, u"no fix"_s);
    const auto logs = r.logs();
    ASSERT_TRUE(logs.has_value());
    ASSERT_EQ(logs->size(), 1u);
    EXPECT_EQ(logs->front().endMs, 3000);
    EXPECT_EQ(logs->front().packets, 450);
    EXPECT_EQ(logs->front().console, u"console-a"_s);
    const auto sessions = r.sessions();
    ASSERT_TRUE(sessions.has_value());
    ASSERT_EQ(sessions->size(), 1u);
    EXPECT_EQ(sessions->front().host, u"test-host"_s);
    EXPECT_GE(sessions->front().lastMs, sessions->front().startMs);
}

// Issue #38: the review's session list: each session with the systems it kept positions of, its
// plan runs and how each ended (a run with no end yet is "running"), and its logs; other
// sessions' rows are not theirs.
TEST_P(Engines, EachSessionIsSummarisedWithItsSystemsPlanRunsAndLogs)
{
    QString first;
    {
        Writer writer(location, options(dir.filePath(u"spool-a"_s), u"ops-a"_s));
        first = writer.session();
        writer.write(positions(u"lauv-sim-1"_s, 1000, 3));
        writer.write(positions(u"boat-1"_s, 1000, 3));
        writer.write(Row{Table::PlanEvent, {1100, u"lauv-sim-1"_s, u"survey"_s, u"sent"_s, QString(), QString()}});
        writer.write(Row{Table::PlanEvent, {1200, u"lauv-sim-1"_s, u"survey"_s, u"started"_s, u"goto1"_s, QString()}});
        writer.write(Row{Table::PlanEvent, {1300, u"lauv-sim-1"_s, u"survey"_s, u"maneuver"_s, u"rows2"_s, u"50 %"_s}});
        writer.write(Row{Table::PlanEvent, {1400, u"lauv-sim-1"_s, u"survey"_s, u"failed"_s, u"rows2"_s, u"aborted"_s}});
        writer.write(Row{Table::PlanEvent, {1500, u"boat-1"_s, u"patrol"_s, u"started"_s, u"go"_s, QString()}});
        writer.write(Row{Table::Log, {u"/logs/a"_s, 1000, 2000, 300, 12000}});
        ASSERT_TRUE(writer.flush());
    }
    {
        Writer writer(location, options(dir.filePath(u"spool-b"_s), u"ops-b"_s));
        writer.write(positions(u"lauv-sim-2"_s, 5000, 2));
        writer.write(Row{Table::PlanEvent, {5100, u"lauv-sim-2"_s, u"survey"_s, u"started"_s, u"goto1"_s, QString()}});
        writer.write(Row{Table::PlanEvent, {5200, u"lauv-sim-2"_s, u"survey"_s, u"completed"_s, u"goto1"_s, QString()}});
        ASSERT_TRUE(writer.flush());
    }
    auto reader = Reader::open(location);
    ASSERT_TRUE(reader.has_value()) << reader.error().toStdString();
    const auto summaries = (*reader)->sessionSummaries();
    ASSERT_TRUE(summaries.has_value()) << summaries.error().toStdString();
    ASSERT_EQ(summaries->size(), 2u);
    const auto &a = summaries->at(0), &b = summaries->at(1);
    EXPECT_EQ(a.session.session, first);
    EXPECT_EQ(a.session.console, u"ops-a"_s);
    EXPECT_EQ(a.systems, (QStringList{u"boat-1"_s, u"lauv-sim-1"_s}));
    EXPECT_EQ(a.runs, (QStringList{u"survey: failed"_s, u"patrol: running"_s}));
    ASSERT_EQ(a.logs.size(), 1u);
    EXPECT_EQ(a.logs[0].folder, u"/logs/a"_s);
    EXPECT_EQ(b.session.console, u"ops-b"_s);
    EXPECT_EQ(b.systems, QStringList{u"lauv-sim-2"_s});
    EXPECT_EQ(b.runs, QStringList{u"survey: completed"_s});
    EXPECT_TRUE(b.logs.empty());
}

// The session list reads which systems a session kept positions of from
// session_systems (schema version 2), not by scanning every position: a
// database written by a console before it (version 1) gets the table filled
// from its positions when it is first opened.
TEST_P(Engines, AVersion1DatabaseGetsItsSessionsSystemsOnceWhenOpened)
{
    {
        Writer writer(location, options(dir.filePath(u"spool-a"_s), u"ops-a"_s));
        writer.write(positions(u"lauv-sim-1"_s, 1000, 3));
        writer.write(positions(u"boat-1"_s, 1000, 3));
        ASSERT_TRUE(writer.flush());
    }
    {
        // As a version-1 console left it: no session_systems.
        QSqlDatabase db = QSqlDatabase::addDatabase(GetParam() == Location::Postgres ? u"QPSQL"_s : u"QSQLITE"_s, u"raw"_s);
        db.setDatabaseName(GetParam() == Location::Postgres ? u"neptus"_s : location.file);
        db.setHostName(location.host);
        db.setUserName(location.user);
        ASSERT_TRUE(db.open());
        QSqlQuery query(db);
        ASSERT_TRUE(query.exec(u"SELECT COUNT(*) FROM session_systems"_s) && query.next());
        EXPECT_EQ(query.value(0).toInt(), 2) << "the writer noted each system once";
        ASSERT_TRUE(query.exec(u"DROP TABLE session_systems"_s));
        ASSERT_TRUE(query.exec(u"DELETE FROM schema_version WHERE version > 1"_s));
        db.close();
    }
    QSqlDatabase::removeDatabase(u"raw"_s);
    auto reader = Reader::open(location);
    ASSERT_TRUE(reader.has_value()) << reader.error().toStdString();
    const auto summaries = (*reader)->sessionSummaries();
    ASSERT_TRUE(summaries.has_value()) << summaries.error().toStdString();
    ASSERT_EQ(summaries->size(), 1u);
    EXPECT_EQ(summaries->front().systems, (QStringList{u"boat-1"_s, u"lauv-sim-1"_s}));
}

TEST_P(Engines, TwoWritersAtOnceKeepEveryRowOnce)
{
    constexpr int perWriter = 20000;
    auto writeAll = [&](const QString &console, const QString &system) {
        Writer writer(location, options(dir.filePath(u"spool-"_s + console), console));
        for (int batch = 0; batch < 20; ++batch) {
            writer.write(positions(system, batch * 1'000'000, perWriter / 20));
            QThread::msleep(5);
        }
        EXPECT_TRUE(writer.flush()) << writer.status().problem.toStdString();
        EXPECT_EQ(writer.status().written, perWriter + 1); // + the session row
    };
    std::thread a(writeAll, u"console-a"_s, u"auv-a"_s), b(writeAll, u"console-b"_s, u"auv-b"_s);
    a.join();
    b.join();
    auto reader = Reader::open(location);
    ASSERT_TRUE(reader.has_value()) << reader.error().toStdString();
    EXPECT_EQ(*(*reader)->count(Table::Position), 2 * perWriter);
    EXPECT_EQ((*reader)->sessions()->size(), 2u);
}

TEST_P(Engines, ANewerSchemaIsRefusedWithTheReason)
{
    {
        auto reader = Reader::open(location);
        ASSERT_TRUE(reader.has_value()) << reader.error().toStdString();
    }
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(GetParam() == Location::Postgres ? u"QPSQL"_s : u"QSQLITE"_s, u"raw"_s);
        db.setDatabaseName(GetParam() == Location::Postgres ? u"neptus"_s : location.file);
        db.setHostName(location.host);
        db.setUserName(location.user);
        ASSERT_TRUE(db.open());
        ASSERT_TRUE(QSqlQuery(db).exec(u"INSERT INTO schema_version (version) VALUES (99)"_s));
        db.close();
    }
    QSqlDatabase::removeDatabase(u"raw"_s);
    auto reader = Reader::open(location);
    ASSERT_FALSE(reader.has_value());
    EXPECT_NE(reader.error().indexOf(u"version 99, newer than this program's"_s), -1) << reader.error().toStdString();
}

INSTANTIATE_TEST_SUITE_P(Database, Engines, ::testing::Values(Location::Sqlite, Location::Postgres),
                         [](const auto &info) { return info.param == Location::Sqlite ? "SQLite" : "PostgreSQL"; });

TEST(DatabasePostgres, AnOutageIsBridgedOnDiskAndNothingIsLostOrDoubled)
{
    test::PgServer server;
    ASSERT_TRUE(server.ok()) << server.error().toStdString();
    QTemporaryDir dir;
    const Location location = *Location::parse(server.url());
    Writer writer(location, options(dir.filePath(u"spool"_s)));
    std::vector<Status> seen;
    QMutex seenMutex;
    writer.setProblemHandler([&](const Status &s) { QMutexLocker lock(&seenMutex); seen.push_back(s); });
    writer.write(positions(u"auv"_s, 0, 1000));
    ASSERT_TRUE(writer.flush());

    ASSERT_TRUE(server.stop());
    for (int i = 1; i <= 10; ++i) { // 2.5 s of writing into the outage
        writer.write(positions(u"auv"_s, i * 1'000'000, 500));
        QThread::msleep(250);
    }
    writer.flush(500);
    const Status during = writer.status();
    EXPECT_FALSE(during.connected);
    EXPECT_FALSE(during.problem.isEmpty());
    EXPECT_EQ(during.spooled, 5000) << during.problem.toStdString();
    EXPECT_GT(during.spoolBytes, 0);
    EXPECT_EQ(during.lost, 0);

    ASSERT_TRUE(server.start()) << server.log().toStdString();
    writer.write(positions(u"auv"_s, 99'000'000, 10));
    ASSERT_TRUE(writer.flush(15000)) << writer.status().problem.toStdString();
    const Status after = writer.status();
    EXPECT_TRUE(after.connected);
    EXPECT_TRUE(after.problem.isEmpty()) << after.problem.toStdString();
    EXPECT_EQ(after.spooled, 0);
    auto reader = Reader::open(location);
    ASSERT_TRUE(reader.has_value()) << reader.error().toStdString();
    EXPECT_EQ(*(*reader)->count(Table::Position), 1000 + 5000 + 10);
    const auto track = (*reader)->track(u"auv"_s, 0, 100'000'000);
    ASSERT_TRUE(track.has_value());
    EXPECT_TRUE(std::is_sorted(track->begin(), track->end(), [](auto &a, auto &b) { return a.ms < b.ms; }));
    QMutexLocker lock(&seenMutex);
    EXPECT_TRUE(std::any_of(seen.begin(), seen.end(), [](const Status &s) { return !s.connected && !s.problem.isEmpty(); }));
    ASSERT_FALSE(seen.empty()); // down, then up again
    EXPECT_TRUE(seen.back().connected);
}

TEST(DatabasePostgres, RowsSpooledByAConsoleThatDiedAreWrittenByTheNextOne)
{
    test::PgServer server;
    ASSERT_TRUE(server.ok()) << server.error().toStdString();
    QTemporaryDir dir;
    const Location location = *Location::parse(server.url());
    ASSERT_TRUE(server.stop());
    {
        Writer writer(location, options(dir.filePath(u"spool"_s)));
        writer.write(positions(u"auv"_s, 0, 300));
        writer.flush(300);
        EXPECT_EQ(writer.status().spooled, 300 + 1); // + the session row
    } // closes during the outage: its rows stay on disk
    ASSERT_TRUE(server.start());
    Writer next(location, options(dir.filePath(u"spool"_s), u"console-a-again"_s));
    ASSERT_TRUE(next.flush(15000)) << next.status().problem.toStdString();
    auto reader = Reader::open(location);
    ASSERT_TRUE(reader.has_value());
    EXPECT_EQ(*(*reader)->count(Table::Position), 300);
    EXPECT_EQ((*reader)->sessions()->size(), 2u);
    EXPECT_TRUE(QDir(dir.filePath(u"spool"_s)).entryList(QDir::Dirs | QDir::NoDotAndDotDot).size() <= 1);
}

TEST(DatabasePostgres, ASpoolPastItsLimitDropsTheOldestAndSaysHowMany)
{
    test::PgServer server;
    ASSERT_TRUE(server.ok()) << server.error().toStdString();
    ASSERT_TRUE(server.stop());
    QTemporaryDir dir;
    Writer::Options o = options(dir.filePath(u"spool"_s));
    o.spoolLimitBytes = 200 * 1024;
    Writer writer(*Location::parse(server.url()), o);
    for (int i = 0; i < 20; ++i) {
        writer.write(positions(u"auv"_s, i * 1'000'000, 200));
        writer.flush(0);
    }
    const Status status = writer.status();
    EXPECT_GT(status.lost, 0);
    EXPECT_LE(status.spoolBytes, o.spoolLimitBytes);
    EXPECT_EQ(status.lost + status.spooled, 20 * 200 + 1); // + the session row
    EXPECT_NE(status.problem.indexOf(u"spool is full"_s), -1) << status.problem.toStdString();
}

// The spool on a full filesystem (ENOSPC, the sandbox's small disk for the
// spool) while the server is down: the problem says so and counts what could
// not be kept; nothing spooled before is damaged; once there is room rows are
// spooled again, and all that was spooled reaches the server when it is back.
TEST(DatabasePostgres, ASpoolOnAFullDiskSaysSoKeepsWhatItHadAndCarriesOnWhenThereIsRoom)
{
    const QString disk = test::smallDisk(u"spool"_s);
    if (disk.isEmpty())
        GTEST_SKIP() << neptus::test::noSmallDisk;
    test::PgServer server;
    ASSERT_TRUE(server.ok()) << server.error().toStdString();
    const Location location = *Location::parse(server.url());
    ASSERT_TRUE(server.stop());
    QTemporaryDir dir(disk + u"/spool-XXXXXX"_s);
    ASSERT_TRUE(dir.isValid());
    Writer writer(location, options(dir.filePath(u"spool"_s)));
    writer.write(positions(u"auv"_s, 0, 100));
    writer.flush(0);
    ASSERT_EQ(writer.status().spooled, 100 + 1) << writer.status().problem.toStdString(); // + the session row
    test::DiskFiller filler(disk);
    filler.fill(0);
    writer.write(positions(u"auv"_s, 1'000'000, 200));
    writer.flush(0);
    Status full = writer.status();
    EXPECT_EQ(full.lost, 200);
    EXPECT_EQ(full.spooled, 101) << "what was spooled before is kept";
    EXPECT_TRUE(full.problem.contains(u"No space left on device"_s)) << full.problem.toStdString();
    EXPECT_TRUE(full.problem.contains(u"200 rows lost"_s)) << full.problem.toStdString();
    filler.free();
    writer.write(positions(u"auv"_s, 2'000'000, 50));
    writer.flush(0);
    EXPECT_EQ(writer.status().spooled, 101 + 50);
    ASSERT_TRUE(server.start()) << server.log().toStdString();
    ASSERT_TRUE(writer.flush(15000)) << writer.status().problem.toStdString();
    EXPECT_TRUE(writer.status().problem.isEmpty()) << writer.status().problem.toStdString();
    auto reader = Reader::open(location);
    ASSERT_TRUE(reader.has_value()) << reader.error().toStdString();
    EXPECT_EQ(*(*reader)->count(Table::Position), 100 + 50) << "every row spooled arrives, none damaged";
}

TEST(DatabasePostgres, TimeSeriesAreHypertablesWhenTimescaleDbIsThere)
{
    test::PgServer server;
    ASSERT_TRUE(server.ok()) << server.error().toStdString();
    if (!server.timescale())
        GTEST_SKIP() << "TimescaleDB is not installed (package postgresql-17-timescaledb)";
    {
        Writer writer(*Location::parse(server.url()), options({}));
        writer.write(positions(u"auv"_s, 0, 10));
        ASSERT_TRUE(writer.flush()) << writer.status().problem.toStdString();
    }
    QSqlDatabase db = QSqlDatabase::addDatabase(u"QPSQL"_s, u"timescale"_s);
    db.setHostName(server.socketDir());
    db.setUserName(u"neptus"_s);
    db.setDatabaseName(u"neptus"_s);
    ASSERT_TRUE(db.open());
    QSqlQuery query(db);
    ASSERT_TRUE(query.exec(u"SELECT hypertable_name FROM timescaledb_information.hypertables ORDER BY 1"_s));
    QStringList tables;
    while (query.next())
        tables.append(query.value(0).toString());
    EXPECT_EQ(tables, (QStringList{u"alarms"_s, u"logbook"_s, u"plan_events"_s, u"positions"_s}));
    query = QSqlQuery();
    db.close();
    db = QSqlDatabase();
    QSqlDatabase::removeDatabase(u"timescale"_s);
}
