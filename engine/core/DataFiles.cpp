#include "core/DataFiles.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace neptus {

QString programDirectory()
{
    if (QCoreApplication::instance())
        return QCoreApplication::applicationDirPath();
    // Before (or without) an application object: where the kernel says we are.
    return QFileInfo(QFileInfo(QStringLiteral("/proc/self/exe")).symLinkTarget()).absolutePath();
}

QString dataDirectory()
{
    const QString overridden = qEnvironmentVariable("NEPTUS_DATA_DIR");
    if (!overridden.isEmpty())
        return QDir(overridden).absolutePath();
    return QDir(programDirectory() + QStringLiteral("/../share/neptus-qt")).absolutePath();
}

QString dataPath(const QString &relative)
{
    return dataDirectory() + u'/' + relative;
}

} // namespace neptus
