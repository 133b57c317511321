#include "FileBrowser.h"

#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>

QVariantList FileBrowser::entries(const QString &folder, const QStringList &nameFilters)
{
    QVariantList list;
    const QDir dir(folder);
    const auto add = [&list](const QFileInfo &info) {
        list.append(QVariantMap{{QStringLiteral("name"), info.fileName()},
                                {QStringLiteral("path"), info.absoluteFilePath()},
                                {QStringLiteral("folder"), info.isDir()},
                                {QStringLiteral("size"), info.isDir() ? 0 : info.size()},
                                {QStringLiteral("modified"), info.lastModified()}});
    };
    const auto sort = QDir::Name | QDir::IgnoreCase;
    for (const QFileInfo &info : dir.entryInfoList(QDir::Dirs | QDir::NoDotAndDotDot, sort))
        add(info);
    for (const QFileInfo &info : dir.entryInfoList(nameFilters, QDir::Files, sort))
        add(info);
    return list;
}

QString FileBrowser::parentOf(const QString &folder)
{
    QDir dir(folder);
    return dir.cdUp() ? dir.absolutePath() : QString();
}

QVariantList FileBrowser::places(const QStringList &extra)
{
    QVariantList list;
    const auto add = [&list](const QString &name, const QString &path) {
        if (QFileInfo(path).isDir())
            list.append(QVariantMap{{QStringLiteral("name"), name}, {QStringLiteral("path"), QDir(path).absolutePath()}});
    };
    add(QStringLiteral("Home"), QDir::homePath());
    const QString user = qEnvironmentVariable("USER");
    for (const QString &root : {QStringLiteral("/media/") + user, QStringLiteral("/run/media/") + user, QStringLiteral("/mnt")}) {
        for (const QFileInfo &medium : QDir(root).entryInfoList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name))
            add(medium.fileName(), medium.absoluteFilePath());
    }
    for (const QString &path : extra) { // "qml/consoles", "neptus-qt/consoles": told apart by their parent
        const QFileInfo info(path);
        add(info.dir().dirName() + QLatin1Char('/') + info.fileName(), path);
    }
    return list;
}

QString FileBrowser::sizeText(qint64 bytes)
{
    if (bytes < 1000)
        return QStringLiteral("%1 B").arg(bytes);
    if (bytes < 1000 * 1000)
        return QStringLiteral("%1 kB").arg(bytes / 1000.0, 0, 'f', 1);
    if (bytes < qint64(1000) * 1000 * 1000)
        return QStringLiteral("%1 MB").arg(bytes / 1e6, 0, 'f', 1);
    return QStringLiteral("%1 GB").arg(bytes / 1e9, 0, 'f', 1);
}
