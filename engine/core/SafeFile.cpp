#include "core/SafeFile.h"

#include <QFile>
#include <QSaveFile>

namespace neptus {

namespace {

// Written whole to the temporary file (opened unbuffered), so that a full disk
// is said as such: a short write sets no error, the next one does (ENOSPC);
// a buffered file's flush, or commit(), reports a short write as an unknown error.
bool writeWhole(QSaveFile &file, const QByteArray &bytes)
{
    for (qint64 at = 0; at < bytes.size();) {
        const qint64 written = file.write(bytes.constData() + at, bytes.size() - at);
        if (written <= 0)
            return false;
        at += written;
    }
    return true;
}

// `bytes` in `file`'s temporary file (not yet in place); an error names `path` and why.
std::expected<void, QString> writeTemporary(QSaveFile &file, const QString &path, const QByteArray &bytes)
{
    if (!file.open(QIODevice::WriteOnly | QIODevice::Unbuffered))
        return std::unexpected(QStringLiteral("%1: %2").arg(path, file.errorString()));
    if (!writeWhole(file, bytes)) {
        const QString why = file.errorString(); // (cancelWriting() says only that it was cancelled)
        file.cancelWriting();
        return std::unexpected(QStringLiteral("%1: %2").arg(path, why));
    }
    return {};
}

} // namespace

std::expected<void, QString> saveFileAtomically(const QString &path, const QByteArray &bytes)
{
    QSaveFile file(path);
    if (auto written = writeTemporary(file, path, bytes); !written)
        return written;
    if (!file.commit())
        return std::unexpected(QStringLiteral("%1: %2").arg(path, file.errorString()));
    return {};
}

std::expected<void, QString> saveFileKeepingPrevious(const QString &path, const QByteArray &bytes,
                                                     const std::function<void()> &beforeReplace)
{
    QSaveFile file(path);
    if (auto written = writeTemporary(file, path, bytes); !written)
        return written;
    if (beforeReplace)
        beforeReplace();
    QFile previous(path);
    if (previous.exists()) {
        if (!previous.open(QIODevice::ReadOnly))
            return std::unexpected(QStringLiteral("%1: cannot read the previous version: %2").arg(path, previous.errorString()));
        const QByteArray old = previous.readAll();
        QSaveFile backup(path + QStringLiteral(".bak"));
        if (!backup.open(QIODevice::WriteOnly | QIODevice::Unbuffered) || !writeWhole(backup, old) || !backup.commit())
            return std::unexpected(QStringLiteral("%1.bak: %2").arg(path, backup.errorString()));
    }
    if (!file.commit())
        return std::unexpected(QStringLiteral("%1: %2").arg(path, file.errorString()));
    return {};
}

} // namespace neptus
