#include "log/Recorder.h"

#include "core/Clock.h"
#include "log/LogFile.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <QtEndian>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace neptus::log {

namespace {

// Copies `from` to `to` as it is (gzip stays gzip); false with the reason.
bool copyFile(const QString &from, const QString &to, QString &why)
{
    QFile source(from);
    QSaveFile target(to);
    if (!source.open(QIODevice::ReadOnly)) {
        why = QStringLiteral("%1: %2").arg(from, source.errorString());
        return false;
    }
    if (!target.open(QIODevice::WriteOnly) || target.write(source.readAll()) < 0 || !target.commit()) {
        why = QStringLiteral("%1: %2").arg(to, target.errorString());
        return false;
    }
    return true;
}

QString gzSuffix(const QString &file)
{
    return file.endsWith(QStringLiteral(".gz")) ? QStringLiteral(".gz") : QString();
}

} // namespace

Recorder::Recorder(RecorderConfig config, QObject *parent)
    : QObject(parent)
    , m_config(std::move(config))
{
}

Recorder::~Recorder()
{
    stop();
}

std::expected<void, QString> Recorder::start()
{
    if (m_running)
        return {};
    if (m_config.root.isEmpty())
        return std::unexpected(QStringLiteral("no folder for the logs"));
    if (!QDir().mkpath(m_config.root))
        return std::unexpected(QStringLiteral("%1: cannot make the logs folder").arg(m_config.root));
    if (!beginPart())
        return std::unexpected(status().problem);
    m_stopping = false;
    m_running = true;
    m_thread = std::thread([this] { run(); });
    return {};
}

void Recorder::stop()
{
    if (!m_running)
        return;
    {
        std::lock_guard lock(m_queueMutex);
        m_stopping = true;
    }
    m_wake.notify_one();
    m_thread.join();
    m_running = false;
    endPart();
}

void Recorder::record(QByteArrayView packet)
{
    {
        std::lock_guard lock(m_queueMutex);
        if (m_queue.size() + packet.size() > m_config.maxQueuedBytes) {
            ++m_queueLost;
            return;
        }
        m_queue.append(packet.data(), packet.size());
    }
}

void Recorder::recordMavlink(QByteArrayView frame)
{
    const qint64 usec = QDateTime::currentMSecsSinceEpoch() * 1000;
    std::lock_guard lock(m_queueMutex);
    if (m_queue.size() + m_tlogQueue.size() + frame.size() + 8 > m_config.maxQueuedBytes) {
        ++m_queueLost;
        return;
    }
    char stamp[8];
    qToBigEndian(quint64(usec), stamp);
    m_tlogQueue.append(stamp, 8);
    m_tlogQueue.append(frame.data(), frame.size());
}

void Recorder::writeTlog(const QByteArray &frames)
{
    if (frames.isEmpty() || m_fd < 0)
        return; // no part open: counted with the IMC packets' problem
    if (m_tlogFd < 0) {
        const QByteArray path = QFile::encodeName(QDir(m_partFolder).filePath(QStringLiteral("mavlink.tlog")));
        m_tlogFd = ::open(path.constData(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
        if (m_tlogFd < 0) {
            setProblem(tr("cannot write %1: %2").arg(QString::fromLocal8Bit(path), QString::fromLocal8Bit(std::strerror(errno))));
            return;
        }
    }
    for (qint64 at = 0; at < frames.size();) {
        const ssize_t written = ::write(m_tlogFd, frames.constData() + at, size_t(frames.size() - at));
        if (written < 0 && errno == EINTR)
            continue;
        if (written <= 0) {
            setProblem(tr("cannot write mavlink.tlog in %1: %2").arg(m_partFolder, QString::fromLocal8Bit(std::strerror(errno))));
            return;
        }
        at += written;
    }
}

Recorder::Status Recorder::status() const
{
    QMutexLocker lock(&m_statusMutex);
    return m_status;
}

void Recorder::run()
{
    QByteArray batch, frames;
    for (;;) {
        qint64 lost = 0;
        bool stopping = false;
        {
            std::unique_lock lock(m_queueMutex);
            m_wake.wait_for(lock, std::chrono::milliseconds(m_config.flushMs), [this] { return m_stopping; });
            // The queue takes the last batch's buffer (emptied, its capacity kept):
            // record() seldom reallocates.
            batch.swap(m_queue);
            frames.swap(m_tlogQueue);
            lost = std::exchange(m_queueLost, 0);
            stopping = m_stopping;
        }
        writeBatch(batch, lost);
        writeTlog(frames);
        batch.resize(0);
        frames.resize(0);
        if (stopping)
            return;
    }
}

void Recorder::writeBatch(const QByteArray &batch, qint64 lostInQueue)
{
    if (lostInQueue > 0) {
        QMutexLocker lock(&m_statusMutex);
        m_status.lost += quint64(lostInQueue);
    }
    if (lostInQueue > 0 && m_fd >= 0)
        setProblem(tr("recording falls behind: %1 messages not recorded (the disk is too slow)").arg(lostInQueue));
    const char *data = batch.constData();
    const qint64 size = batch.size();
    qint64 at = 0;
    bool partFull = false;
    while (at < size) {
        const qint64 now = monotonicMs();
        if (m_fd >= 0 && (partFull || now - m_partStartedMs >= m_config.maxPartMs)) {
            endPart();
            beginPart();
        } else if (m_fd < 0 && now - m_partAttemptMs >= 2000) {
            beginPart(); // after a failure, try again now and then
        }
        // The whole packets up to the part's size limit go in one write.
        const qint64 chunkStart = at;
        m_batchOffsets.clear();
        m_batchTimes.clear();
        while (at < size) {
            const auto header = PacketHeader::read(QByteArrayView(data + at, size - at));
            const qint64 length = header ? header->packetSize() : size - at; // record() takes whole packets
            // A part holds at least one packet, and never grows past its size.
            const qint64 partSize = m_partBytes + (at - chunkStart);
            if (partSize > 0 && partSize + length > m_config.maxPartBytes) {
                partFull = true;
                break;
            }
            m_batchOffsets.push_back(quint64(m_partBytes + (at - chunkStart)));
            m_batchTimes.push_back(header ? header->timestamp : 0.0);
            at += length;
        }
        const qint64 packets = qint64(m_batchOffsets.size());
        if (m_fd >= 0 && writeAll(data + chunkStart, at - chunkStart)) {
            m_partBytes += at - chunkStart;
            m_index.append(m_batchOffsets, m_batchTimes);
            partFull = partFull && at < size;
            QMutexLocker lock(&m_statusMutex);
            m_status.packets += quint64(packets);
            m_status.bytes += quint64(at - chunkStart);
            const bool recovered = !m_status.problem.isEmpty() && lostInQueue == 0;
            lock.unlock();
            if (recovered)
                setProblem({});
            continue;
        }
        // Not written: back to the last whole packet, counted as lost.
        const bool open = m_fd >= 0;
        const QString why = QString::fromLocal8Bit(std::strerror(errno));
        if (m_fd >= 0 && (::ftruncate(m_fd, m_partBytes) != 0 || ::lseek(m_fd, m_partBytes, SEEK_SET) < 0)) {
            ::close(m_fd); // the file cannot be mended: the next batch starts a new part
            m_fd = -1;
        }
        quint64 lost;
        {
            QMutexLocker lock(&m_statusMutex);
            m_status.lost += quint64(packets);
            lost = m_status.lost;
        }
        if (open) // else beginPart() said why
            setProblem(tr("cannot write the log in %1: %2; %3 messages not recorded so far (the console carries on)")
                       .arg(m_partFolder, why).arg(lost));
    }
}

bool Recorder::writeAll(const char *data, qint64 size)
{
    while (size > 0) {
        const ssize_t written = ::write(m_fd, data, size_t(size));
        if (written < 0 && errno == EINTR)
            continue;
        if (written <= 0) {
            if (written == 0)
                errno = ENOSPC;
            return false;
        }
        data += written;
        size -= written;
    }
    return true;
}

bool Recorder::beginPart()
{
    const QDateTime now = QDateTime::currentDateTimeUtc();
    QString name = m_config.name;
    name.replace(QLatin1Char('/'), QLatin1Char('_'));
    const QString day = QDir(m_config.root).filePath(now.toString(QStringLiteral("yyyyMMdd")));
    QString folder = QDir(day).filePath(now.toString(QStringLiteral("HHmmss")) + QLatin1Char('-') + name);
    for (int n = 2; QFileInfo::exists(folder); ++n)
        folder = QDir(day).filePath(now.toString(QStringLiteral("HHmmss")) + QLatin1Char('-') + name
                                    + QStringLiteral("-%1").arg(n));
    m_partFolder = folder;
    m_partAttemptMs = monotonicMs();
    QString why;
    const auto fail = [&](const QString &reason) {
        setProblem(tr("cannot begin a log in %1: %2").arg(folder, reason));
        QDir(folder).removeRecursively(); // made just now: no half logs left behind
        return false;
    };
    if (!QDir().mkpath(folder))
        return fail(tr("cannot make the folder"));
    // The definitions first: a log is readable from its first packet.
    const QDir dir(folder);
    QJsonArray extra;
    QJsonObject systems;
    for (qsizetype i = 0; i < m_config.definitionFiles.size(); ++i) {
        const QString &file = m_config.definitionFiles[i];
        const QString target = i == 0 ? QStringLiteral("IMC.xml") + gzSuffix(file)
                                      : QStringLiteral("IMC-extra-%1").arg(QFileInfo(file).fileName());
        if (!copyFile(file, dir.filePath(target), why))
            return fail(why);
        if (i > 0)
            extra.append(target);
    }
    for (const auto &[system, file] : m_config.definitionsFor) {
        QString safe = system;
        safe.replace(QLatin1Char('/'), QLatin1Char('_'));
        const QString target = QStringLiteral("IMC-for-%1.xml").arg(safe) + gzSuffix(file);
        if (!copyFile(file, dir.filePath(target), why))
            return fail(why);
        systems.insert(system, target);
    }
    const QJsonObject meta{
        {QStringLiteral("format"), QStringLiteral("neptus-qt log 1")},
        {QStringLiteral("started"), now.toString(Qt::ISODateWithMs)},
        {QStringLiteral("console"), QJsonObject{{QStringLiteral("name"), m_config.name},
                                                {QStringLiteral("system"), int(m_config.system)}}},
        {QStringLiteral("definitions"), QJsonObject{{QStringLiteral("extra"), extra},
                                                    {QStringLiteral("systems"), systems}}},
    };
    QSaveFile metaFile(dir.filePath(QStringLiteral("Meta.json")));
    if (!metaFile.open(QIODevice::WriteOnly) || metaFile.write(QJsonDocument(meta).toJson()) < 0 || !metaFile.commit())
        return fail(metaFile.errorString());
    const QByteArray data = QFile::encodeName(dir.filePath(QStringLiteral("Data.lsf")));
    m_fd = ::open(data.constData(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
    if (m_fd < 0)
        return fail(QString::fromLocal8Bit(std::strerror(errno)));
    m_partBytes = 0;
    m_partStartedMs = monotonicMs();
    m_index.open(QString::fromLocal8Bit(data));
    {
        QMutexLocker lock(&m_statusMutex);
        m_status.folder = folder;
        ++m_status.parts;
    }
    QMetaObject::invokeMethod(this, [this, folder] { emit partStarted(folder); }, Qt::QueuedConnection);
    return true;
}

void Recorder::endPart()
{
    if (m_fd < 0)
        return;
    ::fdatasync(m_fd);
    ::close(m_fd);
    m_fd = -1;
    if (m_tlogFd >= 0) {
        ::fdatasync(m_tlogFd);
        ::close(m_tlogFd);
        m_tlogFd = -1;
    }
    m_index.finish();
}

void Recorder::setProblem(const QString &problem)
{
    {
        QMutexLocker lock(&m_statusMutex);
        if (m_status.problem == problem)
            return;
        m_status.problem = problem;
    }
    QMetaObject::invokeMethod(this, [this, problem] { emit problemChanged(problem); }, Qt::QueuedConnection);
}

} // namespace neptus::log
