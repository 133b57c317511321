#pragma once

#include <QObject>
#include <QVariantList>
#include <QtQml/qqmlregistration.h>

// The console layouts there are to open: every .qml file in the given
// directories (the project's consoles, then the user's), each with the title
// and the vehicle kinds its root Console declares. Files that do not read as
// layouts are left out (and said so on the log).
class ConsoleCatalog : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(QStringList directories READ directories WRITE setDirectories NOTIFY consolesChanged)
    Q_PROPERTY(QVariantList consoles READ consoles NOTIFY consolesChanged)

public:
    using QObject::QObject;

    // The project's consoles and ~/.local/share/neptus-qt/consoles.
    static QStringList standardDirectories();

    QStringList directories() const { return m_directories; }
    void setDirectories(const QStringList &directories);
    // [{file: url, title: string, kinds: [string]}], by file name.
    QVariantList consoles() const { return m_consoles; }
    Q_INVOKABLE void refresh();
    // Where a console of that title is saved among the user's (the last
    // directory): "Harbour trials" → ".../Harbour_trials.qml", numbered if taken.
    Q_INVOKABLE QString fileFor(const QString &title) const;

signals:
    void consolesChanged();

private:
    QStringList m_directories;
    QVariantList m_consoles;
};
