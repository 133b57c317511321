#pragma once

#include <QObject>
#include <QStringList>
#include <QVariantList>
#include <QtQml/qqmlregistration.h>

// What FileChooser shows: a folder's subfolders and files (hidden ones left
// out, folders first, by name), and the places a file is usually in on a
// boat (home, removable media, the user's consoles and missions).
class FileBrowser : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_SINGLETON

public:
    using QObject::QObject;

    // [{name, path, folder: bool, size (bytes), modified (date)}]: the
    // subfolders, then the files matching one of `nameFilters` ("*.qml").
    Q_INVOKABLE static QVariantList entries(const QString &folder, const QStringList &nameFilters);
    // The folder above ("" at the top).
    Q_INVOKABLE static QString parentOf(const QString &folder);
    // [{name, path}] of the places that exist: Home, each mounted removable
    // medium (/media/<user>/*, /run/media/<user>/*, /mnt/*), and `extra`.
    Q_INVOKABLE static QVariantList places(const QStringList &extra = {});
    // A size for people: "812 B", "14.2 kB", "3.1 MB".
    Q_INVOKABLE static QString sizeText(qint64 bytes);
};
