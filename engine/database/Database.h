#pragma once

#include <QObject>
#include <QString>
#include <QStringList>
#include <QVariantList>

#include <array>
#include <expected>
#include <functional>
#include <memory>
#include <vector>

namespace neptus::db {

// Where the operation's database is: a SQLite file (the default, beside the
// logs) or a PostgreSQL server that many consoles write to at once.
struct Location
{
    enum Engine { Sqlite, Postgres };
    Engine engine = Sqlite;
    QString file;            // SQLite
    QString host;            // PostgreSQL: a name, an address, or a Unix socket folder ("/run/...")
    int port = 5432;
    QString user, password, database, options;

    // "postgresql://user:password@host:port/name?host=/socket/dir&sslmode=require",
    // "sqlite:/path/file.db" or a plain file path. An error names what is wrong.
    static std::expected<Location, QString> parse(const QString &text);
    // For messages and the status line: no password.
    QString display() const;
};

// The tables, one per kind of record; every row of a time series carries the
// writing session and a number that session gives it, so a batch written
// twice (an answer lost with the connection) is kept once.
enum class Table { Session, System, Position, Alarm, PlanEvent, LogBook, Log };

struct Row
{
    Table table = Table::Position;
    QVariantList values; // in the order of columns(table), without session and seq
};

// The columns a caller fills for each table (session and seq are the writer's).
const QStringList &columns(Table table);

// A position of a system at a moment (the console keeps a few per second).
struct TrackPoint
{
    qint64 ms = 0;
    double lat = 0, lon = 0, depth = 0, altitude = -1, heading = 0, speed = 0;
};

struct Status
{
    bool connected = false;
    qint64 written = 0;   // rows the database holds from this writer
    std::array<qint64, 7> queued{}; // rows given to write(), by Table, since the start
    qint64 pending = 0;   // rows queued in memory
    qint64 spooled = 0;   // rows waiting on disk for the server
    qint64 spoolBytes = 0;
    qint64 lost = 0;      // rows dropped because the spool was full
    QString problem;      // the last connection or write error, empty when all is well
};

// Writes an operation's records to a database on a thread of its own:
// write() only queues (any thread); every 250 ms the queue goes in one
// transaction, rows of a table in multi-row INSERTs. When the server cannot
// be reached the rows go to spool files on disk (bounded: the oldest are
// dropped, and counted, past the limit) and are written, in order, when it
// answers again. The schema is made or brought up to date on connecting
// (versioned migrations, one writer at a time), with TimescaleDB hypertables
// for the time series when the PostgreSQL server has the extension.
class Writer : public QObject
{
    Q_OBJECT
public:
    struct Options
    {
        QString spoolFolder;                     // where rows wait during an outage
        qint64 spoolLimitBytes = 512ll << 20;
        int flushMs = 250;
        int retryMs = 1000;                      // between attempts to reach the server
        QString console;                         // who writes (the sessions table)
        QString host, program;
    };
    Writer(Location location, Options options, QObject *parent = nullptr);
    ~Writer() override; // writes what is queued (or spools it) before returning

    void write(Row row);
    void write(std::vector<Row> rows);
    // This writer's session id (a new UUID each run).
    QString session() const;
    Status status() const;
    // Writes what is queued now, and keeps trying (the spool too) until all
    // of it is in the database: true then, false after `timeoutMs` (the rest
    // is spooled). flush(0) tries once.
    bool flush(int timeoutMs = 30000);
    // Called (on the writer's thread) when status().problem or connected change.
    void setProblemHandler(std::function<void(const Status &)> handler);

private:
    struct Worker;
    std::unique_ptr<Worker> m_worker;
};

// Questions for the database (Review, the web page); a connection of its own,
// used on the thread that made it.
class Reader
{
public:
    static std::expected<std::unique_ptr<Reader>, QString> open(const Location &location);
    ~Reader();

    struct System { int imcId = 0; QString name, kind; qint64 firstMs = 0, lastMs = 0; };
    struct AlarmRecord { qint64 ms = 0; QString console, origin, level, event, message; };
    struct PlanRecord { qint64 ms = 0; QString console, system, plan, event, maneuver, detail; };
    struct LogBookRecord { qint64 ms = 0; QString system, type, context, text; };
    struct SessionRecord { QString session, console, host, program; qint64 startMs = 0, lastMs = 0; };
    struct LogRecord { QString session, console, folder; qint64 beginMs = 0, endMs = 0, packets = 0, bytes = 0; };

    std::expected<std::vector<System>, QString> systems();
    // A system's positions in [fromMs, toMs], oldest first (of any console: one
    // point per moment).
    std::expected<std::vector<TrackPoint>, QString> track(const QString &system, qint64 fromMs, qint64 toMs);
    std::expected<std::vector<AlarmRecord>, QString> alarms(qint64 fromMs, qint64 toMs);
    std::expected<std::vector<PlanRecord>, QString> planEvents(qint64 fromMs, qint64 toMs);
    std::expected<std::vector<LogBookRecord>, QString> logBook(qint64 fromMs, qint64 toMs);
    std::expected<std::vector<SessionRecord>, QString> sessions();
    std::expected<std::vector<LogRecord>, QString> logs();
    // Each session with what it did, oldest first: the systems whose positions it
    // kept, its plan runs as "plan: how it ended" ("survey: completed", "survey:
    // running" while no end is known) in order, and its logs.
    struct SessionSummary
    {
        SessionRecord session;
        QStringList systems, runs;
        std::vector<LogRecord> logs;
    };
    std::expected<std::vector<SessionSummary>, QString> sessionSummaries();
    // Rows in a table, or of one writer's session in it.
    std::expected<qint64, QString> count(Table table, const QString &session = {});

private:
    explicit Reader(QString connection);
    QString m_connection;
};

} // namespace neptus::db
