#pragma once

// A real PostgreSQL server for a test: initdb into a folder of its own, started
// with pg_ctl listening on a Unix socket in that folder only (no TCP, so
// nothing beyond this process's network), with TimescaleDB preloaded when it is
// installed; stopped with pg_ctl (only the server this made). As root (the
// sandbox) the server runs as the `postgres` user, which owns the folder.

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>

#include <pwd.h>
#include <unistd.h>

namespace neptus::test {

class PgServer
{
public:
    // Fast: fsync off, in /tmp (the sandbox's tmpfs; the tests).
    // Durable: the server's defaults, fsync and synchronous commit on, with its data in /var/tmp,
    // on a disk (a syncing server on a tmpfs would sync nothing): a benchmark of what an
    // operation's server does.
    enum class Durability { Fast, Durable };
    explicit PgServer(Durability durability = Durability::Fast)
        : m_durability(durability),
          m_dir((durability == Durability::Durable ? QStringLiteral("/var/tmp") : QDir::tempPath()) + QStringLiteral("/pg-XXXXXX"))
    {
        const QStringList versions = QDir(QStringLiteral("/usr/lib/postgresql")).entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name);
        for (const QString &v : versions)
            if (QFile::exists(QStringLiteral("/usr/lib/postgresql/%1/bin/pg_ctl").arg(v)))
                m_bin = QStringLiteral("/usr/lib/postgresql/%1/bin/").arg(v);
        if (m_bin.isEmpty()) {
            m_error = QStringLiteral("no PostgreSQL server installed (/usr/lib/postgresql/*/bin/pg_ctl; package postgresql)");
            return;
        }
        m_dir.setAutoRemove(true);
        if (geteuid() == 0) {
            const passwd *pg = getpwnam("postgres");
            if (!pg || chown(QFile::encodeName(m_dir.path()).constData(), pg->pw_uid, pg->pw_gid) != 0) {
                m_error = QStringLiteral("running as root and there is no postgres user to run the server as");
                return;
            }
        }
        QString output;
        if (!run(QStringLiteral("initdb"), {QStringLiteral("-D"), dataDir(), QStringLiteral("-U"), QStringLiteral("neptus"),
                                            QStringLiteral("--auth=trust"), QStringLiteral("-E"), QStringLiteral("UTF8"),
                                            QStringLiteral("--no-sync")}, &output)) {
            m_error = QStringLiteral("initdb failed: ") + output;
            return;
        }
        if (!start()) {
            m_error = QStringLiteral("the server did not start: ") + m_lastOutput + log();
            return;
        }
        if (!run(QStringLiteral("createdb"), {QStringLiteral("-h"), m_dir.path(), QStringLiteral("-U"), QStringLiteral("neptus"),
                                              QStringLiteral("neptus")}, &output))
            m_error = QStringLiteral("createdb failed: ") + output;
    }
    ~PgServer() { stop(); }
    PgServer(const PgServer &) = delete;
    PgServer &operator=(const PgServer &) = delete;

    bool ok() const { return m_error.isEmpty(); }
    QString error() const { return m_error; }
    QString url() const { return QStringLiteral("postgresql://neptus@/neptus?host=") + m_dir.path(); }
    QString socketDir() const { return m_dir.path(); }
    bool timescale() const { return QFile::exists(QStringLiteral("/usr/share/postgresql/%1/extension/timescaledb.control").arg(version())); }

    bool start()
    {
        QString options = QStringLiteral("-k %1 -c listen_addresses= -c max_connections=50").arg(m_dir.path());
        if (m_durability == Durability::Fast)
            options += QStringLiteral(" -c fsync=off");
        if (timescale())
            options += QStringLiteral(" -c shared_preload_libraries=timescaledb -c timescaledb.telemetry_level=off");
        m_running = run(QStringLiteral("pg_ctl"), {QStringLiteral("-D"), dataDir(), QStringLiteral("-l"), logFile(),
                                                   QStringLiteral("-o"), options, QStringLiteral("-w"), QStringLiteral("start")},
                        &m_lastOutput);
        return m_running;
    }
    bool stop()
    {
        if (!m_running)
            return true;
        m_running = !run(QStringLiteral("pg_ctl"), {QStringLiteral("-D"), dataDir(), QStringLiteral("-m"), QStringLiteral("fast"),
                                                    QStringLiteral("-w"), QStringLiteral("stop")}, &m_lastOutput);
        return !m_running;
    }
    QString log() const
    {
        QFile file(logFile());
        return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll().right(2000)) : QString();
    }

private:
    Durability m_durability = Durability::Fast;
    QTemporaryDir m_dir;
    QString dataDir() const { return m_dir.path() + QStringLiteral("/data"); }
    QString logFile() const { return m_dir.path() + QStringLiteral("/server.log"); }
    QString version() const { return m_bin.section(u'/', 4, 4); } // /usr/lib/postgresql/VERSION/bin/

    bool run(const QString &tool, const QStringList &arguments, QString *output) const
    {
        QProcess process;
        process.setProcessChannelMode(QProcess::MergedChannels);
        if (geteuid() == 0)
            process.start(QStringLiteral("runuser"), QStringList{QStringLiteral("-u"), QStringLiteral("postgres"), QStringLiteral("--"),
                                                                 m_bin + tool} + arguments);
        else
            process.start(m_bin + tool, arguments);
        const bool finished = process.waitForFinished(60000);
        *output = QString::fromUtf8(process.readAll());
        return finished && process.exitStatus() == QProcess::NormalExit && process.exitCode() == 0;
    }

    QString m_bin;
    QString m_error;
    QString m_lastOutput;
    bool m_running = false;
};

} // namespace neptus::test
