#include "ComponentManifest.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

using namespace Qt::StringLiterals;

QList<PaletteEntry> builtInEntries()
{
    QList<PaletteEntry> entries;
    QFile file(u":/qt/qml/Neptus/Components/palette.json"_s);
    if (!file.open(QIODevice::ReadOnly)) {
        qWarning("ComponentPalette: the built-in palette.json is missing");
        return entries;
    }
    const QJsonArray components = QJsonDocument::fromJson(file.readAll()).object().value(u"components"_s).toArray();
    for (const QJsonValue &value : components) {
        const QJsonObject o = value.toObject();
        PaletteEntry e;
        e.name = o.value(u"name"_s).toString();
        e.module = u"Neptus.Components"_s;
        e.displayName = o.value(u"displayName"_s).toString(e.name);
        e.category = o.value(u"category"_s).toString(u"General"_s);
        e.description = o.value(u"description"_s).toString();
        e.icon = QUrl(o.value(u"icon"_s).toString());
        e.properties = o.value(u"properties"_s).toArray().toVariantList();
        e.defaultWidth = o.value(u"defaultWidth"_s).toDouble();
        e.defaultHeight = o.value(u"defaultHeight"_s).toDouble();
        e.source = QUrl(u"qrc:/qt/qml/Neptus/Components/"_s + e.name + u".qml"_s);
        e.builtIn = true;
        entries << e;
    }
    return entries;
}

void readManifest(PaletteEntry &entry, const QString &jsonFile)
{
    entry.displayName = entry.name;
    entry.category = u"User"_s;
    QFile file(jsonFile);
    if (!file.exists())
        return;
    QJsonParseError error;
    const QJsonDocument json = file.open(QIODevice::ReadOnly) ? QJsonDocument::fromJson(file.readAll(), &error) : QJsonDocument();
    if (!json.isObject()) {
        entry.status = u"error"_s;
        entry.errorString = QStringLiteral("%1: not a JSON object (%2 at offset %3)")
                                .arg(QFileInfo(jsonFile).fileName(), error.errorString())
                                .arg(error.offset);
        return;
    }
    const QJsonObject o = json.object();
    entry.displayName = o.value(u"displayName"_s).toString(entry.name);
    entry.category = o.value(u"category"_s).toString(entry.category);
    entry.description = o.value(u"description"_s).toString();
    if (const QString icon = o.value(u"icon"_s).toString(); !icon.isEmpty())
        entry.icon = icon.contains(u'.') ? QUrl::fromLocalFile(QFileInfo(jsonFile).dir().filePath(icon)) : QUrl(icon);
    if (o.contains(u"properties"_s))
        entry.properties = o.value(u"properties"_s).toArray().toVariantList();
    entry.defaultWidth = o.value(u"defaultWidth"_s).toDouble();
    entry.defaultHeight = o.value(u"defaultHeight"_s).toDouble();
}
