#include "log/LogFile.h"

#include "core/Gzip.h"
#include "messages/Crc16.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLocale>
#include <QSaveFile>
#include <QtEndian>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <limits>
#include <cstring>

#include <fcntl.h>
#include <unistd.h>

namespace neptus::log {

// A file mapped into memory for as long as a log that reads it lives.
class MappedFile
{
public:
    QFile file;
    uchar *bytes = nullptr;
};

namespace {

constexpr char indexMagic[8] = {'N', 'Q', 'L', 'S', 'F', 'I', 'D', 'X'};
constexpr quint32 indexVersion = 1;

// Data.lsf.index: this, then the packets' offsets (u64) and timestamps (f64), host order.
struct IndexHead
{
    char magic[8];
    quint32 version, reserved;
    quint64 dataSize;       // Data.lsf as indexed: its size and modification time
    qint64 dataModifiedMs;
    quint64 count;
};

QString firstExisting(const QDir &dir, std::initializer_list<const char *> names)
{
    for (const char *name : names) {
        if (QFileInfo::exists(dir.filePath(QString::fromLatin1(name))))
            return dir.filePath(QString::fromLatin1(name));
    }
    return {};
}

template<typename T>
T readAt(const char *p, bool bigEndian)
{
    T value;
    std::memcpy(&value, p, sizeof value);
    if constexpr (sizeof(T) == 1)
        return value;
    else
        return bigEndian ? qFromBigEndian(value) : qFromLittleEndian(value);
}

} // namespace

std::optional<PacketHeader> PacketHeader::read(QByteArrayView bytes)
{
    if (bytes.size() < 20)
        return std::nullopt;
    const char *p = bytes.data();
    PacketHeader h;
    const quint16 sync = readAt<quint16>(p, false);
    if (sync == 0xFE54)
        h.bigEndian = false;
    else if (sync == 0x54FE)
        h.bigEndian = true;
    else
        return std::nullopt;
    h.sync = 0xFE54;
    h.mgid = readAt<quint16>(p + 2, h.bigEndian);
    h.size = readAt<quint16>(p + 4, h.bigEndian);
    quint64 bits = readAt<quint64>(p + 6, h.bigEndian);
    std::memcpy(&h.timestamp, &bits, sizeof bits);
    h.src = readAt<quint16>(p + 14, h.bigEndian);
    h.srcEnt = readAt<quint8>(p + 16, h.bigEndian);
    h.dst = readAt<quint16>(p + 17, h.bigEndian);
    h.dstEnt = readAt<quint8>(p + 19, h.bigEndian);
    return h;
}

std::expected<std::shared_ptr<const LogFile>, QString> LogFile::open(const QString &path, const Options &options)
{
    const QFileInfo info(path);
    if (!info.exists())
        return std::unexpected(QStringLiteral("%1: no such file or folder").arg(path));
    const QDir dir = info.isDir() ? QDir(path) : info.dir();
    const QString data = info.isDir() ? firstExisting(dir, {"Data.lsf", "Data.lsf.gz"}) : info.absoluteFilePath();
    if (data.isEmpty())
        return std::unexpected(QStringLiteral("%1: no Data.lsf or Data.lsf.gz in this folder").arg(path));

    auto log = std::shared_ptr<LogFile>(new LogFile);
    log->m_folder = dir.absolutePath();
    log->m_dataFile = data;

    // Who recorded it, and its extra definitions (ours only).
    QStringList extra;
    QList<std::pair<QString, QString>> perSystem;
    if (QFile meta(dir.filePath(QStringLiteral("Meta.json"))); meta.open(QIODevice::ReadOnly)) {
        QJsonParseError error{};
        const QJsonObject object = QJsonDocument::fromJson(meta.read(1 << 20), &error).object();
        if (error.error != QJsonParseError::NoError)
            return std::unexpected(QStringLiteral("%1: %2 at byte %3")
                                       .arg(meta.fileName(), error.errorString()).arg(error.offset));
        const QJsonObject console = object.value(u"console").toObject();
        log->m_recorder = quint16(console.value(u"system").toInt(0xFFFF));
        log->m_recorderName = console.value(u"name").toString();
        const QJsonObject definitions = object.value(u"definitions").toObject();
        for (const auto &file : definitions.value(u"extra").toArray())
            extra.append(dir.filePath(file.toString()));
        const QJsonObject systems = definitions.value(u"systems").toObject();
        for (auto it = systems.begin(); it != systems.end(); ++it)
            perSystem.append({it.key(), dir.filePath(it.value().toString())});
    }

    const QString imc = firstExisting(dir, {"IMC.xml", "IMC.xml.gz"});
    std::shared_ptr<const msg::Schema> definitions = options.fallbackDefinitions;
    if (!imc.isEmpty()) {
        auto loaded = msg::Schema::load(QStringList{imc} + extra);
        if (!loaded)
            return std::unexpected(QStringLiteral("the log's definitions: %1").arg(loaded.error().toString()));
        definitions = *loaded;
    } else if (!definitions) {
        return std::unexpected(QStringLiteral("%1: no IMC.xml or IMC.xml.gz: the definitions its packets were written with")
                                   .arg(dir.absolutePath()));
    }
    log->m_schemas = std::make_shared<msg::SchemaSet>(definitions);
    for (const auto &[system, file] : perSystem) {
        auto loaded = msg::Schema::load({file});
        if (!loaded)
            return std::unexpected(QStringLiteral("definitions of %1: %2").arg(system, loaded.error().toString()));
        log->m_schemas->setFor(system, *loaded);
    }

    QFile file(data);
    if (!file.open(QIODevice::ReadOnly))
        return std::unexpected(QStringLiteral("%1: %2").arg(data, file.errorString()));
    if (file.size() > options.maxBytes)
        return std::unexpected(QStringLiteral("%1: %2 bytes, over the %3 this reader takes")
                                   .arg(data).arg(file.size()).arg(options.maxBytes));
    const bool gzip = isGzip(file.peek(2));
    if (gzip) {
        auto bytes = readFileMaybeGzip(data, options.maxBytes);
        if (!bytes)
            return std::unexpected(bytes.error());
        log->m_data = std::move(*bytes);
    } else if (file.size() > 0) {
        auto mapped = std::make_shared<MappedFile>();
        mapped->file.setFileName(data);
        if (!mapped->file.open(QIODevice::ReadOnly) || !(mapped->bytes = mapped->file.map(0, file.size())))
            return std::unexpected(QStringLiteral("%1: cannot map it: %2").arg(data, mapped->file.errorString()));
        log->m_mapped = mapped;
        log->m_data = QByteArray::fromRawData(reinterpret_cast<const char *>(mapped->bytes), file.size());
    }

    const QString index = data + QStringLiteral(".index");
    if (!gzip && log->readIndex(index)) {
        log->m_indexReused = true;
    } else {
        log->scan();
        if (!gzip && options.writeIndex && log->m_damage.isEmpty())
            writeLogIndex(data, log->m_offsets, log->m_times);
    }
    log->computeLogTimes();
    return log;
}

std::shared_ptr<const LogFile> LogFile::fromData(QByteArray data, std::shared_ptr<msg::SchemaSet> schemas,
                                                 const QString &name)
{
    auto log = std::shared_ptr<LogFile>(new LogFile);
    log->m_dataFile = name;
    log->m_data = std::move(data);
    log->m_schemas = std::move(schemas);
    log->scan();
    log->computeLogTimes();
    return log;
}

void LogFile::scan()
{
    const char *bytes = m_data.constData();
    const qint64 size = m_data.size();
    // About 45 bytes a packet in real logs: reserve once.
    m_offsets.reserve(size_t(size / 40));
    m_times.reserve(size_t(size / 40));
    qint64 at = 0;
    qint64 badCrc = 0;
    qint64 firstBadCrc = -1;
    const QString file = QFileInfo(m_dataFile).fileName();
    while (at < size) {
        const auto header = PacketHeader::read(QByteArrayView(bytes + at, size - at));
        if (!header) {
            if (size - at < 20)
                m_damage = QStringLiteral("%1: cut at byte %2: %3 bytes left, less than a packet's header")
                               .arg(file).arg(at).arg(size - at);
            else
                m_damage = QStringLiteral("%1: at byte %2: no IMC sync number (0x%3)")
                               .arg(file).arg(at)
                               .arg(QByteArray(bytes + at, 2).toHex());
            break;
        }
        const qint64 length = header->packetSize();
        if (at + length > size) {
            m_damage = QStringLiteral("%1: cut at byte %2: the packet there (%3) needs %4 bytes, %5 are left")
                           .arg(file).arg(at).arg(header->mgid).arg(length).arg(size - at);
            break;
        }
        const quint16 stored = readAt<quint16>(bytes + at + length - 2, header->bigEndian);
        if (msg::crc16(QByteArrayView(bytes + at, length - 2)) != stored) {
            ++badCrc;
            if (firstBadCrc < 0)
                firstBadCrc = at;
        } else {
            m_offsets.push_back(quint64(at));
            m_times.push_back(header->timestamp);
        }
        at += length;
    }
    m_readBytes = at;
    const QLocale c = QLocale::c();
    if (!m_damage.isEmpty())
        m_damage += QStringLiteral("; read %1 packets up to there").arg(c.toString(qint64(m_offsets.size())));
    if (badCrc > 0) {
        if (!m_damage.isEmpty())
            m_damage += QStringLiteral("; ");
        m_damage += QStringLiteral("%1: %2 packets with a wrong checksum left out (the first at byte %3)")
                        .arg(file).arg(badCrc).arg(firstBadCrc);
    }
}

void LogFile::computeLogTimes()
{
    m_logTimes.resize(m_times.size());
    double latest = -std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < m_times.size(); ++i) {
        // NaN or absurd timestamps do not move the log's clock.
        const double t = m_times[i];
        if (std::isfinite(t) && t > latest && (latest < 0 || t - latest < 86400.0 * 366))
            latest = t;
        m_logTimes[i] = std::isfinite(latest) ? latest : 0.0;
    }
}

bool LogFile::readIndex(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return false;
    IndexHead head{};
    if (file.read(reinterpret_cast<char *>(&head), sizeof head) != qint64(sizeof head))
        return false;
    const QFileInfo data(m_dataFile);
    if (std::memcmp(head.magic, indexMagic, 8) != 0 || head.version != indexVersion
        || head.dataSize != quint64(m_data.size())
        || head.dataModifiedMs != data.lastModified().toMSecsSinceEpoch()
        || file.size() != qint64(sizeof head + head.count * 16))
        return false;
    m_offsets.resize(head.count);
    m_times.resize(head.count);
    const qint64 bytes = qint64(head.count * 8);
    if (file.read(reinterpret_cast<char *>(m_offsets.data()), bytes) != bytes
        || file.read(reinterpret_cast<char *>(m_times.data()), bytes) != bytes) {
        m_offsets.clear();
        m_times.clear();
        return false;
    }
    // A last cheap check: every offset inside the file, in order.
    for (size_t i = 0; i < m_offsets.size(); ++i) {
        if (m_offsets[i] + 22 > quint64(m_data.size()) || (i > 0 && m_offsets[i] <= m_offsets[i - 1])) {
            m_offsets.clear();
            m_times.clear();
            return false;
        }
    }
    m_readBytes = m_data.size();
    return true;
}

namespace {

bool writeFully(int fd, const void *data, std::size_t size)
{
    const char *at = static_cast<const char *>(data);
    while (size > 0) {
        const ssize_t written = ::write(fd, at, size);
        if (written < 0 && errno == EINTR)
            continue;
        if (written <= 0)
            return false;
        at += written;
        size -= std::size_t(written);
    }
    return true;
}

} // namespace

void LogIndexWriter::open(const QString &dataFile)
{
    abandon();
    m_dataFile = dataFile;
    m_count = 0;
    m_offsetsFd = ::open(QFile::encodeName(dataFile + QStringLiteral(".index.partial")).constData(),
                         O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    m_timesFd = ::open(QFile::encodeName(dataFile + QStringLiteral(".times.partial")).constData(),
                       O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    const IndexHead placeholder{};
    if (m_offsetsFd < 0 || m_timesFd < 0 || !writeFully(m_offsetsFd, &placeholder, sizeof placeholder))
        abandon();
}

void LogIndexWriter::append(const std::vector<quint64> &offsets, const std::vector<double> &times)
{
    if (m_offsetsFd < 0 || offsets.size() != times.size())
        return;
    if (!writeFully(m_offsetsFd, offsets.data(), offsets.size() * 8) || !writeFully(m_timesFd, times.data(), times.size() * 8)) {
        abandon();
        return;
    }
    m_count += offsets.size();
}

bool LogIndexWriter::finish()
{
    if (m_offsetsFd < 0)
        return false;
    // The timestamps after the offsets, then the head that says what was indexed.
    bool ok = ::lseek(m_timesFd, 0, SEEK_SET) == 0;
    std::vector<char> buffer(1 << 20);
    while (ok) {
        const ssize_t read = ::read(m_timesFd, buffer.data(), buffer.size());
        if (read < 0 && errno == EINTR)
            continue;
        if (read <= 0) {
            ok = read == 0;
            break;
        }
        ok = writeFully(m_offsetsFd, buffer.data(), std::size_t(read));
    }
    const QFileInfo data(m_dataFile);
    IndexHead head{};
    std::memcpy(head.magic, indexMagic, 8);
    head.version = indexVersion;
    head.dataSize = quint64(data.size());
    head.dataModifiedMs = data.lastModified().toMSecsSinceEpoch();
    head.count = m_count;
    ok = ok && ::pwrite(m_offsetsFd, &head, sizeof head, 0) == ssize_t(sizeof head) && ::fdatasync(m_offsetsFd) == 0;
    const QString partial = m_dataFile + QStringLiteral(".index.partial");
    ::close(m_offsetsFd);
    ::close(m_timesFd);
    m_offsetsFd = m_timesFd = -1;
    QFile::remove(m_dataFile + QStringLiteral(".times.partial"));
    ok = ok && ::rename(QFile::encodeName(partial).constData(), QFile::encodeName(m_dataFile + QStringLiteral(".index")).constData()) == 0;
    if (!ok)
        QFile::remove(partial);
    return ok;
}

void LogIndexWriter::abandon()
{
    if (m_offsetsFd < 0 && m_timesFd < 0)
        return;
    for (int *fd : {&m_offsetsFd, &m_timesFd}) {
        if (*fd >= 0)
            ::close(*fd);
        *fd = -1;
    }
    QFile::remove(m_dataFile + QStringLiteral(".index.partial"));
    QFile::remove(m_dataFile + QStringLiteral(".times.partial"));
}

bool writeLogIndex(const QString &dataFile, const std::vector<quint64> &offsets, const std::vector<double> &times)
{
    QSaveFile file(dataFile + QStringLiteral(".index"));
    if (!file.open(QIODevice::WriteOnly) || offsets.size() != times.size())
        return false; // a read-only folder: the next open scans again
    const QFileInfo data(dataFile);
    IndexHead head{};
    std::memcpy(head.magic, indexMagic, 8);
    head.version = indexVersion;
    head.dataSize = quint64(data.size());
    head.dataModifiedMs = data.lastModified().toMSecsSinceEpoch();
    head.count = offsets.size();
    file.write(reinterpret_cast<const char *>(&head), sizeof head);
    file.write(reinterpret_cast<const char *>(offsets.data()), qint64(offsets.size() * 8));
    file.write(reinterpret_cast<const char *>(times.data()), qint64(times.size() * 8));
    return file.commit();
}

QByteArrayView LogFile::packet(qsizetype i) const
{
    const qint64 at = offset(i);
    const quint16 size = readAt<quint16>(m_data.constData() + at + 4, bigEndian(i));
    return QByteArrayView(m_data.constData() + at, 22 + qsizetype(size));
}

bool LogFile::bigEndian(qsizetype i) const
{
    return readAt<quint16>(m_data.constData() + offset(i), false) == 0x54FE;
}

quint16 LogFile::messageId(qsizetype i) const
{
    return readAt<quint16>(m_data.constData() + offset(i) + 2, bigEndian(i));
}

quint16 LogFile::source(qsizetype i) const
{
    return readAt<quint16>(m_data.constData() + offset(i) + 14, bigEndian(i));
}

quint8 LogFile::sourceEntity(qsizetype i) const
{
    return quint8(m_data.at(offset(i) + 16));
}

quint16 LogFile::destination(qsizetype i) const
{
    return readAt<quint16>(m_data.constData() + offset(i) + 17, bigEndian(i));
}

qsizetype LogFile::lowerBound(double t) const
{
    return std::lower_bound(m_logTimes.begin(), m_logTimes.end(), t) - m_logTimes.begin();
}

std::expected<msg::Message, msg::CodecError> LogFile::decode(qsizetype i) const
{
    // What the recording console sent is in its destination's definitions.
    if (m_recorder != 0xFFFF && source(i) == m_recorder)
        return m_schemas->codecFor(destination(i))->decode(packet(i));
    return m_schemas->decode(packet(i));
}

} // namespace neptus::log
