#include "core/SafeFile.h"

#include <QFile>
#include <QSaveFile>

namespace neptus {

std::expected<void, QString> saveFileKeepingPrevious(const QString &path, const QByteArray &bytes,
                                                     const std::function<void()> &beforeReplace)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return std::unexpected(QStringLiteral("%1: %2").arg(path, file.errorString()));
    if (file.write(bytes) != bytes.size()) {
        file.cancelWriting();
        return std::unexpected(QStringLiteral("%1: %2").arg(path, file.errorString()));
    }
    if (beforeReplace)
        beforeReplace();
    QFile previous(path);
    if (previous.exists()) {
        if (!previous.open(QIODevice::ReadOnly))
            return std::unexpected(QStringLiteral("%1: cannot read the previous version: %2").arg(path, previous.errorString()));
        const QByteArray old = previous.readAll();
        QSaveFile backup(path + QStringLiteral(".bak"));
        if (!backup.open(QIODevice::WriteOnly) || backup.write(old) != old.size() || !backup.commit())
            return std::unexpected(QStringLiteral("%1.bak: %2").arg(path, backup.errorString()));
    }
    if (!file.commit())
        return std::unexpected(QStringLiteral("%1: %2").arg(path, file.errorString()));
    return {};
}

} // namespace neptus
