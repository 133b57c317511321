#pragma once

#include "log/LogFile.h"

#include <QByteArray>
#include <QByteArrayView>
#include <QMutex>
#include <QObject>
#include <QString>
#include <QStringList>

#include <condition_variable>
#include <expected>
#include <mutex>
#include <thread>
#include <vector>

namespace neptus::log {

struct RecorderConfig
{
    // Logs go to <root>/<yyyyMMdd>/<HHmmss>-<name>/ (UTC), one folder per part.
    QString root;
    QString name = QStringLiteral("console");
    quint16 system = 0xFFFF; // the recording console's IMC id, for Meta.json
    // The console's definition files: the first (with the packet header)
    // becomes IMC.xml, the others are kept beside it and named in Meta.json.
    QStringList definitionFiles;
    // Systems that speak other definitions: (id or name, file).
    QList<std::pair<QString, QString>> definitionsFor;
    // A part ends and the next begins past this size or this age.
    qint64 maxPartBytes = qint64(1) << 30;
    qint64 maxPartMs = 3600 * 1000;
    // Queued packets reach the file at least this often: a crash loses at most this much.
    int flushMs = 200;
    // Past this much waiting to be written (a stalled disk), packets are counted as lost.
    qint64 maxQueuedBytes = qint64(64) << 20;
};

// Records every packet a console receives and sends, as the IMC world's log
// (LogFile): Data.lsf written as packets come, IMC.xml and Meta.json when a
// part begins, Data.lsf.index when it ends. record() only copies the bytes
// into a queue under a short lock; a thread of its own writes them, so the
// GUI and the links never wait on the disk. A write that fails (a full disk)
// is undone to the last whole packet, counted, said by problemChanged, and
// tried again with the next batch: the console carries on.
class Recorder : public QObject
{
    Q_OBJECT

public:
    explicit Recorder(RecorderConfig config, QObject *parent = nullptr);
    ~Recorder() override;

    // Makes the first part's folder and starts writing; an error says why not.
    std::expected<void, QString> start();
    // Writes what is queued, ends the part (with its index) and the thread.
    void stop();

    // One IMC packet, exactly as on the wire. Any thread.
    void record(QByteArrayView packet);
    // One MAVLink frame, received or sent, as on the wire: it goes to
    // mavlink.tlog beside Data.lsf (made with the first frame), the tlog
    // format MAVProxy, pymavlink and QGroundControl read (each frame after
    // its time, 8 bytes big-endian, microseconds since 1970). Any thread.
    void recordMavlink(QByteArrayView frame);

    struct Status
    {
        QString folder;      // the part being written
        quint64 packets = 0; // written, all parts
        quint64 bytes = 0;
        quint64 lost = 0;    // not written: the disk refused them or the queue was full
        int parts = 0;
        QString problem;     // empty when recording well
    };
    Status status() const;

signals:
    // Why recording fails now, or "" when it works again (queued to this object's thread).
    void problemChanged(const QString &problem);
    // A part began (the first one, or after rotation).
    void partStarted(const QString &folder);

private:
    void run();
    // Writes one batch of whole packets; rotates between packets.
    void writeBatch(const QByteArray &batch, qint64 lostInQueue);
    void writeTlog(const QByteArray &frames);
    bool beginPart();
    void endPart();
    bool writeAll(const char *data, qint64 size);
    void setProblem(const QString &problem);

    RecorderConfig m_config;
    std::thread m_thread;
    std::mutex m_queueMutex;
    std::condition_variable m_wake;
    QByteArray m_queue;
    QByteArray m_tlogQueue;
    qint64 m_queueLost = 0; // packets dropped because the queue was full
    bool m_stopping = false;
    bool m_running = false;

    // The writer thread's own state.
    int m_fd = -1;
    int m_tlogFd = -1; // mavlink.tlog of the part, once a frame came
    QString m_partFolder;
    qint64 m_partBytes = 0;
    qint64 m_partStartedMs = 0;
    qint64 m_partAttemptMs = 0;
    LogIndexWriter m_index;
    std::vector<quint64> m_batchOffsets; // of the batch being written, then appended to m_index
    std::vector<double> m_batchTimes;

    mutable QMutex m_statusMutex;
    Status m_status;
};

} // namespace neptus::log
