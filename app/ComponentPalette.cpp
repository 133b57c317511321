#include "ComponentPalette.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMetaProperty>
#include <QQmlComponent>
#include <QQmlContext>
#include <QQmlEngine>
#include <QRegularExpression>
#include <QSaveFile>
#include <QStandardPaths>
#include <QTemporaryDir>

using namespace Qt::StringLiterals;

namespace {

// The generated Neptus.User module of each palette, for the life of the process.
QTemporaryDir &moduleDirectory()
{
    static QTemporaryDir directory(QDir::tempPath() + u"/neptus-components-XXXXXX"_s);
    return directory;
}

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

ComponentPalette::ComponentPalette(QObject *parent)
    : QAbstractListModel(parent)
{
    m_debounce.setSingleShot(true);
    m_debounce.setInterval(150); // editors write a file in several steps
    connect(&m_debounce, &QTimer::timeout, this, &ComponentPalette::rescan);
    connect(&m_watcher, &QFileSystemWatcher::directoryChanged, this, &ComponentPalette::scheduleRescan);
    connect(&m_watcher, &QFileSystemWatcher::fileChanged, this, &ComponentPalette::scheduleRescan);
}

QStringList ComponentPalette::standardDirectories()
{
    QStringList directories;
    for (const QString &base : QStandardPaths::standardLocations(QStandardPaths::GenericDataLocation))
        directories << QDir(base).filePath(u"neptus-qt/components"_s);
    return directories;
}

void ComponentPalette::setDirectories(const QStringList &directories)
{
    if (directories == m_directories)
        return;
    m_directories = directories;
    emit directoriesChanged();
    if (m_engine)
        rescan();
}

void ComponentPalette::componentComplete()
{
    if (!m_engine)
        setEngine(qmlEngine(this));
}

void ComponentPalette::setEngine(QQmlEngine *engine)
{
    m_engine = engine;
    if (!m_engine)
        return;
    m_moduleRoot = moduleDirectory().path();
    m_engine->addImportPath(m_moduleRoot);
    loadBuiltIns();
    rescan();
}

void ComponentPalette::loadBuiltIns()
{
    m_builtIns.clear();
    QFile file(u":/qt/qml/Neptus/Components/palette.json"_s);
    if (!file.open(QIODevice::ReadOnly)) {
        qWarning("ComponentPalette: the built-in palette.json is missing");
        return;
    }
    const QJsonArray components = QJsonDocument::fromJson(file.readAll()).object().value(u"components"_s).toArray();
    for (const QJsonValue &value : components) {
        const QJsonObject o = value.toObject();
        Entry e;
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
        m_builtIns << e;
    }
}

void ComponentPalette::readManifest(Entry &entry, const QString &jsonFile)
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

bool ComponentPalette::writeModule(const QList<Entry> &users)
{
    const QDir module(m_moduleRoot + u"/Neptus/User"_s);
    if (!module.mkpath(u"."_s))
        return false;
    QString qmldir = u"module Neptus.User\n"_s;
    for (const Entry &e : users)
        qmldir += e.name + u" 1.0 "_s + module.relativeFilePath(e.source.toLocalFile()) + u'\n';
    QFile existing(module.filePath(u"qmldir"_s));
    if (existing.open(QIODevice::ReadOnly) && existing.readAll() == qmldir.toUtf8())
        return true;
    existing.close();
    QSaveFile file(module.filePath(u"qmldir"_s));
    return file.open(QIODevice::WriteOnly) && file.write(qmldir.toUtf8()) >= 0 && file.commit();
}

void ComponentPalette::compile(Entry &entry)
{
    if (entry.status == u"error")
        return; // its manifest is broken already
    QQmlComponent component(m_engine, entry.source, QQmlComponent::PreferSynchronous);
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

void ComponentPalette::rescan()
{
    if (!m_engine)
        return;
    m_debounce.stop();
    static const QRegularExpression typeName(u"^[A-Z][A-Za-z0-9_]*$"_s);
    QList<Entry> users;
    QStringList taken;
    for (const Entry &b : std::as_const(m_builtIns))
        taken << b.name;
    for (const QString &directory : std::as_const(m_directories)) {
        const QFileInfoList files = QDir(directory).entryInfoList({u"*.qml"_s}, QDir::Files | QDir::Readable, QDir::Name);
        for (const QFileInfo &file : files) {
            const QString name = file.completeBaseName();
            if (!typeName.match(name).hasMatch() || std::any_of(users.cbegin(), users.cend(), [&](const Entry &e) { return e.name == name; }))
                continue; // not a component type name, or an earlier directory has it
            Entry e;
            e.name = name;
            e.module = QString::fromLatin1(userModule);
            e.source = QUrl::fromLocalFile(file.absoluteFilePath());
            const QFileInfo manifest(file.dir().filePath(name + u".json"_s));
            e.modified = std::max(file.lastModified(), manifest.exists() ? manifest.lastModified() : QDateTime());
            e.size = file.size() + (manifest.exists() ? manifest.size() : 0);
            readManifest(e, manifest.filePath());
            if (taken.contains(name)) {
                e.status = u"error"_s;
                e.errorString = QStringLiteral("%1 is already a built-in component: rename %2").arg(name, file.fileName());
            }
            users << e;
        }
    }
    writeModule(users);
    m_engine->clearComponentCache(); // edited files compile anew
    for (Entry &e : users)
        compile(e);

    QStringList changed;
    for (const Entry &e : std::as_const(users)) {
        const auto before = std::find_if(m_entries.cbegin(), m_entries.cend(), [&](const Entry &o) { return o.name == e.name; });
        if (before != m_entries.cend() && (before->modified != e.modified || before->size != e.size || before->status != e.status))
            changed << e.name;
    }
    const int oldCount = static_cast<int>(m_entries.size());
    beginResetModel();
    m_entries = m_builtIns + users;
    endResetModel();
    if (oldCount != m_entries.size())
        emit countChanged();
    watch();
    for (const QString &name : std::as_const(changed)) {
        const Entry &e = *std::find_if(m_entries.cbegin(), m_entries.cend(), [&](const Entry &o) { return o.name == name; });
        emit componentChanged(name, e.status == u"ready");
    }
    if (!changed.isEmpty()) {
        ++m_revision;
        emit revisionChanged();
    }
}

void ComponentPalette::scheduleRescan()
{
    m_debounce.start();
}

void ComponentPalette::watch()
{
    if (!m_watcher.files().isEmpty())
        m_watcher.removePaths(m_watcher.files());
    if (!m_watcher.directories().isEmpty())
        m_watcher.removePaths(m_watcher.directories());
    QStringList paths;
    for (const QString &directory : std::as_const(m_directories)) {
        if (!QFileInfo(directory).isDir())
            continue;
        paths << directory;
        for (const QFileInfo &file : QDir(directory).entryInfoList({u"*.qml"_s, u"*.json"_s}, QDir::Files))
            paths << file.absoluteFilePath();
    }
    if (!paths.isEmpty())
        m_watcher.addPaths(paths);
}

int ComponentPalette::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(m_entries.size());
}

QVariant ComponentPalette::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_entries.size())
        return {};
    const Entry &e = m_entries[index.row()];
    switch (role) {
    case Qt::DisplayRole:
    case DisplayNameRole: return e.displayName;
    case NameRole: return e.name;
    case ModuleRole: return e.module;
    case CategoryRole: return e.category;
    case DescriptionRole: return e.description;
    case IconRole: return e.icon;
    case PropertiesRole: return e.properties;
    case StatusRole: return e.status;
    case ErrorStringRole: return e.errorString;
    case SourceRole: return e.source;
    case BuiltInRole: return e.builtIn;
    case DefaultWidthRole: return e.defaultWidth;
    case DefaultHeightRole: return e.defaultHeight;
    default: return {};
    }
}

QHash<int, QByteArray> ComponentPalette::roleNames() const
{
    return {{NameRole, "name"},           {ModuleRole, "module"},         {DisplayNameRole, "displayName"},
            {CategoryRole, "category"},   {DescriptionRole, "description"}, {IconRole, "icon"},
            {PropertiesRole, "properties"}, {StatusRole, "status"},        {ErrorStringRole, "errorString"},
            {SourceRole, "source"},       {BuiltInRole, "builtIn"},       {DefaultWidthRole, "defaultWidth"},
            {DefaultHeightRole, "defaultHeight"}};
}

QVariantMap ComponentPalette::entry(const QString &name) const
{
    // The same fields as the model's roles, by the roles' names.
    for (int row = 0; row < m_entries.size(); ++row) {
        if (m_entries[row].name != name)
            continue;
        QVariantMap map;
        const QHash<int, QByteArray> roles = roleNames();
        for (auto it = roles.cbegin(); it != roles.cend(); ++it)
            map.insert(QString::fromLatin1(it.value()), data(index(row), it.key()));
        return map;
    }
    return {};
}
