#pragma once

// Loopback ports for tests that start programs or servers of their own.

#include <QHostAddress>
#include <QTcpServer>
#include <QUdpSocket>

namespace neptus::test {

// A UDP port free on 127.0.0.1 now (for a program's IMC link).
inline quint16 freeUdpPort()
{
    QUdpSocket probe;
    probe.bind(QHostAddress::LocalHost, 0);
    return probe.localPort();
}

// A TCP port on 127.0.0.1 that nobody listens on (once this returns).
inline quint16 closedTcpPort()
{
    QTcpServer probe;
    probe.listen(QHostAddress::LocalHost, 0);
    return probe.serverPort();
}

} // namespace neptus::test
