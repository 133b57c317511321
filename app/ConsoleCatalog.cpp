#include "core/DataFiles.h"
#include "ConsoleCatalog.h"
#include "LayoutDocument.h"

#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QUrl>

QStringList ConsoleCatalog::standardDirectories()
{
    return {neptus::dataPath(QStringLiteral("consoles")),
            QDir(QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation)).filePath(QStringLiteral("neptus-qt/consoles"))};
}

QString ConsoleCatalog::fileFor(const QString &title) const
{
    if (m_directories.isEmpty())
        return {};
    QString stem = title.trimmed();
    stem.replace(QRegularExpression(QStringLiteral("[^A-Za-z0-9_-]+")), QStringLiteral("_"));
    stem.remove(QRegularExpression(QStringLiteral("^_+|_+$")));
    if (stem.isEmpty())
        stem = QStringLiteral("Console");
    if (!stem.front().isUpper())
        stem.front() = stem.front().toUpper(); // a QML file name starts with a capital
    const QDir dir(m_directories.last());
    QString file = dir.filePath(stem + QStringLiteral(".qml"));
    for (int n = 2; QFileInfo::exists(file); ++n)
        file = dir.filePath(QStringLiteral("%1_%2.qml").arg(stem).arg(n));
    return file;
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
