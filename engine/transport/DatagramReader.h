#pragma once

#include <QByteArray>
#include <QHash>
#include <QHostAddress>

#include <atomic>
#include <deque>
#include <expected>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace neptus::transport {

// Reads UDP sockets on a thread of its own, so that datagrams keep being
// taken from the kernel (whose buffer would otherwise overflow and drop them
// unread, a vehicle's with a flood's) however long the GUI thread is busy.
//
// What arrives waits in one bounded queue per sending host; a host over its
// rate (datagrams a second; 0: no limit) or with a full queue (whoever takes
// them fell behind) loses its own datagrams, counted apart, and never another
// host's. take() hands them out one host at a time in turn, so a vehicle's
// datagrams are never stuck behind a flooding host's.
class DatagramReader
{
public:
    struct Datagram
    {
        QByteArray bytes;
        QHostAddress from;
        quint16 port = 0;
        QString host; // hostName(from)
    };
    struct Batch
    {
        std::vector<Datagram> datagrams;
        QHash<QString, int> dropped; // by host, since the last take(): over its rate
        QHash<QString, int> behind;  // by host: its queue was full (the taker fell behind)
        bool more = false;           // some still wait
    };
    struct Limits
    {
        int datagramsPerSecond = 0;       // per host; 0: no limit
        int queuedPerHost = 4096;         // datagrams
        qsizetype queuedBytesPerHost = 4 << 20;
        int hosts = 1024;                 // queues kept at once; datagrams from more are dropped
    };

    // Starts reading `fds` (non-blocking UDP sockets, still owned by the
    // caller and open until this is destroyed). `wake` is called on the
    // reader's thread when datagrams wait and nobody was told yet; it is
    // told again after a take() that left none.
    DatagramReader(std::vector<int> fds, Limits limits, std::function<void()> wake);
    ~DatagramReader();
    DatagramReader(const DatagramReader &) = delete;
    DatagramReader &operator=(const DatagramReader &) = delete;

    // Up to `max` waiting datagrams, one host at a time in turn.
    Batch take(int max);

    // How a sending host is named in counts and alarms: "127.0.0.1", also
    // for an IPv4 address in IPv6 form.
    static QString hostName(const QHostAddress &address);

private:
    struct Host
    {
        QHostAddress address;
        QString name;
        std::deque<Datagram> queue;
        qsizetype bytes = 0;
        qint64 secondStartMs = 0;
        int count = 0;   // admitted in the current second
        int dropped = 0; // over its rate, since the last take()
        int behind = 0;  // its queue full, since the last take()
    };

    // A sender's address as the hash key (IPv4 in `low`), made without allocating.
    struct Key
    {
        quint64 high = 0, low = 0;
        bool operator==(const Key &) const = default;
        friend size_t qHash(const Key &key, size_t seed = 0) { return qHashMulti(seed, key.high, key.low); }
    };

    void run();
    void readAll(int fd);
    void admitLocked(const char *data, qsizetype size, const void *from, quint16 port, const Key &key);
    static constexpr std::size_t batch = 32; // datagrams a system call

    const std::vector<int> m_fds;
    const Limits m_limits;
    const std::function<void()> m_wake;
    int m_stopFd = -1;
    QByteArray m_buffers; // the reader thread's: `batch` datagrams

    std::mutex m_mutex; // guards everything below
    QHash<Key, Host> m_hosts;  // by address
    std::deque<Key> m_turns;   // hosts with datagrams waiting, in turn
    int m_droppedUnqueued = 0;       // from hosts beyond Limits::hosts
    bool m_dropped = false;          // some host dropped since the last take()
    qint64 m_prunedMs = 0;           // when quiet hosts were last let go
    bool m_told = false;             // wake was called and no take() emptied the queues since

    std::thread m_thread;
};

// Sends one datagram from the UDP socket `fd` to `to`:`port` (an IPv4
// address goes as IPv4 unless the socket is IPv6-only); an error says why.
std::expected<void, QString> sendDatagram(int fd, QByteArrayView bytes, const QHostAddress &to, quint16 port, bool ipv6Socket);

} // namespace neptus::transport
