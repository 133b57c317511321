#include "qmlmodels/SessionsModel.h"

#include "database/Database.h"

#include <QFileInfo>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>

using namespace Qt::StringLiterals;

namespace {

struct Read
{
    QList<RowModel::Row> rows;
    QList<bool> quiet;
    QString problem;
};

// On a worker thread: a connection of its own for the one read.
Read readSessions(const neptus::db::Location &location, const QString &own)
{
    Read read;
    if (location.engine == neptus::db::Location::Sqlite && !QFileInfo::exists(location.file)) {
        read.problem = u"no database yet at %1: a console that records writes it"_s.arg(location.file);
        return read;
    }
    auto reader = neptus::db::Reader::open(location);
    if (!reader) {
        read.problem = reader.error();
        return read;
    }
    auto summaries = (*reader)->sessionSummaries();
    if (!summaries) {
        read.problem = summaries.error();
        return read;
    }
    std::reverse(summaries->begin(), summaries->end()); // newest first
    for (const auto &s : *summaries) {
        QStringList here;
        qint64 packets = 0;
        // (last_seen is written as a console starts and ends: one that was
        // killed has none later than its start, its logs say how long it ran.)
        qint64 lastMs = s.session.lastMs;
        for (const auto &log : s.logs) {
            packets += log.packets;
            lastMs = std::max(lastMs, log.endMs);
            if (QFileInfo::exists(log.folder))
                here << log.folder;
        }
        const bool ours = s.session.session == own;
        read.rows.append(RowModel::Row{s.session.session, s.session.console, s.session.host, s.session.program,
                                       double(s.session.startMs), double(s.session.lastMs), s.systems, s.runs, here,
                                       double(packets), ours});
        // Nothing to review: no plan ran, and nothing was recorded or it lasted under a minute (a glimpse).
        const bool glimpse = lastMs - s.session.startMs < 60000;
        read.quiet.append(!ours && s.runs.isEmpty() && (glimpse || (packets == 0 && s.systems.isEmpty())));
    }
    return read;
}

} // namespace

SessionsModel::SessionsModel(QObject *parent)
    : QObject(parent)
    , m_rows({u"session"_s, u"console"_s, u"host"_s, u"program"_s, u"start"_s, u"last"_s, u"systems"_s, u"runs"_s, u"logs"_s,
              u"packets"_s, u"own"_s})
{
}

SessionsModel::~SessionsModel()
{
    m_read.waitForFinished();
}

void SessionsModel::setDatabase(const QString &url)
{
    if (url != m_url) { // another database's sessions
        m_all.clear();
        m_quiet.clear();
        show();
    }
    m_url = url;
    const auto location = neptus::db::Location::parse(url);
    m_display = location ? location->display() : url;
    emit changed();
}

void SessionsModel::refresh()
{
    if (m_loading)
        return; // the read under way answers
    const auto location = neptus::db::Location::parse(m_url);
    if (m_url.isEmpty() || !location) {
        m_problem = m_url.isEmpty() ? u"this console has no database"_s : location.error();
        m_all.clear();
        m_quiet.clear();
        show();
        emit changed();
        return;
    }
    m_loading = true;
    emit changed();
    auto result = std::make_shared<Read>();
    m_read.disconnect(this);
    connect(&m_read, &QFutureWatcherBase::finished, this, [this, result] {
        m_loading = false;
        m_problem = result->problem;
        if (m_problem.isEmpty()) {
            m_all = std::move(result->rows);
            m_quiet = std::move(result->quiet);
            show();
        }
        emit changed();
    });
    m_read.setFuture(QtConcurrent::run([location = *location, own = m_own, result] { *result = readSessions(location, own); }));
}

int SessionsModel::quietCount() const
{
    return int(m_quiet.count(true));
}

void SessionsModel::setShowQuiet(bool show)
{
    if (show == m_showQuiet)
        return;
    m_showQuiet = show;
    this->show();
    emit changed();
}

void SessionsModel::show()
{
    QList<RowModel::Row> rows;
    for (qsizetype i = 0; i < m_all.size(); ++i)
        if (m_showQuiet || !m_quiet.value(i))
            rows.append(m_all[i]);
    m_rows.setRows(std::move(rows));
}

bool SessionsModel::open(const QString &session)
{
    const int row = m_rows.indexOf(session);
    if (row < 0 || session == m_own)
        return false;
    const QStringList logs = m_rows.rows().at(row).at(m_rows.column(u"logs"_s)).toStringList();
    if (logs.isEmpty())
        return false;
    emit openRequested(session, logs);
    return true;
}
