// neptus-sim: simulated vehicles speaking IMC over UDP on loopback (and DDS),
// as DUNE vehicles do: each streams to the consoles it hears a Heartbeat
// from, announces itself, answers EntityList and EntityInfo queries, prints
// every command addressed to it, and runs plans (PlanDB, PlanControl; see
// sim::PlanEngine). With --like-dune it is as strict as a stock DUNE vehicle
// (IMC discovery only, unknown senders ignored, the first transition out of
// each maneuver whatever its condition). Faults can be switched on from the
// command line. One vehicle from the options, or several from --scenario.
// With --mavlink it is instead an ArduPilot vehicle (ArduRover on a boat, or
// ArduSub) speaking MAVLink to a ground station (sim::MavlinkAutopilot).
#include "SimNode.h"

#include "core/DataFiles.h"
#include "sim/MavlinkPeer.h"
#include "sim/Scenario.h"
#include "transport/imc/ImcUdpTransport.h"
#include "transport/mavlink/MavlinkTransport.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFile>
#include <QNetworkInterface>

#include <cstdio>

using namespace neptus;

namespace {

int usage(const QString &why)
{
    std::fprintf(stderr, "neptus-sim: %s (see --help)\n", qPrintable(why));
    return 2;
}

// The --mavlink options, read by name.
int runMavlink(const QCommandLineParser &parser)
{
    const QString mavlink = QStringLiteral("mavlink"), type = QStringLiteral("mavlink-type"), system = QStringLiteral("mavlink-system"),
                  armingFailure = QStringLiteral("arming-failure"), home = QStringLiteral("home"), port = QStringLiteral("port"),
                  host = QStringLiteral("host"), timeFactor = QStringLiteral("time-factor"), key = QStringLiteral("mavlink-key");
    const QString file = dataPath(QStringLiteral("msgdefs/mavlink/ardupilotmega.xml"));
    auto schema = msg::Schema::load({file});
    if (!schema) {
        std::fprintf(stderr, "neptus-sim: %s\n", qPrintable(schema.error().toString()));
        return 1;
    }
    sim::MavlinkPeer::Config config;
    const QString where = parser.value(mavlink);
    if (where.startsWith(u"tcp:")) { // as SITL: listen for the ground station
        bool ok = false;
        const uint tcpPort = where.mid(4).toUInt(&ok);
        if (!ok || tcpPort == 0 || tcpPort > 65535)
            return usage(QStringLiteral("--mavlink tcp:PORT needs a port, not '%1'").arg(where));
        config.tcp = true;
        config.port = quint16(tcpPort);
    } else {
        const auto ground = transport::hostAndPort(where);
        if (!ground)
            return usage(QStringLiteral("--mavlink must look like 127.0.0.1:14550 or tcp:5760, not '%1'").arg(where));
        config.groundAddress = ground->first;
        config.groundPort = ground->second;
    }
    const QString kind = parser.value(type);
    if (kind != u"boat" && kind != u"sub")
        return usage(QStringLiteral("--mavlink-type must be boat or sub, not '%1'").arg(kind));
    config.autopilot.type = kind == u"sub" ? sim::MavlinkAutopilot::Type::Sub : sim::MavlinkAutopilot::Type::Boat;
    bool ok = false;
    const uint id = parser.value(system).toUInt(&ok);
    if (!ok || id < 1 || id > 254)
        return usage(QStringLiteral("--mavlink-system must be from 1 to 254, not '%1'").arg(parser.value(system)));
    config.system = quint8(id);
    config.autopilot.armingFailures = parser.values(armingFailure);
    const QStringList latLon = parser.value(home).split(u',');
    bool latOk = false, lonOk = false;
    const double lat = latLon.value(0).toDouble(&latOk), lon = latLon.value(1).toDouble(&lonOk);
    if (latLon.size() != 2 || !latOk || !lonOk || std::abs(lat) > 90 || std::abs(lon) > 180)
        return usage(QStringLiteral("--home must look like 41.1705,-8.7150, not '%1'").arg(parser.value(home)));
    config.autopilot.home = geo::Geodetic{geo::radians(lat), geo::radians(lon), 0};
    if (!config.tcp)
        config.port = parser.isSet(port) ? quint16(parser.value(port).toUInt()) : 0;
    config.bindAddress = QHostAddress(parser.value(host));
    if (config.bindAddress.isNull())
        return usage(QStringLiteral("--host must be an address, not '%1'").arg(parser.value(host)));
    if (parser.isSet(key)) {
        auto read = transport::mavlinkKeyFromFile(parser.value(key));
        if (!read)
            return usage(QStringLiteral("--mavlink-key: %1").arg(read.error()));
        config.signingKey = *read;
    }
    config.timeFactor = parser.value(timeFactor).toDouble(&ok);
    if (!ok || !(config.timeFactor > 0) || config.timeFactor > 1000)
        return usage(QStringLiteral("--time-factor must be a number above 0 and at most 1000"));
    sim::MavlinkPeer peer(*schema, config);
    if (auto started = peer.start(); !started) {
        std::fprintf(stderr, "neptus-sim: %s\n", qPrintable(started.error()));
        return 1;
    }
    const char *vehicle = kind == u"sub" ? "ardusub" : "ardurover";
    const char *signing = config.signingKey.isEmpty() ? "" : ", signing and taking only signed frames";
    if (config.tcp)
        std::printf("neptus-sim: %s (MAVLink system %u%s) listening on TCP %s:%u, talking to who connects\n", vehicle, id, signing,
                    qPrintable(config.bindAddress.toString()), peer.port());
    else
        std::printf("neptus-sim: %s (MAVLink system %u%s) on %s:%u, talking to %s:%u\n", vehicle, id, signing,
                    qPrintable(config.bindAddress.toString()), peer.port(), qPrintable(config.groundAddress.toString()), config.groundPort);
    std::fflush(stdout);
    return QCoreApplication::exec();
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
    const QCommandLineOption scenario(QStringLiteral("scenario"),
        QStringLiteral("Several vehicles in this process, from a JSON file (see engine/sim/Scenario.h and docs/plans.md): "
                       "ids, names, kinds, ports, positions, DDS, transitions, faults."),
        QStringLiteral("file"));
    const QCommandLineOption mavlink(QStringLiteral("mavlink"),
        QStringLiteral("Be an ArduPilot vehicle speaking MAVLink 2: to the ground station at host:port over UDP (14550 by "
                       "custom), from --port (0: any free one); or tcp:PORT, listening for it as ArduPilot's SITL does (5760)."),
        QStringLiteral("host:port|tcp:port"));
    const QCommandLineOption mavlinkType(QStringLiteral("mavlink-type"),
        QStringLiteral("With --mavlink: boat (ArduRover, default) or sub (ArduSub)."), QStringLiteral("type"), QStringLiteral("boat"));
    const QCommandLineOption mavlinkSystem(QStringLiteral("mavlink-system"),
        QStringLiteral("With --mavlink: its MAVLink system id (default 1)."), QStringLiteral("id"), QStringLiteral("1"));
    const QCommandLineOption armingFailure(QStringLiteral("arming-failure"),
        QStringLiteral("With --mavlink: arming is refused with this reason (\"Gyros inconsistent\"; repeatable)."),
        QStringLiteral("reason"));
    const QCommandLineOption home(QStringLiteral("home"),
        QStringLiteral("With --mavlink: where it starts, lat,lon in degrees (default off Leixões, where every simulated "
                       "vehicle circles and docs/examples/leixoes.xml is)."),
        QStringLiteral("lat,lon"),
        QStringLiteral("%1,%2").arg(sim::SimulatedVehicle::Config{}.latDeg).arg(sim::SimulatedVehicle::Config{}.lonDeg));
    const QCommandLineOption mavlinkKey(QStringLiteral("mavlink-key"),
        QStringLiteral("With --mavlink: sign with the key in this file (a passphrase or 64 hex digits, as the console's "
                       "--mavlink-key) and drop, as ArduPilot does on a telemetry link, every frame not signed with it "
                       "but a radio's RADIO_STATUS."),
        QStringLiteral("file"));
    parser.addOptions({id, name, kind, port, host, console, announcePort, phase, fault, drop, defs, dds, domain, ddsKeys,
                       ddsIdentity, dune, timeFactor, transitions, scenario, mavlink, mavlinkType, mavlinkSystem, armingFailure,
                       home, mavlinkKey});
    if (!parser.parse(QCoreApplication::arguments()))
        return usage(parser.errorText());
    if (parser.isSet(QStringLiteral("help")))
        parser.showHelp(0);
    if (parser.isSet(QStringLiteral("version")))
        parser.showVersion();

    if (parser.isSet(mavlink))
        return runMavlink(parser);

    auto schema = msg::Schema::load(parser.isSet(defs) ? parser.values(defs)
                                                       : msg::Schema::filesIn(dataPath(QStringLiteral("msgdefs"))));
    if (!schema) {
        std::fprintf(stderr, "neptus-sim: %s\n", qPrintable(schema.error().toString()));
        return 1;
    }
    if (parser.isSet(scenario)) {
        for (const QCommandLineOption *single : {&id, &name, &kind, &port, &host, &phase, &fault, &drop, &dune, &transitions})
            if (parser.isSet(*single))
                return usage(QStringLiteral("--%1 is for one vehicle; with --scenario, say it in the scenario file")
                                 .arg(single->names().constFirst()));
    }

    std::vector<SimNode::Options> nodes;
    bool ok = false;
    const double factor = parser.value(timeFactor).toDouble(&ok);
    if (!ok || !(factor > 0) || factor > 1000)
        return usage(QStringLiteral("--time-factor must be a number above 0 and at most 1000, not '%1'").arg(parser.value(timeFactor)));
    QList<std::pair<QHostAddress, quint16>> announceTo;
    for (const QString &c : parser.values(console)) {
        const auto to = transport::hostAndPort(c);
        if (!to)
            return usage(QStringLiteral("--console must look like 127.0.0.1:6001, not '%1'").arg(c));
        announceTo.append(*to);
    }
    if (parser.isSet(announcePort))
        announceTo.append({QHostAddress::LocalHost, static_cast<quint16>(parser.value(announcePort).toUInt())});
    const auto options = [&](sim::ScenarioVehicle vehicle) {
        return SimNode::Options{std::move(vehicle), announceTo, static_cast<int>(parser.value(domain).toUInt()),
                                parser.value(ddsKeys), parser.value(ddsIdentity), factor};
    };

    if (parser.isSet(scenario)) {
        QFile file(parser.value(scenario));
        if (!file.open(QIODevice::ReadOnly))
            return usage(QStringLiteral("--scenario: cannot read %1: %2").arg(file.fileName(), file.errorString()));
        auto read = sim::readScenario(file.read(16 << 20), file.fileName());
        if (!read) {
            std::fprintf(stderr, "neptus-sim: %s\n", qPrintable(read.error()));
            return 1;
        }
        for (auto &v : read->vehicles) {
            nodes.push_back(options(std::move(v)));
            if (!parser.isSet(timeFactor))
                nodes.back().timeFactor = read->timeFactor;
        }
    } else {
        sim::ScenarioVehicle v;
        const uint idValue = parser.value(id).toUInt(&ok, 0);
        if (!ok || idValue == 0 || idValue >= 0xFFFF)
            return usage(QStringLiteral("--id must be a number from 1 to 65534, not '%1'").arg(parser.value(id)));
        v.config.id = static_cast<quint16>(idValue);
        v.config.name = parser.value(name);
        const auto kindValue = sim::SimulatedVehicle::kindNamed(parser.value(kind));
        if (!kindValue)
            return usage(QStringLiteral("--kind must be auv, asv or uav, not '%1'").arg(parser.value(kind)));
        v.config.kind = *kindValue;
        const uint portValue = parser.value(port).toUInt(&ok);
        if (!ok || portValue == 0 || portValue > 65535)
            return usage(QStringLiteral("--port must be a port number, not '%1'").arg(parser.value(port)));
        v.port = static_cast<quint16>(portValue);
        v.host = parser.value(host);
        v.config.phase = parser.value(phase).toDouble() * 3.14159265358979 / 180;
        for (const QString &f : parser.values(fault)) {
            auto timed = sim::SimulatedVehicle::parseFault(f);
            if (!timed)
                return usage(QStringLiteral("--fault: ") + timed.error());
            v.faults.push_back(*timed);
        }
        if (parser.isSet(drop)) {
            auto timed = sim::SimulatedVehicle::parseFault(QStringLiteral("comms-loss@") + parser.value(drop));
            if (!timed || parser.value(drop).count(u':') != 1)
                return usage(QStringLiteral("--comms-drop must look like 30:10"));
            v.faults.push_back(*timed);
        }
        const QString transitionMode = parser.value(transitions);
        if (transitionMode != u"conditions" && transitionMode != u"first")
            return usage(QStringLiteral("--transitions must be conditions or first, not '%1'").arg(transitionMode));
        v.likeDune = parser.isSet(dune);
        v.firstTransitionOnly = v.likeDune || transitionMode == u"first";
        v.config.periodicEntityList = !v.likeDune;
        v.config.fuelLevelOnly = v.likeDune;
        v.dds = parser.isSet(dds);
        nodes.push_back(options(std::move(v)));
    }
    for (const SimNode::Options &n : nodes) {
        const QHostAddress address(n.vehicle.host);
        if (address.protocol() != QAbstractSocket::IPv4Protocol
            || (!address.isLoopback() && !QNetworkInterface::allAddresses().contains(address)))
            return usage(QStringLiteral("%1: the host must be a 127.x.x.x address or an IPv4 address of this machine, not '%2'")
                             .arg(n.vehicle.config.name, n.vehicle.host));
    }

    std::vector<std::unique_ptr<SimNode>> running;
    for (SimNode::Options &n : nodes) {
        running.push_back(std::make_unique<SimNode>(*schema, std::move(n)));
        if (auto started = running.back()->start(); !started) {
            std::fprintf(stderr, "neptus-sim: %s\n", qPrintable(started.error()));
            return 1;
        }
    }
    return QCoreApplication::exec();
}
