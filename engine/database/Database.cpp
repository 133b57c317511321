#include "database/Database.h"

#include "core/SafeFile.h"

#include <QDataStream>
#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QLockFile>
#include <QMutex>
#include <QSet>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QThread>
#include <QTimer>
#include <QUrl>
#include <QUrlQuery>
#include <QUuid>

#include <atomic>
#include <cmath>

using namespace Qt::StringLiterals;

namespace neptus::db {

std::expected<Location, QString> Location::parse(const QString &text)
{
    Location location;
    const QString trimmed = text.trimmed();
    if (trimmed.isEmpty())
        return std::unexpected(u"no database given"_s);
    if (trimmed.startsWith(u"postgresql://"_s) || trimmed.startsWith(u"postgres://"_s)) {
        const QUrl url(trimmed, QUrl::StrictMode);
        if (!url.isValid())
            return std::unexpected(u"database address '%1' is not a valid URL: %2"_s.arg(trimmed, url.errorString()));
        location.engine = Postgres;
        location.user = url.userName();
        location.password = url.password();
        location.host = url.host();
        location.port = url.port(5432);
        location.database = url.path().mid(1);
        QStringList options;
        for (const auto &[key, value] : QUrlQuery(url).queryItems(QUrl::FullyDecoded)) {
            if (key == u"host"_s)
                location.host = value;
            else if (key == u"port"_s) {
                bool ok = false;
                location.port = value.toInt(&ok);
                if (!ok || location.port <= 0 || location.port > 65535)
                    return std::unexpected(u"database address: port '%1' is not a port number"_s.arg(value));
            } else if (key == u"user"_s)
                location.user = value;
            else if (key == u"sslmode"_s || key == u"sslrootcert"_s || key == u"sslcert"_s || key == u"sslkey"_s
                     || key == u"connect_timeout"_s || key == u"application_name"_s)
                options.append(key + u'=' + value);
            else
                return std::unexpected(u"database address: unknown parameter '%1' (host, port, user, sslmode, sslrootcert, "
                                       "sslcert, sslkey, connect_timeout, application_name)"_s.arg(key));
        }
        if (location.database.isEmpty() || location.database.contains(u'/'))
            return std::unexpected(u"database address '%1' names no database (postgresql://user@host/NAME)"_s.arg(location.display()));
        location.options = options.join(u';');
        return location;
    }
    if (trimmed.contains(u"://"_s))
        return std::unexpected(u"database address '%1': only postgresql:// addresses or SQLite files are understood"_s.arg(trimmed));
    location.file = trimmed.startsWith(u"sqlite:"_s) ? trimmed.mid(7) : trimmed;
    return location;
}

QString Location::display() const
{
    if (engine == Sqlite)
        return u"sqlite:"_s + file;
    const QString where = host.startsWith(u'/') ? u"socket in "_s + host : host + u':' + QString::number(port);
    return u"postgresql://%1@%2/%3"_s.arg(user, where, database);
}

namespace {

struct TableInfo
{
    const char *name;
    QStringList columns;
    bool series; // carries session + seq, written once
    QStringList types; // of the columns, for PostgreSQL's arrays
};

const TableInfo &info(Table table)
{
    static const TableInfo tables[] = {
        {"sessions", {u"console"_s, u"host"_s, u"program"_s, u"started"_s, u"last_seen"_s}, false,
         {u"text"_s, u"text"_s, u"text"_s, u"bigint"_s, u"bigint"_s}},
        {"systems", {u"imc_id"_s, u"name"_s, u"kind"_s, u"first_heard"_s, u"last_heard"_s}, false,
         {u"integer"_s, u"text"_s, u"text"_s, u"bigint"_s, u"bigint"_s}},
        {"positions", {u"t"_s, u"system"_s, u"imc_id"_s, u"lat"_s, u"lon"_s, u"depth"_s, u"altitude"_s, u"heading"_s, u"speed"_s}, true,
         {u"bigint"_s, u"text"_s, u"integer"_s, u"float8"_s, u"float8"_s, u"float8"_s, u"float8"_s, u"float8"_s, u"float8"_s}},
        {"alarms", {u"t"_s, u"origin"_s, u"level"_s, u"event"_s, u"message"_s}, true,
         {u"bigint"_s, u"text"_s, u"text"_s, u"text"_s, u"text"_s}},
        {"plan_events", {u"t"_s, u"system"_s, u"plan"_s, u"event"_s, u"maneuver"_s, u"detail"_s}, true,
         {u"bigint"_s, u"text"_s, u"text"_s, u"text"_s, u"text"_s, u"text"_s}},
        {"logbook", {u"t"_s, u"system"_s, u"type"_s, u"context"_s, u"text"_s}, true,
         {u"bigint"_s, u"text"_s, u"text"_s, u"text"_s, u"text"_s}},
        {"logs", {u"folder"_s, u"began"_s, u"ended"_s, u"packets"_s, u"bytes"_s}, false,
         {u"text"_s, u"bigint"_s, u"bigint"_s, u"bigint"_s, u"bigint"_s}},
    };
    return tables[int(table)];
}

constexpr int tableCount = 7;

// One element of a PostgreSQL array literal ({"a","b"}, {1,2}).
void appendElement(QString &out, const QVariant &value, bool text)
{
    if (value.isNull() || !value.isValid()) {
        out += u"NULL"_s;
    } else if (text) {
        QString s = value.toString();
        s.replace(u'\\', u"\\\\"_s).replace(u'"', u"\\\""_s);
        out += u'"' + s + u'"';
    } else if (value.typeId() == QMetaType::Double || value.typeId() == QMetaType::Float) {
        const double d = value.toDouble();
        out += std::isnan(d) ? u"NaN"_s : std::isinf(d) ? (d > 0 ? u"Infinity"_s : u"-Infinity"_s) : QString::number(d, 'g', 17);
    } else {
        out += QString::number(value.toLongLong());
    }
}

// Version 1: every table. Types both engines take (SQLite reads them by affinity).
const QStringList schemaV1 = {
    u"CREATE TABLE IF NOT EXISTS sessions (session TEXT PRIMARY KEY, console TEXT NOT NULL, host TEXT, program TEXT, "
    "started BIGINT NOT NULL, last_seen BIGINT NOT NULL)"_s,
    u"CREATE TABLE IF NOT EXISTS systems (imc_id INTEGER NOT NULL, name TEXT NOT NULL, kind TEXT, first_heard BIGINT NOT NULL, "
    "last_heard BIGINT NOT NULL, PRIMARY KEY (imc_id, name))"_s,
    u"CREATE TABLE IF NOT EXISTS positions (session TEXT NOT NULL, seq BIGINT NOT NULL, t BIGINT NOT NULL, system TEXT NOT NULL, "
    "imc_id INTEGER, lat DOUBLE PRECISION NOT NULL, lon DOUBLE PRECISION NOT NULL, depth DOUBLE PRECISION, "
    "altitude DOUBLE PRECISION, heading DOUBLE PRECISION, speed DOUBLE PRECISION, PRIMARY KEY (session, seq, t))"_s,
    u"CREATE INDEX IF NOT EXISTS positions_system_t ON positions (system, t)"_s,
    u"CREATE TABLE IF NOT EXISTS alarms (session TEXT NOT NULL, seq BIGINT NOT NULL, t BIGINT NOT NULL, origin TEXT NOT NULL, "
    "level TEXT, event TEXT NOT NULL, message TEXT, PRIMARY KEY (session, seq, t))"_s,
    u"CREATE INDEX IF NOT EXISTS alarms_t ON alarms (t)"_s,
    u"CREATE TABLE IF NOT EXISTS plan_events (session TEXT NOT NULL, seq BIGINT NOT NULL, t BIGINT NOT NULL, system TEXT NOT NULL, "
    "plan TEXT, event TEXT NOT NULL, maneuver TEXT, detail TEXT, PRIMARY KEY (session, seq, t))"_s,
    u"CREATE INDEX IF NOT EXISTS plan_events_t ON plan_events (t)"_s,
    u"CREATE TABLE IF NOT EXISTS logbook (session TEXT NOT NULL, seq BIGINT NOT NULL, t BIGINT NOT NULL, system TEXT NOT NULL, "
    "type TEXT, context TEXT, text TEXT, PRIMARY KEY (session, seq, t))"_s,
    u"CREATE INDEX IF NOT EXISTS logbook_t ON logbook (t)"_s,
    u"CREATE TABLE IF NOT EXISTS logs (session TEXT NOT NULL, folder TEXT NOT NULL, began BIGINT, ended BIGINT, packets BIGINT, "
    "bytes BIGINT, PRIMARY KEY (session, folder))"_s,
};

struct Migration
{
    int version;
    const QStringList *statements;
};
// Version 2: which systems each session kept positions of, for the session
// list (reading it from positions scanned the whole table: 8-13 s for 5.2 M
// rows in SQLite); filled once from positions, then by the writer.
const QStringList schemaV2 = {
    u"CREATE TABLE IF NOT EXISTS session_systems (session TEXT NOT NULL, system TEXT NOT NULL, PRIMARY KEY (session, system))"_s,
    u"INSERT INTO session_systems (session, system) SELECT DISTINCT session, system FROM positions"_s,
};

const Migration migrations[] = {{1, &schemaV1}, {2, &schemaV2}};

QString sqlError(const QSqlError &error)
{
    const QString text = error.text().simplified(); // libpq's lines and tabs, on one line
    return text.isEmpty() ? u"unknown database error"_s : text;
}

std::expected<void, QString> exec(QSqlDatabase &db, const QString &statement)
{
    QSqlQuery query(db);
    if (!query.exec(statement))
        return std::unexpected(sqlError(query.lastError()));
    return {};
}

QString newConnectionName(const char *what)
{
    static std::atomic<int> counter = 0;
    return u"neptus-db-%1-%2"_s.arg(QLatin1StringView(what)).arg(++counter);
}

std::expected<QSqlDatabase, QString> connectTo(const Location &location, const QString &name)
{
    if (!QSqlDatabase::isDriverAvailable(location.engine == Location::Sqlite ? u"QSQLITE"_s : u"QPSQL"_s))
        return std::unexpected(location.engine == Location::Sqlite
                                   ? u"Qt's SQLite driver (QSQLITE) is not installed"_s
                                   : u"Qt's PostgreSQL driver (QPSQL, package libqt6sql6-psql) is not installed"_s);
    QSqlDatabase db = QSqlDatabase::database(name, false);
    if (!db.isValid())
        db = QSqlDatabase::addDatabase(location.engine == Location::Sqlite ? u"QSQLITE"_s : u"QPSQL"_s, name);
    if (location.engine == Location::Sqlite) {
        if (const QString dir = QFileInfo(location.file).absolutePath(); !QDir().mkpath(dir))
            return std::unexpected(u"cannot make the folder %1 for the database"_s.arg(dir));
        db.setDatabaseName(location.file);
        db.setConnectOptions(u"QSQLITE_BUSY_TIMEOUT=10000"_s);
    } else {
        db.setHostName(location.host);
        db.setPort(location.port);
        db.setUserName(location.user);
        db.setPassword(location.password);
        db.setDatabaseName(location.database);
        db.setConnectOptions(location.options.contains(u"connect_timeout"_s) ? location.options
                             : location.options.isEmpty()                    ? u"connect_timeout=3"_s
                                                                             : location.options + u";connect_timeout=3"_s);
    }
    if (!db.open())
        return std::unexpected(u"cannot open %1: %2"_s.arg(location.display(), sqlError(db.lastError())));
    if (location.engine == Location::Postgres)
        if (auto quiet = exec(db, u"SET client_min_messages = warning"_s); !quiet) // no "already exists, skipping"
            return std::unexpected(quiet.error());
    if (location.engine == Location::Sqlite) {
        // Each connection's page cache (the writer's and the readers') is
        // capped at 512 KiB (SQLite's default is 2 MiB): a console writes for
        // hours and reads little, and the operating system caches the file
        // anyway. (Not what grows in a long watch: BENCHMARKS.md, "The
        // console over hours".)
        for (const QString &pragma :
             {u"PRAGMA journal_mode=WAL"_s, u"PRAGMA synchronous=NORMAL"_s, u"PRAGMA cache_size=-512"_s})
            if (auto done = exec(db, pragma); !done)
                return std::unexpected(done.error());
    }
    return db;
}

// Brings the schema to the newest version, one writer at a time (a
// PostgreSQL advisory lock; SQLite's write lock), and makes the time series
// TimescaleDB hypertables where the server has the extension.
std::expected<void, QString> migrate(QSqlDatabase &db, bool postgres)
{
    auto fail = [&](const QString &what, const QString &why) -> std::expected<void, QString> {
        QSqlQuery(db).exec(u"ROLLBACK"_s);
        return std::unexpected(u"%1: %2"_s.arg(what, why));
    };
    if (auto begun = exec(db, postgres ? u"BEGIN"_s : u"BEGIN IMMEDIATE"_s); !begun)
        return fail(u"schema update"_s, begun.error());
    if (postgres)
        if (auto locked = exec(db, u"SELECT pg_advisory_xact_lock(7406257)"_s); !locked)
            return fail(u"schema update"_s, locked.error());
    if (auto made = exec(db, u"CREATE TABLE IF NOT EXISTS schema_version (version INTEGER NOT NULL)"_s); !made)
        return fail(u"schema update"_s, made.error());
    QSqlQuery current(db);
    if (!current.exec(u"SELECT COALESCE(MAX(version), 0) FROM schema_version"_s) || !current.next())
        return fail(u"schema update"_s, sqlError(current.lastError()));
    const int version = current.value(0).toInt();
    const int newest = std::end(migrations)[-1].version;
    if (version > newest)
        return fail(u"schema update"_s, u"the database's schema is version %1, newer than this program's %2: update the program"_s
                                            .arg(version).arg(newest));
    for (const Migration &migration : migrations) {
        if (migration.version <= version)
            continue;
        for (const QString &statement : *migration.statements)
            if (auto done = exec(db, statement); !done)
                return fail(u"schema version %1"_s.arg(migration.version), done.error());
        if (auto noted = exec(db, u"INSERT INTO schema_version (version) VALUES (%1)"_s.arg(migration.version)); !noted)
            return fail(u"schema version %1"_s.arg(migration.version), noted.error());
    }
    if (postgres) {
        // The extension where the server has it (and lets this user make it); without it, plain tables.
        QSqlQuery available(db);
        if (available.exec(u"SELECT 1 FROM pg_available_extensions WHERE name = 'timescaledb' AND installed_version IS NULL"_s)
            && available.next()) {
            exec(db, u"SAVEPOINT timescale"_s);
            if (!exec(db, u"CREATE EXTENSION IF NOT EXISTS timescaledb"_s))
                exec(db, u"ROLLBACK TO SAVEPOINT timescale"_s);
        }
        QSqlQuery timescale(db);
        if (timescale.exec(u"SELECT 1 FROM pg_extension WHERE extname = 'timescaledb'"_s) && timescale.next()) {
            for (const char *table : {"positions", "alarms", "plan_events", "logbook"})
                if (auto made = exec(db, u"SELECT create_hypertable('%1', 't', chunk_time_interval => 86400000::bigint, "
                                          "if_not_exists => TRUE, migrate_data => TRUE)"_s.arg(QLatin1StringView(table)));
                    !made)
                    return fail(u"TimescaleDB hypertable %1"_s.arg(QLatin1StringView(table)), made.error());
        }
    }
    if (auto committed = exec(db, u"COMMIT"_s); !committed)
        return fail(u"schema update"_s, committed.error());
    return {};
}

struct Queued
{
    Table table;
    qint64 seq;
    QVariantList values;
};

// A batch on disk while the server is away: who wrote it, and its rows.
constexpr quint32 spoolMagic = 0x4e515350; // "NQSP"

// A spool file, whole or not at all; an error says why (a full disk: "No space left on device").
std::expected<void, QString> writeSpool(const QString &path, const QString &session, const std::vector<Queued> &rows)
{
    QByteArray bytes;
    QDataStream out(&bytes, QIODevice::WriteOnly);
    out.setVersion(QDataStream::Qt_6_8);
    out << spoolMagic << session << quint32(rows.size());
    for (const Queued &row : rows)
        out << quint8(row.table) << row.seq << row.values;
    return saveFileAtomically(path, bytes);
}

std::expected<std::pair<QString, std::vector<Queued>>, QString> readSpool(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return std::unexpected(file.errorString());
    QDataStream in(&file);
    in.setVersion(QDataStream::Qt_6_8);
    quint32 magic = 0, count = 0;
    QString session;
    in >> magic >> session >> count;
    if (magic != spoolMagic || in.status() != QDataStream::Ok || count > 100'000'000)
        return std::unexpected(u"not a spool file"_s);
    std::vector<Queued> rows;
    rows.reserve(std::min<quint32>(count, 1'000'000));
    for (quint32 i = 0; i < count; ++i) {
        quint8 table = 0;
        Queued row{};
        in >> table >> row.seq >> row.values;
        if (in.status() != QDataStream::Ok || table >= tableCount
            || row.values.size() != info(Table(table)).columns.size())
            return std::unexpected(u"row %1 of %2 is damaged"_s.arg(i + 1).arg(count));
        row.table = Table(table);
        rows.push_back(std::move(row));
    }
    return std::pair{session, std::move(rows)};
}

} // namespace

const QStringList &columns(Table table)
{
    return info(table).columns;
}

struct Writer::Worker : QObject
{
    Location location;
    Options options;
    QString session = QUuid::createUuid().toString(QUuid::WithoutBraces);
    QString connection = newConnectionName("writer");
    QThread thread;
    QTimer *timer = nullptr;

    mutable QMutex mutex;
    std::vector<Queued> queue;
    qint64 nextSeq = 1;
    Status status;
    std::function<void(const Status &)> handler;

    // Writer thread only.
    bool connected = false;
    QElapsedTimer sinceAttempt;
    QString spoolDir; // <spoolFolder>/<session>
    std::unique_ptr<QLockFile> spoolLock;
    qint64 spoolIndex = 0;
    QHash<QString, int> failures; // spool file → failed attempts while connected
    // The spool folder is read when something may wait there: at the start,
    // after this writer spooled, and once a minute (a console that died
    // mid-outage leaves its batches to the next writer on that folder) —
    // not at every flush.
    QElapsedTimer sinceSpoolRead;
    bool spoolDrained = false;

    bool postgres() const { return location.engine == Location::Postgres; }

    void setProblem(const QString &problem)
    {
        std::function<void(const Status &)> call;
        Status now;
        {
            QMutexLocker lock(&mutex);
            if (status.problem == problem && status.connected == connected)
                return;
            status.problem = problem;
            status.connected = connected;
            now = status;
            call = handler;
        }
        if (call)
            call(now);
    }

    void disconnect(const QString &why)
    {
        prepared_.clear();
        connected = false;
        if (QSqlDatabase db = QSqlDatabase::database(connection, false); db.isValid())
            db.close();
        sinceAttempt.restart();
        setProblem(why);
    }

    bool tryConnect()
    {
        if (connected)
            return true;
        if (sinceAttempt.isValid() && sinceAttempt.elapsed() < options.retryMs)
            return false;
        sinceAttempt.restart();
        auto db = connectTo(location, connection);
        if (!db) {
            disconnect(db.error());
            return false;
        }
        if (auto migrated = migrate(*db, postgres()); !migrated) {
            disconnect(u"%1: %2"_s.arg(location.display(), migrated.error()));
            return false;
        }
        connected = true;
        setProblem({});
        return true;
    }

    // Rows of one table in statements of up to `chunk` rows; upserts merged by key first.
    bool insert(QSqlDatabase &db, const QString &rowSession, Table table, std::vector<const Queued *> rows, QString *error)
    {
        const TableInfo &t = info(table);
        QStringList cols = t.columns;
        if (t.series)
            cols = QStringList{u"session"_s, u"seq"_s} + cols;
        else if (table != Table::System)
            cols.prepend(u"session"_s);
        std::vector<Queued> merged; // rows points into it from here on, for keyed tables
        if (!t.series) { // one row per key: the last (sessions, logs) or merged (systems)
            QHash<QString, qsizetype> at;
            for (const Queued *row : rows) {
                const QString key = table == Table::System ? row->values[0].toString() + u'/' + row->values[1].toString()
                                                           : row->values[0].toString();
                const auto found = at.constFind(key);
                if (found == at.cend()) {
                    at.insert(key, qsizetype(merged.size()));
                    merged.push_back(*row);
                } else if (table == Table::System) {
                    QVariantList &v = merged[size_t(*found)].values;
                    if (!row->values[2].toString().isEmpty())
                        v[2] = row->values[2];
                    v[3] = std::min(v[3].toLongLong(), row->values[3].toLongLong());
                    v[4] = std::max(v[4].toLongLong(), row->values[4].toLongLong());
                } else {
                    merged[size_t(*found)] = *row;
                }
            }
            rows.clear();
            for (const Queued &row : merged)
                rows.push_back(&row);
        }
        QString conflict = u" ON CONFLICT DO NOTHING"_s;
        if (table == Table::Session)
            conflict = u" ON CONFLICT (session) DO UPDATE SET last_seen = excluded.last_seen"_s;
        else if (table == Table::Log)
            conflict = u" ON CONFLICT (session, folder) DO UPDATE SET ended = excluded.ended, packets = excluded.packets, "
                       "bytes = excluded.bytes"_s;
        else if (table == Table::System) {
            const QString least = postgres() ? u"LEAST"_s : u"MIN"_s, greatest = postgres() ? u"GREATEST"_s : u"MAX"_s;
            conflict = u" ON CONFLICT (imc_id, name) DO UPDATE SET kind = CASE WHEN excluded.kind <> '' THEN excluded.kind "
                       "ELSE systems.kind END, first_heard = %1(systems.first_heard, excluded.first_heard), "
                       "last_heard = %2(systems.last_heard, excluded.last_heard)"_s.arg(least, greatest);
        }
        if (postgres()) {
            // PostgreSQL: a column of values as one array parameter, unnested into rows (a bind a
            // column instead of a bind a value: the driver quotes and the server parses far less).
            QStringList types = t.types;
            if (t.series)
                types = QStringList{u"text"_s, u"bigint"_s} + types;
            else if (table != Table::System)
                types.prepend(u"text"_s);
            std::shared_ptr<QSqlQuery> &statement = prepared_[int(table)];
            if (!statement) {
                QStringList arrays;
                for (const QString &type : types)
                    arrays.append(u"?::"_s + type + u"[]"_s);
                statement = std::make_shared<QSqlQuery>(db);
                if (!statement->prepare(u"INSERT INTO %1 (%2) SELECT * FROM unnest(%3)%4"_s.arg(QLatin1StringView(t.name), cols.join(u", "_s),
                                                                                               arrays.join(u", "_s), conflict))) {
                    *error = sqlError(statement->lastError());
                    statement.reset();
                    return false;
                }
            }
            constexpr qsizetype chunk = 20000;
            for (qsizetype from = 0; from < qsizetype(rows.size()); from += chunk) {
                const qsizetype to = std::min<qsizetype>(from + chunk, qsizetype(rows.size()));
                for (qsizetype c = 0; c < types.size(); ++c) {
                    const bool text = types[c] == u"text"_s;
                    const qsizetype own = c - (types.size() - t.columns.size()); // index into the row's values
                    QString array = u"{"_s;
                    array.reserve((to - from) * 12);
                    for (qsizetype i = from; i < to; ++i) {
                        if (i > from)
                            array += u',';
                        const Queued &row = *rows[size_t(i)];
                        appendElement(array, own >= 0 ? row.values[own] : (c == 0 ? QVariant(rowSession) : QVariant(row.seq)), text);
                    }
                    array += u'}';
                    statement->bindValue(int(c), array);
                }
                if (!statement->exec()) {
                    *error = sqlError(statement->lastError());
                    return false;
                }
            }
            return true;
        }
        const QString one = u'(' + QStringList(cols.size(), u"?"_s).join(u',') + u')';
        const qsizetype chunk = std::max<qsizetype>(1, 4000 / cols.size());
        for (qsizetype from = 0; from < qsizetype(rows.size()); from += chunk) {
            const qsizetype n = std::min<qsizetype>(chunk, qsizetype(rows.size()) - from);
            // Full chunks reuse one prepared statement per table (parsed once per connection).
            const QString sql = u"INSERT INTO %1 (%2) VALUES %3%4"_s.arg(QLatin1StringView(t.name), cols.join(u", "_s),
                                                                          QStringList(n, one).join(u','), conflict);
            QSqlQuery adHoc(db);
            QSqlQuery *statement = &adHoc;
            if (n == chunk) {
                std::shared_ptr<QSqlQuery> &kept = prepared_[int(table)];
                if (!kept) {
                    kept = std::make_shared<QSqlQuery>(db);
                    if (!kept->prepare(sql)) {
                        *error = sqlError(kept->lastError());
                        kept.reset();
                        return false;
                    }
                }
                statement = kept.get();
            } else if (!adHoc.prepare(sql)) {
                *error = sqlError(adHoc.lastError());
                return false;
            }
            QSqlQuery &query = *statement;
            for (qsizetype i = from; i < from + n; ++i) {
                const Queued &row = *rows[size_t(i)];
                if (table != Table::System)
                    query.addBindValue(rowSession);
                if (t.series)
                    query.addBindValue(row.seq);
                for (const QVariant &value : row.values)
                    query.addBindValue(value);
            }
            if (!query.exec()) {
                *error = sqlError(query.lastError());
                return false;
            }
        }
        return true;
    }
    QHash<int, std::shared_ptr<QSqlQuery>> prepared_; // by table, for full chunks; cleared with the connection

    // The systems these positions are of, in session_systems (once each: the
    // pairs committed are remembered; `fresh` gets those noted now).
    QSet<std::pair<QString, QString>> notedSystems_;
    bool noteSessionSystems(QSqlDatabase &db, const QString &rowSession, const std::vector<const Queued *> &positions,
                            QList<std::pair<QString, QString>> &fresh, QString *error)
    {
        const qsizetype systemColumn = info(Table::Position).columns.indexOf(u"system"_s);
        for (const Queued *row : positions) {
            const std::pair pair{rowSession, row->values[systemColumn].toString()};
            if (!notedSystems_.contains(pair) && !fresh.contains(pair))
                fresh.append(pair);
        }
        for (const auto &[session, system] : fresh) {
            QSqlQuery note(db);
            note.prepare(u"INSERT INTO session_systems (session, system) VALUES (?, ?) ON CONFLICT DO NOTHING"_s);
            note.addBindValue(session);
            note.addBindValue(system);
            if (!note.exec()) {
                *error = sqlError(note.lastError());
                return false;
            }
        }
        return true;
    }

    // One transaction: every row, or none.
    bool writeRows(const QString &rowSession, const std::vector<Queued> &rows, QString *error)
    {
        QSqlDatabase db = QSqlDatabase::database(connection, false);
        if (!db.transaction()) {
            *error = sqlError(db.lastError());
            return false;
        }
        std::vector<const Queued *> byTable[tableCount];
        for (const Queued &row : rows)
            byTable[int(row.table)].push_back(&row);
        for (int t = 0; t < tableCount; ++t)
            if (!byTable[t].empty() && !insert(db, rowSession, Table(t), byTable[t], error)) {
                db.rollback();
                return false;
            }
        QList<std::pair<QString, QString>> noted;
        if (!noteSessionSystems(db, rowSession, byTable[int(Table::Position)], noted, error)) {
            db.rollback();
            return false;
        }
        if (!db.commit()) {
            *error = sqlError(db.lastError());
            db.rollback();
            return false;
        }
        for (const auto &pair : noted)
            notedSystems_.insert(pair);
        return true;
    }

    QStringList spoolFiles(const QString &dir) const
    {
        QStringList files = QDir(dir).entryList({u"*.spool"_s}, QDir::Files, QDir::Name);
        for (QString &f : files)
            f = dir + u'/' + f;
        return files;
    }

    void refreshSpoolStatus()
    {
        qint64 rows = 0, bytes = 0;
        for (const QString &file : spoolFiles(spoolDir)) {
            bytes += QFileInfo(file).size();
            rows += QFileInfo(file).completeBaseName().section(u'-', 1, 1).toLongLong();
        }
        QMutexLocker lock(&mutex);
        status.spooled = rows;
        status.spoolBytes = bytes;
    }

    void spool(const std::vector<Queued> &rows)
    {
        if (rows.empty())
            return;
        if (spoolDir.isEmpty()) {
            QMutexLocker lock(&mutex);
            status.lost += qint64(rows.size());
            status.problem = u"the database cannot be reached and there is no spool folder: %1 rows lost"_s.arg(status.lost);
            return;
        }
        QDir().mkpath(spoolDir);
        spoolDrained = false;
        const QString path = u"%1/%2-%3.spool"_s.arg(spoolDir).arg(++spoolIndex, 10, 10, QLatin1Char('0')).arg(rows.size());
        if (const auto written = writeSpool(path, session, rows); !written) {
            QMutexLocker lock(&mutex);
            status.lost += qint64(rows.size());
            status.problem = u"cannot write the spool file %1; %2 rows lost so far"_s.arg(written.error()).arg(status.lost);
            return;
        }
        // Bounded: past the limit the oldest batches go, counted.
        QStringList files = spoolFiles(spoolDir);
        qint64 bytes = 0;
        for (const QString &f : files)
            bytes += QFileInfo(f).size();
        while (bytes > options.spoolLimitBytes && files.size() > 1) {
            const QString oldest = files.takeFirst();
            bytes -= QFileInfo(oldest).size();
            const qint64 dropped = QFileInfo(oldest).completeBaseName().section(u'-', 1, 1).toLongLong();
            QFile::remove(oldest);
            QMutexLocker lock(&mutex);
            status.lost += dropped;
            status.problem = u"the database spool is full (%1 MiB): %2 of the oldest rows dropped"_s
                                 .arg(options.spoolLimitBytes >> 20).arg(status.lost);
        }
        refreshSpoolStatus();
    }

    // Spooled batches, this run's and those a run before left (their lock is free), oldest first.
    bool drainSpool()
    {
        if (options.spoolFolder.isEmpty() || (spoolDrained && sinceSpoolRead.elapsed() < 60000))
            return true;
        spoolDrained = false;
        sinceSpoolRead.restart();
        const QStringList sessions = QDir(options.spoolFolder).entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Time | QDir::Reversed);
        for (const QString &name : sessions) {
            const QString dir = options.spoolFolder + u'/' + name;
            std::unique_ptr<QLockFile> adopted;
            if (dir != spoolDir) {
                adopted = std::make_unique<QLockFile>(dir + u".lock"_s);
                if (!adopted->tryLock(0))
                    continue; // another writer's, still running
            }
            for (const QString &file : spoolFiles(dir)) {
                auto batch = readSpool(file);
                QString error;
                if (!batch) {
                    QFile::rename(file, file + u".bad"_s);
                    setProblem(u"spool file %1 set aside: %2"_s.arg(file, batch.error()));
                    continue;
                }
                if (!writeRows(batch->first, batch->second, &error)) {
                    // A batch the server refuses while it answers is set aside after a few tries.
                    if (++failures[file] >= 5 && QSqlDatabase::database(connection, false).isOpen()
                        && QSqlQuery(QSqlDatabase::database(connection, false)).exec(u"SELECT 1"_s)) {
                        QFile::rename(file, file + u".bad"_s);
                        setProblem(u"spool file %1 set aside, the database refuses it: %2"_s.arg(file, error));
                        continue;
                    }
                    disconnect(u"%1: %2"_s.arg(location.display(), error));
                    refreshSpoolStatus();
                    return false;
                }
                failures.remove(file);
                QFile::remove(file);
                QMutexLocker lock(&mutex);
                status.written += qint64(batch->second.size());
            }
            if (dir != spoolDir) {
                QDir(dir).removeRecursively();
                adopted->unlock();
                QFile::remove(dir + u".lock"_s);
            }
        }
        refreshSpoolStatus();
        spoolDrained = true;
        return true;
    }

    void tick()
    {
        std::vector<Queued> rows;
        {
            QMutexLocker lock(&mutex);
            rows.swap(queue);
            status.pending = 0;
        }
        if (tryConnect()) {
            QString error;
            if (drainSpool() && (rows.empty() || writeRows(session, rows, &error))) {
                QMutexLocker lock(&mutex);
                status.written += qint64(rows.size());
                return;
            }
            if (connected)
                disconnect(u"%1: %2"_s.arg(location.display(), error));
        }
        spool(rows);
    }
};

Writer::Writer(Location location, Options options, QObject *parent)
    : QObject(parent)
    , m_worker(std::make_unique<Worker>())
{
    Worker &w = *m_worker;
    w.location = std::move(location);
    w.options = std::move(options);
    if (!w.options.spoolFolder.isEmpty()) {
        QDir().mkpath(w.options.spoolFolder);
        w.spoolDir = w.options.spoolFolder + u'/' + w.session;
        w.spoolLock = std::make_unique<QLockFile>(w.spoolDir + u".lock"_s);
        w.spoolLock->tryLock(0);
    }
    w.moveToThread(&w.thread);
    w.thread.setObjectName(u"database writer"_s);
    w.thread.start();
    QMetaObject::invokeMethod(&w, [&w] {
        w.timer = new QTimer(&w);
        QObject::connect(w.timer, &QTimer::timeout, &w, [&w] { w.tick(); });
        w.timer->start(w.options.flushMs);
    }, Qt::BlockingQueuedConnection);
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    write(Row{Table::Session, {w.options.console, w.options.host, w.options.program, now, now}});
}

Writer::~Writer()
{
    Worker &w = *m_worker;
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    write(Row{Table::Session, {w.options.console, w.options.host, w.options.program, now, now}});
    QMetaObject::invokeMethod(&w, [&w] {
        w.sinceAttempt.invalidate(); // one last attempt, whatever the back-off
        w.tick();
        delete w.timer;
        w.prepared_.clear();
        if (QSqlDatabase::database(w.connection, false).isValid())
            QSqlDatabase::database(w.connection, false).close();
        QSqlDatabase::removeDatabase(w.connection);
    }, Qt::BlockingQueuedConnection);
    w.thread.quit();
    w.thread.wait();
    if (w.spoolLock) {
        w.spoolLock->unlock();
        if (QDir(w.spoolDir).isEmpty())
            QDir().rmdir(w.spoolDir);
    }
}

void Writer::write(Row row)
{
    std::vector<Row> one;
    one.push_back(std::move(row));
    write(std::move(one));
}

void Writer::write(std::vector<Row> rows)
{
    Worker &w = *m_worker;
    QMutexLocker lock(&w.mutex);
    for (Row &row : rows) {
        ++w.status.queued[size_t(row.table)];
        w.queue.push_back({row.table, w.nextSeq++, std::move(row.values)});
    }
    w.status.pending = qint64(w.queue.size());
}

QString Writer::session() const
{
    return m_worker->session;
}

Status Writer::status() const
{
    QMutexLocker lock(&m_worker->mutex);
    return m_worker->status;
}

bool Writer::flush(int timeoutMs)
{
    QElapsedTimer timer;
    timer.start();
    Worker &w = *m_worker;
    for (;;) {
        QMetaObject::invokeMethod(&w, [&w] { w.tick(); }, Qt::BlockingQueuedConnection);
        const Status now = status();
        if (now.pending == 0 && now.spooled == 0)
            return true;
        if (timer.elapsed() >= timeoutMs)
            return false;
        QThread::msleep(50);
    }
}

void Writer::setProblemHandler(std::function<void(const Status &)> handler)
{
    QMutexLocker lock(&m_worker->mutex);
    m_worker->handler = std::move(handler);
}

// ---------------------------------------------------------------------------

Reader::Reader(QString connection)
    : m_connection(std::move(connection))
{
}

Reader::~Reader()
{
    QSqlDatabase::database(m_connection, false).close();
    QSqlDatabase::removeDatabase(m_connection);
}

std::expected<std::unique_ptr<Reader>, QString> Reader::open(const Location &location)
{
    const QString name = newConnectionName("reader");
    auto db = connectTo(location, name);
    if (!db) {
        QSqlDatabase::removeDatabase(name);
        return std::unexpected(db.error());
    }
    if (auto migrated = migrate(*db, location.engine == Location::Postgres); !migrated) {
        db->close();
        *db = {};
        QSqlDatabase::removeDatabase(name);
        return std::unexpected(migrated.error());
    }
    return std::unique_ptr<Reader>(new Reader(name));
}

namespace {

template<typename Record, typename Fill>
std::expected<std::vector<Record>, QString> select(const QString &connection, const QString &sql, const QVariantList &binds, Fill fill)
{
    QSqlQuery query(QSqlDatabase::database(connection, false));
    query.setForwardOnly(true);
    if (!query.prepare(sql))
        return std::unexpected(sqlError(query.lastError()));
    for (const QVariant &value : binds)
        query.addBindValue(value);
    if (!query.exec())
        return std::unexpected(sqlError(query.lastError()));
    std::vector<Record> records;
    while (query.next())
        records.push_back(fill(query));
    return records;
}

} // namespace

std::expected<std::vector<Reader::System>, QString> Reader::systems()
{
    return select<System>(m_connection, u"SELECT imc_id, name, kind, first_heard, last_heard FROM systems ORDER BY name, imc_id"_s, {},
                          [](const QSqlQuery &q) {
                              return System{q.value(0).toInt(), q.value(1).toString(), q.value(2).toString(),
                                            q.value(3).toLongLong(), q.value(4).toLongLong()};
                          });
}

std::expected<std::vector<TrackPoint>, QString> Reader::track(const QString &system, qint64 fromMs, qint64 toMs)
{
    auto points = select<TrackPoint>(
        m_connection,
        u"SELECT t, lat, lon, depth, altitude, heading, speed FROM positions WHERE system = ? AND t BETWEEN ? AND ? ORDER BY t"_s,
        {system, fromMs, toMs}, [](const QSqlQuery &q) {
            return TrackPoint{q.value(0).toLongLong(), q.value(1).toDouble(), q.value(2).toDouble(), q.value(3).toDouble(),
                              q.value(4).toDouble(), q.value(5).toDouble(), q.value(6).toDouble()};
        });
    if (!points)
        return points;
    // Several consoles hear the same vehicle: one point per moment.
    std::vector<TrackPoint> &all = *points;
    std::vector<TrackPoint> kept;
    kept.reserve(all.size());
    for (const TrackPoint &p : all)
        if (kept.empty() || p.ms - kept.back().ms >= 100)
            kept.push_back(p);
    return kept;
}

std::expected<std::vector<Reader::AlarmRecord>, QString> Reader::alarms(qint64 fromMs, qint64 toMs)
{
    return select<AlarmRecord>(m_connection,
                               u"SELECT a.t, s.console, a.origin, a.level, a.event, a.message FROM alarms a "
                               "LEFT JOIN sessions s ON s.session = a.session WHERE a.t BETWEEN ? AND ? ORDER BY a.t, a.seq"_s,
                               {fromMs, toMs}, [](const QSqlQuery &q) {
                                   return AlarmRecord{q.value(0).toLongLong(), q.value(1).toString(), q.value(2).toString(),
                                                      q.value(3).toString(), q.value(4).toString(), q.value(5).toString()};
                               });
}

std::expected<std::vector<Reader::PlanRecord>, QString> Reader::planEvents(qint64 fromMs, qint64 toMs)
{
    return select<PlanRecord>(m_connection,
                              u"SELECT p.t, s.console, p.system, p.plan, p.event, p.maneuver, p.detail FROM plan_events p "
                              "LEFT JOIN sessions s ON s.session = p.session WHERE p.t BETWEEN ? AND ? ORDER BY p.t, p.seq"_s,
                              {fromMs, toMs}, [](const QSqlQuery &q) {
                                  return PlanRecord{q.value(0).toLongLong(), q.value(1).toString(), q.value(2).toString(),
                                                    q.value(3).toString(), q.value(4).toString(), q.value(5).toString(),
                                                    q.value(6).toString()};
                              });
}

std::expected<std::vector<Reader::LogBookRecord>, QString> Reader::logBook(qint64 fromMs, qint64 toMs)
{
    return select<LogBookRecord>(m_connection,
                                 u"SELECT t, system, type, context, text FROM logbook WHERE t BETWEEN ? AND ? ORDER BY t, seq"_s,
                                 {fromMs, toMs}, [](const QSqlQuery &q) {
                                     return LogBookRecord{q.value(0).toLongLong(), q.value(1).toString(), q.value(2).toString(),
                                                          q.value(3).toString(), q.value(4).toString()};
                                 });
}

std::expected<std::vector<Reader::SessionRecord>, QString> Reader::sessions()
{
    return select<SessionRecord>(m_connection,
                                 u"SELECT session, console, host, program, started, last_seen FROM sessions ORDER BY started"_s, {},
                                 [](const QSqlQuery &q) {
                                     return SessionRecord{q.value(0).toString(), q.value(1).toString(), q.value(2).toString(),
                                                          q.value(3).toString(), q.value(4).toLongLong(), q.value(5).toLongLong()};
                                 });
}

std::expected<std::vector<Reader::LogRecord>, QString> Reader::logs()
{
    return select<LogRecord>(m_connection,
                             u"SELECT l.session, s.console, l.folder, l.began, l.ended, l.packets, l.bytes FROM logs l "
                             "LEFT JOIN sessions s ON s.session = l.session ORDER BY l.began"_s,
                             {}, [](const QSqlQuery &q) {
                                 return LogRecord{q.value(0).toString(), q.value(1).toString(), q.value(2).toString(),
                                                  q.value(3).toLongLong(), q.value(4).toLongLong(), q.value(5).toLongLong(),
                                                  q.value(6).toLongLong()};
                             });
}

std::expected<std::vector<Reader::SessionSummary>, QString> Reader::sessionSummaries()
{
    auto sessions = this->sessions();
    auto logs = this->logs();
    if (!sessions || !logs)
        return std::unexpected(sessions ? logs.error() : sessions.error());
    // Three reads for every session at once, not two a session.
    auto systems = select<QStringList>(m_connection, u"SELECT session, system FROM session_systems ORDER BY session, system"_s, {},
                                       [](const QSqlQuery &q) { return QStringList{q.value(0).toString(), q.value(1).toString()}; });
    if (!systems)
        return std::unexpected(systems.error());
    auto events = select<QStringList>(
        m_connection, u"SELECT session, system, plan, event FROM plan_events ORDER BY t, seq"_s, {}, [](const QSqlQuery &q) {
            return QStringList{q.value(0).toString(), q.value(1).toString(), q.value(2).toString(), q.value(3).toString()};
        });
    if (!events)
        return std::unexpected(events.error());
    std::vector<SessionSummary> summaries;
    summaries.reserve(sessions->size());
    QHash<QString, SessionSummary *> byId;
    for (SessionRecord &record : *sessions)
        summaries.push_back(SessionSummary{std::move(record), {}, {}, {}});
    for (SessionSummary &summary : summaries)
        byId.insert(summary.session.session, &summary);
    for (const QStringList &row : *systems)
        if (SessionSummary *summary = byId.value(row[0]))
            summary->systems << row[1];
    // A run is a "started" row, then the row that ends it (see OperationsFeed).
    // (success and failure: what consoles before the one tracker wrote.)
    static const QStringList ends = {u"completed"_s, u"failed"_s, u"stopped"_s, u"replaced"_s, u"ended"_s, u"success"_s, u"failure"_s};
    QHash<QString, qsizetype> open; // session + system + plan → its run in the session's `runs`
    for (const QStringList &row : *events) {
        SessionSummary *summary = byId.value(row[0]);
        if (!summary)
            continue;
        const QString key = row[0] + u'\n' + row[1] + u'\n' + row[2];
        if (row[3] == u"started") {
            open.insert(key, summary->runs.size());
            summary->runs << row[2] + u": running"_s;
        } else if (ends.contains(row[3]) && open.contains(key)) {
            summary->runs[open.take(key)] = row[2] + u": "_s + row[3];
        }
    }
    for (const LogRecord &log : *logs)
        if (SessionSummary *summary = byId.value(log.session))
            summary->logs.push_back(log);
    return summaries;
}

std::expected<qint64, QString> Reader::count(Table table, const QString &session)
{
    const QString sql = u"SELECT COUNT(*) FROM %1"_s.arg(QLatin1StringView(info(table).name));
    auto n = select<qint64>(m_connection, session.isEmpty() ? sql : sql + u" WHERE session = ?"_s,
                            session.isEmpty() ? QVariantList{} : QVariantList{session},
                            [](const QSqlQuery &q) { return q.value(0).toLongLong(); });
    if (!n)
        return std::unexpected(n.error());
    return n->empty() ? 0 : n->front();
}

} // namespace neptus::db
