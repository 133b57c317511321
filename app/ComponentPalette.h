#pragma once

#include <QAbstractListModel>
#include <QDateTime>
#include <QFileSystemWatcher>
#include <QHash>
#include <QQmlParserStatus>
#include <QTimer>
#include <QUrl>
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
// Earlier directories win over later ones for the same name.
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

    static constexpr auto userModule = "Neptus.User";

    explicit ComponentPalette(QObject *parent = nullptr);

    // The system-wide and per-user directories (XDG data dirs + "neptus-qt/components"), user first.
    static QStringList standardDirectories();

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
    struct Entry
    {
        QString name, module, displayName, category, description;
        QUrl icon, source;
        QVariantList properties;
        double defaultWidth = 0, defaultHeight = 0; // as placed; 0: the designer's default
        QString status = QStringLiteral("ready");
        QString errorString;
        bool builtIn = false;
        QDateTime modified; // of the .qml and .json, the later
        qint64 size = -1;
    };

    void loadBuiltIns();
    void scheduleRescan();
    void watch();
    bool writeModule(const QList<Entry> &users);
    void compile(Entry &entry);
    static void readManifest(Entry &entry, const QString &jsonFile);

    QQmlEngine *m_engine = nullptr;
    QStringList m_directories;
    QList<Entry> m_builtIns;
    QList<Entry> m_entries;
    QFileSystemWatcher m_watcher;
    QTimer m_debounce;
    QString m_moduleRoot; // import path holding Neptus/User/qmldir
    int m_revision = 0;
};
