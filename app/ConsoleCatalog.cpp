#include "core/DataFiles.h"
#include "ConsoleCatalog.h"

#include "LayoutDocument.h"

#include <QDir>
#include <QStandardPaths>
#include <QUrl>

QStringList ConsoleCatalog::standardDirectories()
{
    return {neptus::dataPath(QStringLiteral("consoles")),
            QDir(QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation)).filePath(QStringLiteral("neptus-qt/consoles"))};
}

void ConsoleCatalog::setDirectories(const QStringList &directories)
{
    if (directories == m_directories)
        return;
    m_directories = directories;
    refresh();
}

void ConsoleCatalog::refresh()
{
    m_consoles.clear();
    for (const QString &directory : std::as_const(m_directories)) {
        for (const QFileInfo &file : QDir(directory).entryInfoList({QStringLiteral("*.qml")}, QDir::Files, QDir::Name)) {
            auto document = neptus::layout::LayoutDocument::load(file.absoluteFilePath());
            if (!document) {
                qWarning("Console catalog: %s", qPrintable(document.error()));
                continue;
            }
            const QString root = document->root().id();
            const QString title = document->value(root, QStringLiteral("title")).toString();
            m_consoles.append(QVariantMap{
                {QStringLiteral("file"), QUrl::fromLocalFile(file.absoluteFilePath())},
                {QStringLiteral("title"), title.isEmpty() ? file.completeBaseName() : title},
                {QStringLiteral("kinds"), document->value(root, QStringLiteral("vehicleKinds")).toStringList()}});
        }
    }
    emit consolesChanged();
}
