#include "ComponentPalette.h"

#include "ComponentCompiler.h"
#include "ComponentManifest.h"

#include <QDir>
#include <QQmlEngine>
#include <QRegularExpression>
#include <QStandardPaths>

using namespace Qt::StringLiterals;

ComponentPalette::ComponentPalette(QObject *parent)
    : QAbstractListModel(parent)
{
    connect(&m_watcher, &DirectoryWatcher::changed, this, &ComponentPalette::rescan);
}

QStringList ComponentPalette::standardDirectories()
{
    QStringList directories;
    for (const QString &base : QStandardPaths::standardLocations(QStandardPaths::GenericDataLocation))
        directories << QDir(base).filePath(u"neptus-qt/components"_s);
    return directories;
}

QList<PaletteEntry> ComponentPalette::userComponents(const QStringList &directories)
{
    static const QRegularExpression typeName(u"^[A-Z][A-Za-z0-9_]*$"_s);
    QList<PaletteEntry> users;
    for (const QString &directory : directories) {
        const QFileInfoList files = QDir(directory).entryInfoList({u"*.qml"_s}, QDir::Files | QDir::Readable, QDir::Name);
        for (const QFileInfo &file : files) {
            const QString name = file.completeBaseName();
            if (!typeName.match(name).hasMatch() || std::any_of(users.cbegin(), users.cend(), [&](const PaletteEntry &e) { return e.name == name; }))
                continue; // not a component type name, or an earlier directory has it
            PaletteEntry e;
            e.name = name;
            e.module = QString::fromLatin1(userModule);
            e.source = QUrl::fromLocalFile(file.absoluteFilePath());
            const QFileInfo manifest(file.dir().filePath(name + u".json"_s));
            e.modified = std::max(file.lastModified(), manifest.exists() ? manifest.lastModified() : QDateTime());
            e.size = file.size() + (manifest.exists() ? manifest.size() : 0);
            readManifest(e, manifest.filePath());
            users << e;
        }
    }
    return users;
}

void ComponentPalette::installUserModule(QQmlEngine &engine, const QStringList &directories)
{
    engine.addImportPath(UserModule::importPath());
    UserModule::write(userComponents(directories));
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
    m_engine->addImportPath(UserModule::importPath());
    m_builtIns = builtInEntries();
    rescan();
}

void ComponentPalette::rescan()
{
    if (!m_engine)
        return;
    m_watcher.settle();
    QList<PaletteEntry> users = userComponents(m_directories);
    for (PaletteEntry &e : users) {
        if (std::any_of(m_builtIns.cbegin(), m_builtIns.cend(), [&](const PaletteEntry &b) { return b.name == e.name; })) {
            e.status = u"error"_s;
            e.errorString = QStringLiteral("%1 is already a built-in component: rename %2").arg(e.name, QFileInfo(e.source.toLocalFile()).fileName());
        }
    }
    UserModule::write(users);
    m_engine->clearComponentCache(); // edited files compile anew
    for (PaletteEntry &e : users)
        compileComponent(*m_engine, e);

    QStringList changed;
    bool namesChanged = users.size() + m_builtIns.size() != m_entries.size();
    for (const PaletteEntry &e : std::as_const(users)) {
        const auto before = std::find_if(m_entries.cbegin(), m_entries.cend(), [&](const PaletteEntry &o) { return o.name == e.name; });
        if (before == m_entries.cend())
            namesChanged = true;
        else if (before->modified != e.modified || before->size != e.size || before->status != e.status)
            changed << e.name;
    }
    const int oldCount = static_cast<int>(m_entries.size());
    beginResetModel();
    m_entries = m_builtIns + users;
    endResetModel();
    if (oldCount != m_entries.size())
        emit countChanged();
    m_watcher.watch(m_directories);
    for (const QString &name : std::as_const(changed)) {
        const PaletteEntry &e = *std::find_if(m_entries.cbegin(), m_entries.cend(), [&](const PaletteEntry &o) { return o.name == name; });
        emit componentChanged(name, e.status == u"ready");
    }
    // A console that could not load for want of a component loads once it is there.
    if (!changed.isEmpty() || (namesChanged && oldCount > 0)) {
        ++m_revision;
        emit revisionChanged();
    }
}

int ComponentPalette::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(m_entries.size());
}

QVariant ComponentPalette::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_entries.size())
        return {};
    const PaletteEntry &e = m_entries[index.row()];
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
