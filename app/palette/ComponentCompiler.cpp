#include "ComponentCompiler.h"

#include <QFileInfo>
#include <QMetaProperty>
#include <QQmlComponent>
#include <QQmlEngine>

#include <memory>

using namespace Qt::StringLiterals;

namespace {

QString editorFor(const QMetaProperty &property)
{
    switch (property.metaType().id()) {
    case QMetaType::Double:
    case QMetaType::Float:
    case QMetaType::Int:
    case QMetaType::LongLong:
        return u"number"_s;
    case QMetaType::Bool:
        return u"bool"_s;
    case QMetaType::QString:
        return QString::fromLatin1(property.name()).endsWith(u"path"_s, Qt::CaseInsensitive) ? u"path"_s : u"text"_s;
    case QMetaType::QUrl:
        return u"text"_s;
    default:
        return QString::fromLatin1(property.typeName()) == u"QColor" ? u"color"_s : QString();
    }
}

QString describe(const QList<QQmlError> &errors)
{
    QStringList lines;
    for (const QQmlError &error : errors)
        lines << QStringLiteral("%1:%2:%3: %4")
                     .arg(error.url().isLocalFile() ? QFileInfo(error.url().toLocalFile()).fileName() : error.url().toString())
                     .arg(error.line())
                     .arg(error.column())
                     .arg(error.description());
    return lines.join(u'\n');
}

} // namespace

void compileComponent(QQmlEngine &engine, PaletteEntry &entry)
{
    if (entry.status == u"error")
        return; // its manifest is broken already
    QQmlComponent component(&engine, entry.source, QQmlComponent::PreferSynchronous);
    if (component.isError()) {
        entry.status = u"error"_s;
        entry.errorString = describe(component.errors());
        return;
    }
    if (!entry.properties.isEmpty())
        return;
    // No manifest list: the properties the component itself declares.
    std::unique_ptr<QObject> instance(component.create());
    if (!instance) {
        entry.status = u"error"_s;
        entry.errorString = describe(component.errors());
        return;
    }
    const QMetaObject *meta = instance->metaObject();
    for (int i = meta->propertyOffset(); i < meta->propertyCount(); ++i) {
        const QMetaProperty property = meta->property(i);
        const QString editor = editorFor(property);
        if (!property.isWritable() || editor.isEmpty())
            continue;
        entry.properties << QVariantMap{{u"name"_s, QString::fromLatin1(property.name())}, {u"type"_s, editor}};
    }
}
