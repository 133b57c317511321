#pragma once

// Full-disk tests on a real full filesystem (ENOSPC), not a file-size limit:
// the sandbox every build and test runs in (tools/lib.sh) mounts a 2 MiB tmpfs
// for each full-disk test, so that tests running side by side do not fill
// each other's.

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QString>

#include <sys/statvfs.h>

namespace neptus::test {

// The small filesystem for `name` (recorder, spool, mission-saves,
// layout-saves: one test each); empty outside the sandbox (the test then says
// it is skipped, and why).
inline QString smallDisk(const QString &name)
{
    const QString root = qEnvironmentVariable("NEPTUS_SMALL_DISKS");
    const QString path = root + u'/' + name;
    return !root.isEmpty() && QDir(path).exists() ? path : QString();
}

// Why a full-disk test is skipped when smallDisk() is empty.
inline constexpr const char *noSmallDisk = "no small filesystem to fill: run inside the sandbox (tools/test mounts one, with bubblewrap 0.7 or newer)";

inline qint64 freeBytes(const QString &path)
{
    struct statvfs s {};
    return statvfs(QFile::encodeName(path).constData(), &s) == 0 ? qint64(s.f_bavail) * qint64(s.f_frsize) : -1;
}

// Fills a filesystem with a file of its own until only `leave` bytes are free,
// rounded up to whole blocks (fill(0): full), and frees it again (free(), or
// when it goes).
class DiskFiller
{
public:
    explicit DiskFiller(const QString &disk) : m_file(disk + QStringLiteral("/filler")) {}
    ~DiskFiller() { free(); }
    DiskFiller(const DiskFiller &) = delete;
    DiskFiller &operator=(const DiskFiller &) = delete;

    // Returns the bytes left free after.
    qint64 fill(qint64 leave)
    {
        const QString disk = QFileInfo(m_file).absolutePath();
        struct statvfs s {};
        if (statvfs(QFile::encodeName(disk).constData(), &s) != 0 || s.f_frsize == 0)
            return -1;
        const qint64 block = qint64(s.f_frsize);
        const qint64 target = (leave + block - 1) / block * block;
        QFile filler(m_file);
        if (!filler.open(QIODevice::Append | QIODevice::Unbuffered))
            return -1;
        const QByteArray whole(int(block), 'x'); // whole blocks: the last never takes more than asked
        while (freeBytes(disk) > target && filler.write(whole) == whole.size()) {
        }
        return freeBytes(disk);
    }
    void free() { QFile::remove(m_file); }

private:
    QString m_file;
};

} // namespace neptus::test
