// neptus-sim: one simulated vehicle speaking IMC over UDP on loopback, as a
// DUNE vehicle does: it streams to the consoles it hears a Heartbeat from,
// announces itself, answers EntityList and EntityInfo queries, and prints
// every command addressed to it, and runs plans (PlanDB, PlanControl; see
// sim::PlanEngine). With --like-dune it is as strict as a stock DUNE vehicle
// (IMC discovery only, unknown senders ignored, the first transition out of
// each maneuver whatever its condition). Faults and a communications drop
// can be switched on from the command line.
#include "core/DataFiles.h"
#include "messages/Codec.h"
#include "transport/dds/DdsTransport.h"
#include "sim/SimulatedVehicle.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDateTime>
#include <QElapsedTimer>
#include <QHash>
#include <QNetworkDatagram>
#include <QRegularExpression>
#include <QSet>
#include <QNetworkInterface>
#include <QTimer>
#include <QUdpSocket>

#include <cstdio>

using namespace neptus;

namespace {

// IMC's discovery ports on loopback.
QList<std::pair<QHostAddress, quint16>> imcDiscoveryPorts()
{
    QList<std::pair<QHostAddress, quint16>> ports;
    for (quint16 port = 30100; port <= 30104; ++port)
        ports.append({QHostAddress::LocalHost, port});
    return ports;
}

int usage(const QString &why)
{
    std::fprintf(stderr, "neptus-sim: %s (see --help)\n", qPrintable(why));
    return 2;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("neptus-sim"));
    QCoreApplication::setApplicationVersion(QStringLiteral(NEPTUS_VERSION));
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("A simulated vehicle speaking IMC over UDP on loopback."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption id(QStringLiteral("id"), QStringLiteral("IMC system id (default 0x1f)."), QStringLiteral("id"), QStringLiteral("0x1f"));
    const QCommandLineOption name(QStringLiteral("name"), QStringLiteral("System name (default lauv-sim-1)."), QStringLiteral("name"), QStringLiteral("lauv-sim-1"));
    const QCommandLineOption kind(QStringLiteral("kind"), QStringLiteral("auv, asv or uav (default auv)."), QStringLiteral("kind"), QStringLiteral("auv"));
    const QCommandLineOption port(QStringLiteral("port"), QStringLiteral("UDP port (default 6002)."), QStringLiteral("port"), QStringLiteral("6002"));
    const QCommandLineOption host(QStringLiteral("host"), QStringLiteral("Address to send and listen on (default 127.0.0.1): another loopback one, such as 127.0.0.2, plays a second host (an impostor with the same --id); one of this machine's interfaces puts the vehicle on that network."), QStringLiteral("address"), QStringLiteral("127.0.0.1"));
    const QCommandLineOption console(QStringLiteral("console"), QStringLiteral("A console to announce to, host:port (repeatable)."), QStringLiteral("host:port"));
    const QCommandLineOption announcePort(QStringLiteral("announce-port"), QStringLiteral("Also announce to this port on 127.0.0.1 (IMC discovery uses 30100)."), QStringLiteral("port"));
    const QCommandLineOption phase(QStringLiteral("phase"), QStringLiteral("Start angle on the track, degrees."), QStringLiteral("degrees"), QStringLiteral("0"));
    const QCommandLineOption fault(QStringLiteral("fault"),
        QStringLiteral("A fault: %1; from the start, or @SECONDS after it, for :SECONDS (navigation-loss@60:20). "
                       "Repeatable. At run time: SetEntityParameters to entity Simulation, parameter Fault = "
                       "battery-drain, comms-loss:20 (for 20 s) or none.")
            .arg(sim::SimulatedVehicle::faultNames().join(QStringLiteral(", "))),
        QStringLiteral("fault[@start[:duration]]"));
    const QCommandLineOption drop(QStringLiteral("comms-drop"), QStringLiteral("Say nothing from second START for DURATION seconds (--fault comms-loss@START:DURATION)."), QStringLiteral("START:DURATION"));
    const QCommandLineOption defs(QStringLiteral("defs"), QStringLiteral("Message definition file (repeatable; default msgdefs/)."), QStringLiteral("file"));
    const QCommandLineOption dds(QStringLiteral("dds"), QStringLiteral("Also publish over Cyclone DDS (loopback configuration)."));
    const QCommandLineOption domain(QStringLiteral("dds-domain"), QStringLiteral("DDS domain id (default 0)."), QStringLiteral("id"), QStringLiteral("0"));
    const QCommandLineOption ddsKeys(QStringLiteral("dds-keys"), QStringLiteral("DDS Security: a key set made by tools/dds-keys, with --dds-identity."), QStringLiteral("dir"));
    const QCommandLineOption ddsIdentity(QStringLiteral("dds-identity"), QStringLiteral("DDS Security: the name this vehicle's keys were made for."), QStringLiteral("name"));
    const QCommandLineOption dune(QStringLiteral("like-dune"),
        QStringLiteral("Behave as a stock DUNE vehicle: announce only to the IMC discovery ports (127.0.0.1:30100-30104) "
                       "and listen there, take messages only from systems that announced themselves, stream to those "
                       "heard from in the last 30 s, send the EntityList only when asked, follow the first transition "
                       "out of each maneuver whatever its condition."));
    const QCommandLineOption timeFactor(QStringLiteral("time-factor"),
        QStringLiteral("Simulated seconds per real second (default 1; 20 runs a 10-minute plan in 30 s). Messages "
                       "still go out at their usual rates in real time."), QStringLiteral("factor"), QStringLiteral("1"));
    const QCommandLineOption transitions(QStringLiteral("transitions"),
        QStringLiteral("conditions (default): after a maneuver, the first transition whose condition holds; first: "
                       "the first transition whatever its condition, as DUNE does (also with --like-dune)."),
        QStringLiteral("conditions|first"), QStringLiteral("conditions"));
    parser.addOptions({id, name, kind, port, host, console, announcePort, phase, fault, drop, defs, dds, domain, ddsKeys,
                       ddsIdentity, dune, timeFactor, transitions});
    if (!parser.parse(QCoreApplication::arguments()))
        return usage(parser.errorText());
    if (parser.isSet(QStringLiteral("help")))
        parser.showHelp(0);
    if (parser.isSet(QStringLiteral("version")))
        parser.showVersion();

    auto schema = msg::Schema::load(parser.isSet(defs) ? parser.values(defs)
                                                       : msg::Schema::filesIn(dataPath(QStringLiteral("msgdefs"))));
    if (!schema) {
        std::fprintf(stderr, "neptus-sim: %s\n", qPrintable(schema.error().toString()));
        return 1;
    }
    sim::SimulatedVehicle::Config config;
    bool ok = false;
    const uint idValue = parser.value(id).toUInt(&ok, 0);
    if (!ok || idValue == 0 || idValue >= 0xFFFF)
        return usage(QStringLiteral("--id must be a number from 1 to 65534, not '%1'").arg(parser.value(id)));
    config.id = static_cast<quint16>(idValue);
    config.name = parser.value(name);
    const QString kindName = parser.value(kind).toLower();
    if (kindName == u"auv") config.kind = sim::SimulatedVehicle::Kind::Auv;
    else if (kindName == u"asv") config.kind = sim::SimulatedVehicle::Kind::Asv;
    else if (kindName == u"uav") config.kind = sim::SimulatedVehicle::Kind::Uav;
    else return usage(QStringLiteral("--kind must be auv, asv or uav, not '%1'").arg(parser.value(kind)));
    const uint portValue = parser.value(port).toUInt(&ok);
    if (!ok || portValue == 0 || portValue > 65535)
        return usage(QStringLiteral("--port must be a port number, not '%1'").arg(parser.value(port)));
    const QHostAddress address(parser.value(host));
    if (address.protocol() != QAbstractSocket::IPv4Protocol
        || (!address.isLoopback() && !QNetworkInterface::allAddresses().contains(address)))
        return usage(QStringLiteral("--host must be a 127.x.x.x address or an IPv4 address of this machine, not '%1'")
                         .arg(parser.value(host)));
    config.phase = parser.value(phase).toDouble() * 3.14159265358979 / 180;
    config.services = QStringLiteral("imc+udp://%1:%2/").arg(address.toString()).arg(portValue);
    std::vector<sim::SimulatedVehicle::TimedFault> faults;
    for (const QString &f : parser.values(fault)) {
        auto timed = sim::SimulatedVehicle::parseFault(f);
        if (!timed)
            return usage(QStringLiteral("--fault: ") + timed.error());
        faults.push_back(*timed);
    }
    if (parser.isSet(drop)) {
        auto timed = sim::SimulatedVehicle::parseFault(QStringLiteral("comms-loss@") + parser.value(drop));
        if (!timed || parser.value(drop).count(u':') != 1)
            return usage(QStringLiteral("--comms-drop must look like 30:10"));
        faults.push_back(*timed);
    }
    QList<std::pair<QHostAddress, quint16>> announceTo;
    for (const QString &c : parser.values(console)) {
        const qsizetype colon = c.lastIndexOf(u':');
        if (colon <= 0)
            return usage(QStringLiteral("--console must look like 127.0.0.1:6001, not '%1'").arg(c));
        announceTo.append({QHostAddress(c.left(colon)), static_cast<quint16>(c.mid(colon + 1).toUInt())});
    }
    if (parser.isSet(announcePort))
        announceTo.append({QHostAddress::LocalHost, static_cast<quint16>(parser.value(announcePort).toUInt())});

    const double factor = parser.value(timeFactor).toDouble(&ok);
    if (!ok || !(factor > 0) || factor > 1000)
        return usage(QStringLiteral("--time-factor must be a number above 0 and at most 1000, not '%1'").arg(parser.value(timeFactor)));
    const QString transitionMode = parser.value(transitions);
    if (transitionMode != u"conditions" && transitionMode != u"first")
        return usage(QStringLiteral("--transitions must be conditions or first, not '%1'").arg(transitionMode));
    const bool likeDune = parser.isSet(dune);
    config.periodicEntityList = !likeDune;
    sim::SimulatedVehicle vehicle(*schema, config);
    for (const auto &f : faults)
        vehicle.scheduleFault(f);
    vehicle.setTimeFactor(factor);
    if (likeDune || transitionMode == u"first")
        vehicle.plans().setTransitions(sim::PlanEngine::Transitions::FirstOnly);
    const msg::Codec codec(*schema);
    QUdpSocket socket;
    if (!socket.bind(address, static_cast<quint16>(portValue))) {
        std::fprintf(stderr, "neptus-sim: cannot listen on %s:%u: %s\n", qPrintable(address.toString()), portValue,
                     qPrintable(socket.errorString()));
        return 1;
    }
    // Like DUNE: listen for announcements on the first free IMC discovery
    // port and announce to all of them.
    QUdpSocket discovery;
    if (likeDune) {
        for (const auto &[address, to] : imcDiscoveryPorts()) {
            if (discovery.bind(address, to))
                break;
            discovery.close();
        }
        if (discovery.state() != QAbstractSocket::BoundState) {
            std::fprintf(stderr, "neptus-sim: no IMC discovery port (30100-30104) is free on 127.0.0.1\n");
            return 1;
        }
        announceTo = imcDiscoveryPorts();
    }
    std::printf("neptus-sim: %s (id 0x%04x) on %s:%u\n", qPrintable(config.name), config.id,
                qPrintable(address.toString()), portValue);
    std::fflush(stdout);

    QElapsedTimer clock;
    clock.start();
    const auto wallTime = [] { return QDateTime::currentMSecsSinceEpoch() / 1000.0; };
    const auto sendTo = [&](const msg::Message &m, const QHostAddress &address, quint16 to) {
        QByteArray packet;
        if (codec.encode(m, packet))
            socket.writeDatagram(packet, address, to);
    };
    // Plain mode: consoles heard from, and when: it streams to them for 5 s after each Heartbeat.
    QHash<QPair<QString, quint16>, qint64> consoles;
    // Like DUNE: systems that announced an imc+udp service, and when they were
    // last heard; it streams to those heard in the last 30 s and ignores the rest.
    struct Peer
    {
        QHostAddress address;
        quint16 port = 0;
        qint64 heardMs = -1;
    };
    QHash<quint16, Peer> peers;
    QSet<quint16> ignored;
    const auto handle = [&](const QNetworkDatagram &datagram) {
        auto message = codec.decode(datagram.data());
        if (!message)
            return;
        const quint16 from = message->header.src;
        if (from == config.id)
            return; // our own Announce on the discovery ports
        if (likeDune) {
            if (message->abbrev() == u"Announce") {
                static const QRegularExpression service(QStringLiteral(R"(imc\+udp://([^:/;]+):(\d+))"));
                const auto match = service.match(message->text(u"services"));
                if (match.hasMatch()) {
                    Peer &peer = peers[from];
                    peer.address = QHostAddress(match.captured(1));
                    peer.port = static_cast<quint16>(match.captured(2).toUInt());
                }
                return;
            }
            if (!peers.contains(from)) {
                if (!ignored.contains(from)) {
                    ignored.insert(from);
                    std::printf("neptus-sim: ignoring 0x%04x: it has not announced itself\n", from);
                    std::fflush(stdout);
                }
                return;
            }
            peers[from].heardMs = clock.elapsed();
        } else if (message->abbrev() == u"Heartbeat") {
            const QPair<QString, quint16> console{datagram.senderAddress().toString(), static_cast<quint16>(datagram.senderPort())};
            if (!consoles.contains(console)) { // a new console: say who we are at once
                for (const msg::Message &m : vehicle.introduction(wallTime()))
                    sendTo(m, datagram.senderAddress(), static_cast<quint16>(datagram.senderPort()));
            }
            consoles[console] = clock.elapsed();
        }
        if (message->header.dst == config.id && message->abbrev() != u"Announce" && message->abbrev() != u"Heartbeat") {
            std::printf("neptus-sim: received %s from 0x%04x\n", qPrintable(message->abbrev()), from);
            std::fflush(stdout);
        }
        for (const msg::Message &reply : vehicle.answer(*message, wallTime())) {
            if (likeDune)
                sendTo(reply, peers[from].address, peers[from].port);
            else
                sendTo(reply, datagram.senderAddress(), static_cast<quint16>(datagram.senderPort()));
        }
    };
    QObject::connect(&socket, &QUdpSocket::readyRead, [&] {
        while (socket.hasPendingDatagrams())
            handle(socket.receiveDatagram());
    });
    QObject::connect(&discovery, &QUdpSocket::readyRead, [&] {
        while (discovery.hasPendingDatagrams())
            handle(discovery.receiveDatagram());
    });
    // Over DDS there is no heartbeat handshake: publish to whoever subscribes.
    std::unique_ptr<transport::DdsTransport> ddsLink;
    if (parser.isSet(dds)) {
        transport::DdsConfig ddsConfig{static_cast<dds_domainid_t>(parser.value(domain).toUInt()), {}, config.id};
        ddsConfig.security = {parser.value(ddsKeys), parser.value(ddsIdentity)};
        ddsLink = std::make_unique<transport::DdsTransport>(*schema, ddsConfig);
        if (auto started = ddsLink->start(); !started) {
            std::fprintf(stderr, "neptus-sim: %s\n", qPrintable(started.error()));
            return 1;
        }
        QObject::connect(ddsLink.get(), &transport::DdsTransport::received, [&](const msg::Message &m) {
            if (m.header.dst == config.id) {
                std::printf("neptus-sim: received %s from 0x%04x over DDS\n", qPrintable(m.abbrev()), m.header.src);
                std::fflush(stdout);
            }
            for (const msg::Message &reply : vehicle.answer(m, wallTime()))
                ddsLink->publish(m.header.src, reply);
        });
    }
    double previous = -1;
    QByteArray buffer;
    QTimer timer;
    QObject::connect(&timer, &QTimer::timeout, [&] {
        const double t = clock.elapsed() / 1000.0;
        const auto messages = vehicle.step(previous, t, QDateTime::currentMSecsSinceEpoch() / 1000.0);
        previous = t;
        if (ddsLink)
            ddsLink->broadcast(messages);
        for (const msg::Message &m : messages) {
            if (!codec.encode(m, buffer))
                continue;
            for (auto it = consoles.cbegin(); it != consoles.cend(); ++it) {
                if (clock.elapsed() - it.value() < 5000)
                    socket.writeDatagram(buffer, QHostAddress(it.key().first), it.key().second);
            }
            for (const Peer &peer : std::as_const(peers)) {
                if (peer.heardMs >= 0 && clock.elapsed() - peer.heardMs < 30000)
                    socket.writeDatagram(buffer, peer.address, peer.port);
            }
            if (m.abbrev() == u"Announce") {
                for (const auto &[address, to] : announceTo)
                    socket.writeDatagram(buffer, address, to);
            }
        }
    });
    timer.start(20);
    return QCoreApplication::exec();
}
