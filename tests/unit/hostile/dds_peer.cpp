// A DDS participant without keys, for tst_dds_security (a process of its own:
// Cyclone gives every participant of one process the same security set-up).
//   dds-peer DOMAIN SECONDS
// Sends, as 0x4002, an Abort to 0x0023 and an EstimatedState every 100 ms;
// at the end prints "heard N" (messages it received) and exits 0.
#include "transport/dds/DdsTransport.h"

#include "Schemas.h"

#include <QCoreApplication>
#include <QTimer>

#include <cstdio>

using namespace neptus;

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    if (args.size() != 3) {
        std::fprintf(stderr, "usage: dds-peer DOMAIN SECONDS\n");
        return 2;
    }
    transport::DdsTransport peer(test::shippedSchema(),
                                 transport::DdsConfig{dds_domainid_t(args[1].toUInt()), {}, 0x4002, QStringLiteral("no-keys")});
    if (auto started = peer.start(); !started) {
        std::fprintf(stderr, "dds-peer: %s\n", qPrintable(started.error()));
        return 1;
    }
    int heard = 0;
    QObject::connect(&peer, &transport::DdsTransport::received, [&] { ++heard; });
    QTimer tick;
    QObject::connect(&tick, &QTimer::timeout, [&] {
        peer.publish(0x23, msg::Message(test::shippedSchema()->byAbbrev(u"Abort")));
        peer.broadcast(msg::Message(test::shippedSchema()->byAbbrev(u"EstimatedState")));
    });
    tick.start(100);
    QTimer::singleShot(args[2].toInt() * 1000, &app, &QCoreApplication::quit);
    app.exec();
    std::printf("heard %d\n", heard);
    return 0;
}
