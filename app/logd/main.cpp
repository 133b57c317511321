// neptus-logd: a headless recorder node for an operations room with no
// console open. It joins the vehicles' networks as a console does (IMC/UDP,
// DDS), records everything (Data.lsf logs) and writes the operation's
// database; it sends no command to any vehicle. Stops cleanly on SIGINT or
// SIGTERM (what it queued is written, or kept on disk for the database).
#include "database/Database.h"
#include "log/Recorder.h"
#include "messages/Schema.h"
#include "core/DataFiles.h"
#include "session/Console.h"
#include "session/OperationsFeed.h"
#include "transport/imc/ImcUdpTransport.h"
#include "web/LiveServer.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <QSocketNotifier>
#include <QStandardPaths>
#include <QTimer>

#include <csignal>
#include <cstdio>
#include <sys/socket.h>
#include <unistd.h>

using namespace Qt::StringLiterals;

namespace {

int signalPipe[2] = {-1, -1};

void onSignal(int)
{
    const char byte = 1;
    [[maybe_unused]] const auto written = ::write(signalPipe[1], &byte, 1);
}

int fail(const QString &what)
{
    std::fprintf(stderr, "neptus-logd: %s\n", qPrintable(what));
    return 2;
}

} // namespace

int main(int argc, char *argv[])
{
    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    QCoreApplication app(argc, argv);
    QCoreApplication::setOrganizationName(u"neptus-qt"_s);
    QCoreApplication::setApplicationName(u"neptus"_s);
    QCoreApplication::setApplicationVersion(QStringLiteral(NEPTUS_VERSION));

    QCommandLineParser parser;
    parser.setApplicationDescription(u"Records what the vehicles say and writes the operation's database, with no console open."_s);
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption imcPort(u"imc-port"_s, u"IMC/UDP port to listen on (default 6010; 0: none)."_s, u"port"_s, u"6010"_s);
    const QCommandLineOption imcBind(u"imc-bind"_s, u"Address to listen on (default 127.0.0.1)."_s, u"address"_s, u"127.0.0.1"_s);
    const QCommandLineOption imcPeer(u"imc-peer"_s, u"A vehicle to reach, host:port (repeatable)."_s, u"host:port"_s);
    const QCommandLineOption imcDiscovery(u"imc-discovery"_s, u"IMC discovery on the IMC ports 30100-30104: on or off (default on)."_s,
                                          u"on|off"_s, u"on"_s);
    const QCommandLineOption ddsDomain(u"dds-domain"_s, u"DDS domain (default -1: no DDS)."_s, u"id"_s, u"-1"_s);
    const QCommandLineOption logDir(u"log-dir"_s, u"Where logs go (default: logs/ in the user's data folder)."_s, u"folder"_s);
    const QCommandLineOption noRecord(u"no-record"_s, u"Record no log (the database only)."_s);
    const QCommandLineOption database(u"database"_s,
                                      u"postgresql://user@host/name or a SQLite file (default: operation.db beside the logs)."_s, u"url"_s);
    const QCommandLineOption name(u"name"_s, u"This node's name in the database and on the network (default neptus-logd)."_s,
                                  u"name"_s, u"neptus-logd"_s);
    const QCommandLineOption quitAfter(u"quit-after"_s, u"Exit after this many milliseconds."_s, u"ms"_s);
    const QCommandLineOption webPort(u"web-port"_s, u"Serve the live web page on this port (0: any free one; default: no page)."_s, u"port"_s);
    const QCommandLineOption webBind(u"web-bind"_s, u"Address the web page listens on (default 127.0.0.1; another needs --web-token)."_s,
                                     u"address"_s, u"127.0.0.1"_s);
    const QCommandLineOption webToken(u"web-token"_s, u"The web page's access token (at least 16 characters)."_s, u"token"_s);
    const QCommandLineOption webCert(u"web-cert"_s, u"Serve the page over HTTPS with this PEM certificate (and --web-key)."_s, u"file"_s);
    const QCommandLineOption webKey(u"web-key"_s, u"The PEM private key of --web-cert."_s, u"file"_s);
    const QCommandLineOption webTiles(u"web-tiles"_s, u"Map tiles for the page, a URL with {z}/{x}/{y} (default: the offline coastline only)."_s,
                                      u"url"_s);
    parser.addOptions({imcPort, imcBind, imcPeer, imcDiscovery, ddsDomain, logDir, noRecord, database, name, quitAfter, webPort, webBind,
                       webToken, webCert, webKey, webTiles});
    parser.process(app);

    auto schema = neptus::msg::Schema::load(neptus::msg::Schema::filesIn(neptus::dataPath(u"msgdefs"_s)));
    if (!schema)
        return fail(schema.error().toString());
    const QString root = parser.isSet(logDir)
        ? QFileInfo(parser.value(logDir)).absoluteFilePath()
        : QDir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation)).filePath(u"logs"_s);
    const QString url = parser.isSet(database) ? parser.value(database) : QDir(root).filePath(u"operation.db"_s);
    const auto location = neptus::db::Location::parse(url);
    if (!location)
        return fail(u"--database: "_s + location.error());

    std::unique_ptr<neptus::log::Recorder> recorder;
    if (!parser.isSet(noRecord)) {
        neptus::log::RecorderConfig config;
        config.root = root;
        config.name = parser.value(name);
        config.system = 0x4002;
        config.definitionFiles = neptus::msg::Schema::filesIn(neptus::dataPath(u"msgdefs"_s));
        recorder = std::make_unique<neptus::log::Recorder>(config);
        if (auto started = recorder->start(); !started) {
            std::fprintf(stderr, "neptus-logd: recording: %s; carrying on without it\n", qPrintable(started.error()));
            recorder.reset();
        } else {
            std::printf("neptus-logd: recording in %s\n", qPrintable(recorder->status().folder));
        }
    }
    neptus::db::Writer::Options options;
    options.spoolFolder = QDir(root).filePath(u"database-spool"_s);
    options.console = parser.value(name);
    options.host = QSysInfo::machineHostName();
    options.program = u"neptus-logd " NEPTUS_VERSION ""_s;
    neptus::db::Writer writer(*location, options);
    std::printf("neptus-logd: database %s\n", qPrintable(location->display()));

    neptus::session::Console console(*schema);
    console.setRecorder(recorder.get());
    neptus::session::OperationsFeed feed(console, &writer);
    feed.setRecorder(recorder.get());
    // The node says what goes wrong with its own parts on its output (no alarm window here).
    auto &graph = console.alarmGraph();
    QString lastSaid;
    QTimer watch;
    QObject::connect(&watch, &QTimer::timeout, &app, [&] {
        QStringList problems;
        for (const char *part : {"database", "recording"})
            if (const auto node = graph.find(QLatin1StringView(part)); node != neptus::alarms::AlarmGraph::noNode
                && neptus::alarms::isAlarm(graph.ownLevel(node)))
                problems.append(QLatin1StringView(part) + u": "_s + graph.message(node));
        const QString said = problems.join(u"; "_s);
        if (said != lastSaid)
            std::printf("neptus-logd: %s\n", said.isEmpty() ? "all well" : qPrintable(said));
        lastSaid = said;
    });
    watch.start(1000);

    if (const int port = parser.value(imcPort).toInt(); port > 0) {
        neptus::transport::ImcUdpConfig config;
        config.port = quint16(port);
        config.bindAddress = QHostAddress(parser.value(imcBind));
        if (config.bindAddress.isNull())
            return fail(u"--imc-bind: '%1' is not an address"_s.arg(parser.value(imcBind)));
        config.discovery = parser.value(imcDiscovery) != u"off"_s;
        config.systemId = 0x4002;
        config.systemName = parser.value(name);
        for (const QString &value : parser.values(imcPeer)) {
            const auto peer = neptus::transport::hostAndPort(value);
            if (!peer)
                return fail(u"--imc-peer must look like 127.0.0.1:6002, not '%1'"_s.arg(value));
            config.destinations.append(*peer);
        }
        if (auto started = console.startImc(config); !started)
            std::fprintf(stderr, "neptus-logd: %s; carrying on without IMC\n", qPrintable(started.error()));
        else
            std::printf("neptus-logd: IMC/UDP on %s:%u\n", qPrintable(config.bindAddress.toString()), console.imc()->port());
    }
    std::unique_ptr<neptus::web::LiveServer> web;
    if (parser.isSet(webPort)) {
        bool ok = false;
        const uint port = parser.value(webPort).toUInt(&ok);
        if (!ok || port > 65535)
            return fail(u"--web-port: '%1' is not a port"_s.arg(parser.value(webPort)));
        auto config = neptus::web::pageConfig({parser.value(webBind), int(port), parser.value(webToken), parser.value(webCert),
                                               parser.value(webKey), parser.value(webTiles), parser.value(name)});
        if (!config)
            return fail(config.error());
        config->history = *location;
        web = std::make_unique<neptus::web::LiveServer>(feed, *config);
        auto started = web->start();
        if (!started)
            return fail(started.error());
        std::printf("neptus-logd: web page on %s\n", qPrintable(web->url()));
    }
    if (const int domain = parser.value(ddsDomain).toInt(); domain >= 0) {
        neptus::transport::DdsConfig config{static_cast<dds_domainid_t>(domain), {}};
        config.systemId = 0x4002;
        config.systemName = parser.value(name);
        if (auto started = console.startDds(config); !started)
            std::fprintf(stderr, "neptus-logd: %s; carrying on without DDS\n", qPrintable(started.error()));
    }

    // SIGINT/SIGTERM end the event loop; the destructors write what is queued.
    if (::socketpair(AF_UNIX, SOCK_STREAM, 0, signalPipe) == 0) {
        std::signal(SIGINT, onSignal);
        std::signal(SIGTERM, onSignal);
        auto *notifier = new QSocketNotifier(signalPipe[0], QSocketNotifier::Read, &app);
        QObject::connect(notifier, &QSocketNotifier::activated, &app, &QCoreApplication::quit);
    }
    if (parser.isSet(quitAfter))
        QTimer::singleShot(parser.value(quitAfter).toInt(), &app, &QCoreApplication::quit);
    const int code = app.exec();
    std::printf("neptus-logd: stopping\n");
    return code;
}
