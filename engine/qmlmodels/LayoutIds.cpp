#include "qmlmodels/LayoutIds.h"

#include <QQmlContext>
#include <QtQml/qqml.h>

QObject *LayoutIds::child(QObject *console, const QString &id)
{
    const QQmlContext *context = console ? qmlContext(console) : nullptr;
    if (!context || id.isEmpty())
        return nullptr;
    QObject *object = context->objectForName(id);
    return object && object->parent() == console ? object : nullptr;
}

QString LayoutIds::idOf(QObject *object)
{
    const QQmlContext *context = object ? qmlContext(object) : nullptr;
    return context ? context->nameForObject(object) : QString();
}
