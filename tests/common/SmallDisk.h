#pragma once

// Full-disk tests on a real full filesystem (ENOSPC), not a file-size limit:
// the sandbox every build and test runs in (tools/lib.sh) mounts a 2 MiB tmpfs
// of its own for each kind of writer, so that tests running side by side do
// not fill each other's.

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QString>

#include <sys/statvfs.h>

namespace neptus::test {

// The small filesystem for `name` (recorder, spool, saves); empty outside the
// sandbox (the test then says it is skipped, and why).
inline QString smallDisk(const QString &name)
{
    const QString root = qEnvironmentVariable("NEPTUS_SMALL_DISKS");
    const QString path = root + u'/' + name;
    return !root.isEmpty() && QDir(path).exists() ? path : QString();
}

inline qint64 freeBytes(const QString &path)
{
    struct statvfs s {};
    return statvfs(QFile::encodeName(path).constData(), &s) == 0 ? qint64(s.f_bavail) * qint64(s.f_frsize) : -1;
}

// Fills a filesystem with a file of its own until only `leave` bytes are free
// (fill(0): full), and frees it again (free(), or when it goes).
class DiskFiller
{
public:
    explicit DiskFiller(const QString &disk) : m_file(disk + QStringLiteral("/filler")) {}
    ~DiskFiller() { free(); }
    DiskFiller(const DiskFiller &) = delete;
    DiskFiller &operator=(const DiskFiller &) = delete;

    // Returns the bytes left free after (what the filesystem's blocks allow).
    qint64 fill(qint64 leave)
    {
        const QString disk = QFileInfo(m_file).absolutePath();
        QFile filler(m_file);
        if (!filler.open(QIODevice::Append))
            return -1;
        const QByteArray block(4096, 'x');
        while (freeBytes(disk) > leave && filler.write(block.constData(), std::min<qint64>(block.size(), freeBytes(disk) - leave)) > 0)
            filler.flush();
        return freeBytes(disk);
    }
    void free() { QFile::remove(m_file); }

private:
    QString m_file;
};

} // namespace neptus::test
