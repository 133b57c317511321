#pragma once

#include <QFileSystemWatcher>
#include <QObject>
#include <QStringList>
#include <QTimer>

// Watches component directories and the .qml and .json files in them, and
// says `changed` once things settle (editors write a file in several steps).
class DirectoryWatcher : public QObject
{
    Q_OBJECT

public:
    explicit DirectoryWatcher(QObject *parent = nullptr);

    // Watches these (existing) directories and their files now, instead of what it watched.
    void watch(const QStringList &directories);
    // Drops a pending `changed` (the caller looked already).
    void settle() { m_debounce.stop(); }

signals:
    void changed();

private:
    QFileSystemWatcher m_watcher;
    QTimer m_debounce;
};
