#include "UserModule.h"

#include <QDir>
#include <QFile>
#include <QSaveFile>
#include <QTemporaryDir>

using namespace Qt::StringLiterals;

namespace {

QTemporaryDir &moduleDirectory()
{
    static QTemporaryDir directory(QDir::tempPath() + u"/neptus-components-XXXXXX"_s);
    return directory;
}

} // namespace

QString UserModule::importPath()
{
    return moduleDirectory().path();
}

bool UserModule::write(const QList<PaletteEntry> &entries)
{
    const QDir module(importPath() + u"/Neptus/User"_s);
    if (!module.mkpath(u"."_s))
        return false;
    QString qmldir = u"module Neptus.User\n"_s;
    for (const PaletteEntry &e : entries)
        qmldir += e.name + u" 1.0 "_s + module.relativeFilePath(e.source.toLocalFile()) + u'\n';
    QFile existing(module.filePath(u"qmldir"_s));
    if (existing.open(QIODevice::ReadOnly) && existing.readAll() == qmldir.toUtf8())
        return true;
    existing.close();
    QSaveFile file(module.filePath(u"qmldir"_s));
    return file.open(QIODevice::WriteOnly) && file.write(qmldir.toUtf8()) >= 0 && file.commit();
}
