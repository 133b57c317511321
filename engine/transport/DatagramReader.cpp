#include "transport/DatagramReader.h"

#include "core/Clock.h"

#include <array>
#include <cerrno>
#include <cstring>

#include <netinet/in.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <unistd.h>

namespace neptus::transport {

namespace {

constexpr std::size_t largestDatagram = 65536;
// Datagrams read from one socket before looking at the others.
constexpr int readsPerSocket = 512;

} // namespace

QString DatagramReader::hostName(const QHostAddress &address)
{
    bool isIpv4 = false;
    const quint32 ipv4 = address.toIPv4Address(&isIpv4);
    return isIpv4 ? QHostAddress(ipv4).toString() : address.toString();
}

DatagramReader::DatagramReader(std::vector<int> fds, Limits limits, std::function<void()> wake)
    : m_fds(std::move(fds))
    , m_limits(limits)
    , m_wake(std::move(wake))
    , m_stopFd(::eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK))
    , m_buffers(qsizetype(largestDatagram * batch), Qt::Uninitialized)
{
    for (const int fd : m_fds) {
        // Room for bursts while the reader is not scheduled (the kernel caps it).
        const int size = 4 << 20;
        ::setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &size, sizeof size);
    }
    m_thread = std::thread([this] { run(); });
}

DatagramReader::~DatagramReader()
{
    const quint64 one = 1;
    if (::write(m_stopFd, &one, sizeof one) != sizeof one)
        std::terminate(); // an eventfd write cannot fail short of a broken descriptor
    m_thread.join();
    ::close(m_stopFd);
}

void DatagramReader::run()
{
    std::vector<pollfd> polls;
    for (const int fd : m_fds)
        polls.push_back({fd, POLLIN, 0});
    polls.push_back({m_stopFd, POLLIN, 0});
    for (;;) {
        if (::poll(polls.data(), polls.size(), -1) < 0 && errno != EINTR)
            return;
        if (polls.back().revents != 0)
            return;
        for (std::size_t i = 0; i + 1 < polls.size(); ++i) {
            if (polls[i].revents != 0)
                readAll(polls[i].fd);
        }
    }
}

void DatagramReader::readAll(int fd)
{
    // Up to `batch` datagrams a call (a flood costs one system call per
    // batch, not per datagram), queued under one lock.
    std::array<mmsghdr, batch> messages{};
    std::array<iovec, batch> buffers{};
    std::array<sockaddr_storage, batch> senders{};
    for (int read = 0; read < readsPerSocket;) {
        for (std::size_t i = 0; i < batch; ++i) {
            buffers[i] = {m_buffers.data() + i * largestDatagram, largestDatagram};
            messages[i].msg_hdr = {};
            messages[i].msg_hdr.msg_iov = &buffers[i];
            messages[i].msg_hdr.msg_iovlen = 1;
            messages[i].msg_hdr.msg_name = &senders[i];
            messages[i].msg_hdr.msg_namelen = sizeof senders[i];
        }
        const int count = ::recvmmsg(fd, messages.data(), batch, MSG_DONTWAIT, nullptr);
        if (count < 0) {
            if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)
                return; // all read
            ++read;     // an error report (an ICMP port unreachable for a datagram we sent): read on
            continue;
        }
        read += count;
        bool tell = false;
        {
            std::lock_guard lock(m_mutex);
            for (int i = 0; i < count; ++i) {
                const auto &from = senders[size_t(i)];
                Key key;
                quint16 port = 0;
                if (from.ss_family == AF_INET) {
                    const auto *v4 = reinterpret_cast<const sockaddr_in *>(&from);
                    key.low = v4->sin_addr.s_addr;
                    port = ntohs(v4->sin_port);
                } else if (from.ss_family == AF_INET6) {
                    const auto *v6 = reinterpret_cast<const sockaddr_in6 *>(&from);
                    std::memcpy(&key.high, &v6->sin6_addr, sizeof key.high);
                    std::memcpy(&key.low, reinterpret_cast<const char *>(&v6->sin6_addr) + sizeof key.high, sizeof key.low);
                    port = ntohs(v6->sin6_port);
                } else {
                    continue;
                }
                const char *data = static_cast<const char *>(buffers[size_t(i)].iov_base);
                admitLocked(data, qsizetype(messages[size_t(i)].msg_len), &from, port, key);
            }
            tell = !m_told && !m_turns.empty();
            m_told = m_told || tell;
        }
        if (tell)
            m_wake();
    }
}

void DatagramReader::admitLocked(const char *data, qsizetype size, const void *from, quint16 port, const Key &key)
{
    auto host = m_hosts.find(key);
    if (host == m_hosts.end()) {
        if (m_hosts.size() >= m_limits.hosts) {
            ++m_droppedUnqueued;
            m_dropped = true;
            return;
        }
        const QHostAddress address(static_cast<const sockaddr *>(from));
        host = m_hosts.insert(key, Host{address, hostName(address), {}, 0, 0, 0, 0, 0});
    }
    const qint64 now = monotonicMs();
    if (now - host->secondStartMs >= 1000) {
        host->secondStartMs = now;
        host->count = 0;
    }
    const bool overRate = m_limits.datagramsPerSecond > 0 && host->count >= m_limits.datagramsPerSecond;
    const bool full = qsizetype(host->queue.size()) >= m_limits.queuedPerHost
                      || host->bytes + size > m_limits.queuedBytesPerHost;
    if (overRate || full) {
        ++(overRate ? host->dropped : host->behind);
        m_dropped = true;
        return;
    }
    ++host->count;
    if (host->queue.empty())
        m_turns.push_back(key);
    host->queue.push_back({QByteArray(data, size), host->address, port, host->name});
    host->bytes += size;
}

DatagramReader::Batch DatagramReader::take(int max)
{
    Batch batch;
    std::lock_guard lock(m_mutex);
    while (int(batch.datagrams.size()) < max && !m_turns.empty()) {
        const Key key = m_turns.front();
        m_turns.pop_front();
        Host &host = m_hosts[key];
        host.bytes -= host.queue.front().bytes.size();
        batch.datagrams.push_back(std::move(host.queue.front()));
        host.queue.pop_front();
        if (!host.queue.empty())
            m_turns.push_back(key);
    }
    // Drops are collected, and quiet hosts let go, only when there are some
    // or once a second: not a walk over every host on each take.
    const qint64 now = monotonicMs();
    const bool prune = now - m_prunedMs >= 1000;
    if (m_dropped || prune) {
        for (auto it = m_hosts.begin(); it != m_hosts.end();) {
            if (it->dropped > 0) {
                batch.dropped[it->name] += it->dropped;
                it->dropped = 0;
            }
            if (it->behind > 0) {
                batch.behind[it->name] += it->behind;
                it->behind = 0;
            }
            // A host quiet for two seconds keeps no queue (nor a rate window).
            if (prune && it->queue.empty() && now - it->secondStartMs > 2000)
                it = m_hosts.erase(it);
            else
                ++it;
        }
        m_dropped = false;
        if (prune)
            m_prunedMs = now;
    }
    if (m_droppedUnqueued > 0) {
        batch.dropped[QStringLiteral("other hosts")] += m_droppedUnqueued;
        m_droppedUnqueued = 0;
    }
    batch.more = !m_turns.empty();
    m_told = batch.more;
    return batch;
}

std::expected<void, QString> sendDatagram(int fd, QByteArrayView bytes, const QHostAddress &to, quint16 port, bool ipv6Socket)
{
    if (fd < 0)
        return std::unexpected(QStringLiteral("not started"));
    sockaddr_storage address{};
    socklen_t size = 0;
    bool isIpv4 = false;
    const quint32 ipv4 = to.toIPv4Address(&isIpv4);
    if (isIpv4 && !ipv6Socket) {
        auto *v4 = reinterpret_cast<sockaddr_in *>(&address);
        v4->sin_family = AF_INET;
        v4->sin_port = htons(port);
        v4->sin_addr.s_addr = htonl(ipv4);
        size = sizeof *v4;
    } else {
        auto *v6 = reinterpret_cast<sockaddr_in6 *>(&address);
        v6->sin6_family = AF_INET6;
        v6->sin6_port = htons(port);
        const Q_IPV6ADDR raw = to.toIPv6Address();
        std::memcpy(&v6->sin6_addr, raw.c, sizeof v6->sin6_addr);
        size = sizeof *v6;
    }
    if (::sendto(fd, bytes.data(), size_t(bytes.size()), 0, reinterpret_cast<sockaddr *>(&address), size) != bytes.size())
        return std::unexpected(qt_error_string(errno));
    return {};
}

} // namespace neptus::transport
