// DatagramReader: the IMC socket's own reading thread, its queue per host,
// the turns hosts take and what each loses on its own. Loopback only.
#include "transport/DatagramReader.h"

#include <QThread>
#include <QUdpSocket>

#include <gtest/gtest.h>

#include <atomic>

#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

using neptus::transport::DatagramReader;

namespace {

// A non-blocking UDP socket on 127.0.0.1, any port, for the reader.
struct Socket
{
    Socket()
    {
        fd = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        ::bind(fd, reinterpret_cast<sockaddr *>(&address), sizeof address);
        socklen_t size = sizeof address;
        ::getsockname(fd, reinterpret_cast<sockaddr *>(&address), &size);
        port = ntohs(address.sin_port);
    }
    ~Socket() { ::close(fd); }
    int fd = -1;
    quint16 port = 0;
};

// Sends `count` datagrams "<host>/<n>" from `host` to `port`.
void sendFrom(const char *host, quint16 port, int count)
{
    QUdpSocket sender;
    ASSERT_TRUE(sender.bind(QHostAddress(QString::fromLatin1(host)), 0));
    for (int i = 0; i < count; ++i)
        sender.writeDatagram(QByteArray(host) + '/' + QByteArray::number(i), QHostAddress::LocalHost, port);
}

QString hostOf(const DatagramReader::Datagram &d)
{
    return d.from.toString();
}

} // namespace

TEST(DatagramReader, HostsTakeTurnsAndAFullQueueLosesOnlyItsOwn)
{
    Socket socket;
    std::atomic<int> wakes{0};
    DatagramReader::Limits limits;
    limits.queuedPerHost = 100;
    DatagramReader reader({socket.fd}, limits, [&] { ++wakes; });

    sendFrom("127.0.0.2", socket.port, 300);
    sendFrom("127.0.0.3", socket.port, 3);
    QThread::msleep(300); // loopback delivers at once; the reader thread reads meanwhile
    EXPECT_EQ(wakes.load(), 1) << "told once while datagrams wait";

    const DatagramReader::Batch first = reader.take(8);
    ASSERT_EQ(first.datagrams.size(), 8u);
    QStringList order;
    for (const auto &d : first.datagrams)
        order << hostOf(d);
    EXPECT_EQ(order, (QStringList{"127.0.0.2", "127.0.0.3", "127.0.0.2", "127.0.0.3", "127.0.0.2", "127.0.0.3",
                                  "127.0.0.2", "127.0.0.2"}));
    EXPECT_EQ(first.datagrams[0].bytes, QByteArray("127.0.0.2/0")) << "in the order sent";
    EXPECT_EQ(first.behind.value(QStringLiteral("127.0.0.2")), 200) << "past its queue of 100";
    EXPECT_FALSE(first.behind.contains(QStringLiteral("127.0.0.3")));
    EXPECT_TRUE(first.more);

    const DatagramReader::Batch rest = reader.take(1000);
    EXPECT_EQ(rest.datagrams.size(), 100u + 3u - 8u);
    EXPECT_EQ(rest.datagrams.back().bytes, QByteArray("127.0.0.2/99"));
    EXPECT_TRUE(rest.behind.isEmpty() && rest.dropped.isEmpty()) << "reported once";
    EXPECT_FALSE(rest.more);

    sendFrom("127.0.0.3", socket.port, 1);
    QThread::msleep(100);
    EXPECT_EQ(wakes.load(), 2) << "told again once the queues were emptied";
}

TEST(DatagramReader, AHostOverItsRateLosesTheRestOfTheSecond)
{
    Socket socket;
    DatagramReader::Limits limits;
    limits.datagramsPerSecond = 50;
    DatagramReader reader({socket.fd}, limits, [] {});
    sendFrom("127.0.0.4", socket.port, 200);
    QThread::msleep(300);
    const DatagramReader::Batch batch = reader.take(1000);
    // Sent within a second (a slow machine may straddle two).
    EXPECT_GE(batch.datagrams.size(), 50u);
    EXPECT_LE(batch.datagrams.size(), 100u);
    EXPECT_EQ(batch.datagrams.size() + size_t(batch.dropped.value(QStringLiteral("127.0.0.4"))), 200u);
}
