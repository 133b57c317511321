#pragma once

#include "DirectoryWatcher.h"
#include "PaletteEntry.h"
#include "UserModule.h"

#include <QAbstractListModel>
#include <QHash>
#include <QQmlParserStatus>
#include <QtQml/qqmlregistration.h>

class QQmlEngine;

// The designer's palette: the project's components (module Neptus.Components,
// described by its palette.json) and every `Name.qml` in the user component
// directories (optionally described by a `Name.json` beside it), which layouts
// import as module `Neptus.User`.
//
// The directories are watched: a component dropped in appears within a
// second, an edited one is recompiled (and `revision` changes so the console
// reloads it), a broken one is listed with its QML error and status "error".
// Earlier directories win over later ones for the same name. The parts:
// ComponentManifest (palette.json, Name.json), UserModule (the Neptus.User
// qmldir), ComponentCompiler, DirectoryWatcher.
class ComponentPalette : public QAbstractListModel, public QQmlParserStatus
{
    Q_OBJECT
    Q_INTERFACES(QQmlParserStatus)
    QML_ELEMENT
    Q_PROPERTY(QStringList directories READ directories WRITE setDirectories NOTIFY directoriesChanged)
    Q_PROPERTY(int revision READ revision NOTIFY revisionChanged)
    Q_PROPERTY(int count READ rowCount NOTIFY countChanged)

public:
    enum Role {
        NameRole = Qt::UserRole + 1,
        ModuleRole,
        DisplayNameRole,
        CategoryRole,
        DescriptionRole,
        IconRole,
        PropertiesRole,
        StatusRole,
        ErrorStringRole,
        SourceRole,
        BuiltInRole,
        DefaultWidthRole,
        DefaultHeightRole,
    };
    Q_ENUM(Role)

    static constexpr auto userModule = UserModule::uri;

    explicit ComponentPalette(QObject *parent = nullptr);

    // The system-wide and per-user directories (XDG data dirs + "neptus-qt/components"), user first.
    static QStringList standardDirectories();
    // The components in `directories` (`Name.qml`, earlier directories
    // first), described by their manifests, not yet compiled.
    static QList<PaletteEntry> userComponents(const QStringList &directories);
    // Makes the Neptus.User module of `directories` importable in `engine`
    // before any console loads (a saved layout imports it on its first line).
    static void installUserModule(QQmlEngine &engine, const QStringList &directories);

    QStringList directories() const { return m_directories; }
    void setDirectories(const QStringList &directories);
    int revision() const { return m_revision; }

    // For use outside QML: the engine components are compiled in (adds the
    // Neptus.User import path to it).
    void setEngine(QQmlEngine *engine);

    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    QHash<int, QByteArray> roleNames() const override;

    // One entry as a map of the role names, or an empty map.
    Q_INVOKABLE QVariantMap entry(const QString &name) const;
    // Looks at the directories again now (the watcher does it by itself).
    Q_INVOKABLE void rescan();

    void classBegin() override {}
    void componentComplete() override;

signals:
    void directoriesChanged();
    void revisionChanged();
    void countChanged();
    // A user component's file changed, and now compiles (or not).
    void componentChanged(const QString &name, bool ready);

private:
    QQmlEngine *m_engine = nullptr;
    QStringList m_directories;
    QList<PaletteEntry> m_builtIns;
    QList<PaletteEntry> m_entries;
    DirectoryWatcher m_watcher;
    int m_revision = 0;
};
