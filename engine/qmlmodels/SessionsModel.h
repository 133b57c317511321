#pragma once

#include "qmlmodels/RowModel.h"

#include <QFutureWatcher>
#include <QObject>
#include <QtQml/qqmlregistration.h>

// The operation's sessions from its database (SQLite or PostgreSQL), newest
// first, for review (issue #38): who (console, host), when, the systems each
// heard, the plans that ran and how they ended, the logs it recorded and
// whether they are still on this machine. Read on a worker thread, so a slow
// server never holds the screen. open() asks for a session's logs to be opened
// for review: the program answers `openRequested` (the shell starts a review
// window of its own, so a live console keeps watching its vehicles).
class SessionsModel : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("the console session's")
    // The database read (a URL or SQLite file), without its password; "" when the console has none.
    Q_PROPERTY(QString database READ database NOTIFY changed)
    // One row a session: session, console, host, program, start, last (ms since 1970), systems, runs
    // (lists of text), logs (the folders still here), packets (recorded, all logs), own (this console's).
    Q_PROPERTY(RowModel *rows READ rows CONSTANT)
    Q_PROPERTY(bool loading READ loading NOTIFY changed)
    // Sessions with nothing to review (no plan ran, and nothing recorded or
    // under a minute long: a console opened and closed, a glance, a test) are
    // folded away unless shown.
    Q_PROPERTY(int quietCount READ quietCount NOTIFY changed)
    Q_PROPERTY(bool showQuiet READ showQuiet WRITE setShowQuiet NOTIFY changed)
    // Why the last read failed ("" when it did not).
    Q_PROPERTY(QString problem READ problem NOTIFY changed)

public:
    explicit SessionsModel(QObject *parent = nullptr);
    ~SessionsModel() override;

    // The database to read (a URL or a SQLite file); read at the first refresh() (the view's).
    void setDatabase(const QString &url);
    // This console's own session in it (its row says so and is not opened for review).
    void setOwnSession(const QString &session) { m_own = session; }
    QString database() const { return m_display; }
    RowModel *rows() { return &m_rows; }
    bool loading() const { return m_loading; }
    QString problem() const { return m_problem; }
    int quietCount() const;
    bool showQuiet() const { return m_showQuiet; }
    void setShowQuiet(bool show);

    // Reads the sessions again (the list as it stands stays meanwhile).
    Q_INVOKABLE void refresh();
    // Asks for `session`'s logs to be opened for review; false (and nothing asked) when none is here.
    Q_INVOKABLE bool open(const QString &session);

signals:
    void changed();
    void openRequested(const QString &session, const QStringList &logFolders);

private:
    QString m_url, m_display, m_problem, m_own;
    bool m_loading = false;
    bool m_showQuiet = false;
    RowModel m_rows;
    QList<RowModel::Row> m_all; // every session read; m_rows shows them but the quiet ones unless asked
    QList<bool> m_quiet;
    void show();
    QFutureWatcher<void> m_read;
};
