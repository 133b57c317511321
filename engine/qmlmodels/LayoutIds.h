#pragma once

#include <QObject>
#include <QString>
#include <QtQml/qqmlregistration.h>

// A console layout's components by the ids its file gives them ("map2D1"):
// the portrait arrangement and the designer name components that way.
class LayoutIds : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_SINGLETON

public:
    // The child of `console` whose id in the layout file is `id`, or null. By
    // the file's ids (a hash), not by asking each child its id (a scan of the
    // ids for every child): big layouts open in linear time.
    Q_INVOKABLE static QObject *child(QObject *console, const QString &id);
    // The id `object` has in the file that made it, or "".
    Q_INVOKABLE static QString idOf(QObject *object);
};
