#pragma once

#include "messages/SchemaSet.h"

#include <QByteArray>
#include <QString>

#include <expected>
#include <memory>
#include <vector>

namespace neptus::log {

// The IMC world's log, as DUNE, Neptus and our recorder write it: a folder
// holding Data.lsf (IMC packets one after another, exactly as on the wire;
// or Data.lsf.gz) and IMC.xml (or IMC.xml.gz), the definitions the packets
// were written with. Ours adds Meta.json (who recorded, extra definition
// files, definitions of systems that speak another IMC) and Data.lsf.index
// (where each packet starts and its time, so a long log opens at once).
//
// Opened, a log is its packets in file order with their times. A packet's
// `time` is its header's timestamp; its `logTime` never goes back (the
// latest timestamp so far): vehicles queue messages and send them late, and
// replay and seek need one order. A damaged or cut log is read up to the
// damage; damage() says where, by byte offset. Read-only and thread-safe
// once opened.
class LogFile
{
public:
    struct Options
    {
        // Definitions to use when the folder has no IMC.xml (a bare Data.lsf).
        std::shared_ptr<const msg::Schema> fallbackDefinitions;
        // Write Data.lsf.index beside an uncompressed log that lacks a valid one.
        bool writeIndex = true;
        // Larger logs are refused (an uncompressed Data.lsf.gz is held in memory).
        qint64 maxBytes = qint64(16) << 30;
    };

    // `path` is the log's folder or its Data.lsf / Data.lsf.gz. An error says
    // what is missing or unreadable, naming the file.
    static std::expected<std::shared_ptr<const LogFile>, QString> open(const QString &path, const Options &options);
    static std::expected<std::shared_ptr<const LogFile>, QString> open(const QString &path)
    {
        return open(path, Options{});
    }

    // The packets of a log already in memory (tests, fuzzing): no files read or written.
    static std::shared_ptr<const LogFile> fromData(QByteArray data, std::shared_ptr<msg::SchemaSet> schemas,
                                                   const QString &name = QStringLiteral("Data.lsf"));

    QString folder() const { return m_folder; }
    QString dataFile() const { return m_dataFile; }
    // Empty when the whole file was read; else where and why reading stopped
    // ("Data.lsf: at byte 81920: no IMC sync number (0x0000); read 1,204 packets up to there").
    QString damage() const { return m_damage; }
    // Where reading stopped (the file's size when whole).
    qint64 readBytes() const { return m_readBytes; }
    bool indexReused() const { return m_indexReused; }

    // The definitions: the log's own (IMC.xml), and other systems' own.
    const msg::SchemaSet &schemas() const { return *m_schemas; }
    std::shared_ptr<msg::SchemaSet> sharedSchemas() const { return m_schemas; }
    // The system that recorded the log (our Meta.json), 0xFFFF when unknown.
    quint16 recorder() const { return m_recorder; }
    QString recorderName() const { return m_recorderName; }

    qsizetype count() const { return qsizetype(m_offsets.size()); }
    QByteArrayView packet(qsizetype i) const;
    qint64 offset(qsizetype i) const { return qint64(m_offsets[size_t(i)]); }
    double time(qsizetype i) const { return m_times[size_t(i)]; }
    double logTime(qsizetype i) const { return m_logTimes[size_t(i)]; }
    // Read from the packet's header, without decoding it.
    quint16 messageId(qsizetype i) const;
    quint16 source(qsizetype i) const;
    quint8 sourceEntity(qsizetype i) const;
    quint16 destination(qsizetype i) const;
    // First and last log times (0 when empty).
    double begin() const { return m_logTimes.empty() ? 0 : m_logTimes.front(); }
    double end() const { return m_logTimes.empty() ? 0 : m_logTimes.back(); }
    // The first packet whose log time is at or after `t` (count() if none).
    qsizetype lowerBound(double t) const;

    std::expected<msg::Message, msg::CodecError> decode(qsizetype i) const;

private:
    LogFile() = default;
    // Walks the packets from the start, filling the index; stops at damage.
    void scan();
    bool readIndex(const QString &path);
    void computeLogTimes();
    bool bigEndian(qsizetype i) const;

    QString m_folder;
    QString m_dataFile;
    QString m_damage;
    qint64 m_readBytes = 0;
    bool m_indexReused = false;
    QByteArray m_data; // the packets: a mapped file or decompressed bytes
    std::shared_ptr<class MappedFile> m_mapped;
    std::shared_ptr<msg::SchemaSet> m_schemas;
    quint16 m_recorder = 0xFFFF;
    QString m_recorderName;
    std::vector<quint64> m_offsets;
    std::vector<double> m_times;
    std::vector<double> m_logTimes;
};

// Writes Data.lsf.index for `dataFile` (whole, closed) from where its packets
// start and their timestamps; false when it cannot (the log still opens, by scanning).
bool writeLogIndex(const QString &dataFile, const std::vector<quint64> &offsets, const std::vector<double> &times);

// Writes Data.lsf.index while the log is written, a batch of packets at a
// time, so that a recorder holds no index in memory (16 bytes a packet for
// an hour's part was most of a console's growth): the offsets go to
// Data.lsf.index.partial, the timestamps to Data.lsf.times.partial; finish()
// joins them into Data.lsf.index once Data.lsf is closed. Any failure makes
// it give up quietly (the log still opens, by scanning).
class LogIndexWriter
{
public:
    LogIndexWriter() = default;
    ~LogIndexWriter() { abandon(); }
    LogIndexWriter(const LogIndexWriter &) = delete;
    LogIndexWriter &operator=(const LogIndexWriter &) = delete;

    void open(const QString &dataFile);
    void append(const std::vector<quint64> &offsets, const std::vector<double> &times);
    // Data.lsf is closed: its index goes in place. False when it could not be written.
    bool finish();
    void abandon();

private:
    QString m_dataFile;
    int m_offsetsFd = -1, m_timesFd = -1;
    quint64 m_count = 0;
};

// Reads an IMC packet's 20-byte header without decoding (the same in every IMC revision).
struct PacketHeader
{
    quint16 sync = 0, mgid = 0, size = 0;
    double timestamp = 0;
    quint16 src = 0;
    quint8 srcEnt = 0;
    quint16 dst = 0;
    quint8 dstEnt = 0;
    bool bigEndian = false;

    // None unless the bytes start with an IMC sync number, either byte order.
    static std::optional<PacketHeader> read(QByteArrayView bytes);
    qsizetype packetSize() const { return 20 + qsizetype(size) + 2; }
};

} // namespace neptus::log
