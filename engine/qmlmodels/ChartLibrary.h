#pragma once

#include <QFutureWatcher>
#include <QObject>
#include <QStringList>
#include <QtQml/qqmlregistration.h>

// The chart manager's model: the console's own charts (charts::addToLibrary),
// cells added from a cell, an exchange set, a folder or a zip on a worker
// thread (a large set takes a while), removed by name. `changed` says the
// folder's cells are different: the maps and the depth watch read it again.
class ChartLibrary : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    // The charts folder (~/.local/share/neptus-qt/charts unless set).
    Q_PROPERTY(QString folder READ folder WRITE setFolder NOTIFY changed)
    // The cells it holds, by name.
    Q_PROPERTY(QStringList cells READ cells NOTIFY changed)
    Q_PROPERTY(bool busy READ busy NOTIFY busyChanged)
    // What the last add or remove did ("added US4MD81M"), or why it failed.
    Q_PROPERTY(QString message READ message NOTIFY busyChanged)
    Q_PROPERTY(bool failed READ failed NOTIFY busyChanged)

public:
    explicit ChartLibrary(QObject *parent = nullptr);

    QString folder() const { return m_folder; }
    void setFolder(const QString &folder);
    QStringList cells() const { return m_cells; }
    bool busy() const { return m_busy; }
    QString message() const { return m_message; }
    bool failed() const { return m_failed; }

    Q_INVOKABLE void add(const QString &source);
    Q_INVOKABLE void remove(const QString &cell);

signals:
    void changed();
    void busyChanged();

private:
    void finish(bool failed, const QString &message);

    QString m_folder;
    QStringList m_cells;
    QString m_message;
    bool m_failed = false;
    bool m_busy = false; // from add() until its result is taken (the worker ends before that)
    QFutureWatcher<void> m_adding;
};
