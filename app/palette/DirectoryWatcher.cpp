#include "DirectoryWatcher.h"

#include <QDir>
#include <QFileInfo>

using namespace Qt::StringLiterals;

DirectoryWatcher::DirectoryWatcher(QObject *parent)
    : QObject(parent)
{
    m_debounce.setSingleShot(true);
    m_debounce.setInterval(150);
    connect(&m_debounce, &QTimer::timeout, this, &DirectoryWatcher::changed);
    connect(&m_watcher, &QFileSystemWatcher::directoryChanged, &m_debounce, qOverload<>(&QTimer::start));
    connect(&m_watcher, &QFileSystemWatcher::fileChanged, &m_debounce, qOverload<>(&QTimer::start));
}

void DirectoryWatcher::watch(const QStringList &directories)
{
    if (!m_watcher.files().isEmpty())
        m_watcher.removePaths(m_watcher.files());
    if (!m_watcher.directories().isEmpty())
        m_watcher.removePaths(m_watcher.directories());
    QStringList paths;
    for (const QString &directory : directories) {
        if (!QFileInfo(directory).isDir())
            continue;
        paths << directory;
        for (const QFileInfo &file : QDir(directory).entryInfoList({u"*.qml"_s, u"*.json"_s}, QDir::Files))
            paths << file.absoluteFilePath();
    }
    if (!paths.isEmpty())
        m_watcher.addPaths(paths);
}
