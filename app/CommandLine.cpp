#include "core/DataFiles.h"
#include "CommandLine.h"
#include "database/Database.h"
#include "transport/imc/ImcUdpTransport.h"
#include "transport/mavlink/MavlinkTransport.h"

#include <QNetworkInterface>

#include <QCommandLineParser>
#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>
#include <QSettings>
#include <QStandardPaths>

QString CommandLine::logRoot() const
{
    if (!logDirectory.isEmpty())
        return logDirectory;
    if (const QString saved = QSettings().value(QStringLiteral("log/folder")).toString(); !saved.isEmpty())
        return saved;
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation)).filePath(QStringLiteral("logs"));
}

QString CommandLine::databaseUrl(bool orBesideTheLogs) const
{
    if (!database.isEmpty())
        return database;
    // How a console hands its database to a review window it opens: not on the command line,
    // which other users can read (a PostgreSQL URL may hold a password).
    if (const QString handed = qEnvironmentVariable("NEPTUS_DATABASE"); !handed.isEmpty())
        return handed;
    if (const QString saved = QSettings().value(QStringLiteral("database/url")).toString(); !saved.isEmpty())
        return saved;
    return orBesideTheLogs ? QDir(logRoot()).filePath(QStringLiteral("operation.db")) : QString();
}

namespace {

// The log folders a session of the operation recorded (by its id's first characters, or the latest
// session of a console by its name), from the operation's database.
std::expected<QStringList, QString> sessionLogs(const QString &url, const QString &wanted)
{
    const auto location = neptus::db::Location::parse(url);
    if (!location)
        return std::unexpected(location.error());
    if (location->engine == neptus::db::Location::Sqlite && !QFileInfo::exists(location->file))
        return std::unexpected(QStringLiteral("no database at %1").arg(location->file));
    auto reader = neptus::db::Reader::open(*location);
    if (!reader)
        return std::unexpected(reader.error());
    // (sessions and logs only: sessionSummaries would read every position too.)
    const auto sessions = (*reader)->sessions();
    const auto logs = (*reader)->logs();
    if (!sessions || !logs)
        return std::unexpected(sessions ? logs.error() : sessions.error());
    QString found;
    for (const auto &s : *sessions) // oldest first: a console's latest session wins
        if (s.console == wanted || (wanted.size() >= 4 && s.session.startsWith(wanted)))
            found = s.session;
    if (found.isEmpty())
        return std::unexpected(QStringLiteral("no session '%1' in %2 (neptus-log sessions %2 lists them)").arg(wanted, location->display()));
    QStringList folders;
    for (const auto &l : *logs)
        if (l.session == found && QFileInfo::exists(l.folder))
            folders << l.folder;
    if (folders.isEmpty())
        return std::unexpected(QStringLiteral("session %1 recorded no log that is still there").arg(found));
    return folders;
}

} // namespace

std::expected<CommandLine, QString> CommandLine::parse(const QStringList &arguments)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Neptus-Qt: console for missions of teams of unmanned vehicles."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption console(QStringLiteral("console"),
        QStringLiteral("Console layout (QML file) to open. Default: %1/Default.qml")
            .arg(neptus::dataPath(QStringLiteral("consoles"))),
        QStringLiteral("file"));
    const QCommandLineOption screenshot(QStringLiteral("screenshot"),
        QStringLiteral("Render the console, write it to a PNG file and exit."), QStringLiteral("file"));
    const QCommandLineOption screenshotDelay(QStringLiteral("screenshot-delay"),
        QStringLiteral("With --screenshot: wait this many milliseconds first (let data arrive)."), QStringLiteral("ms"));
    const QCommandLineOption components(QStringLiteral("components"),
        QStringLiteral("Also offer the components (.qml files) in this directory; watched while running. Repeatable."),
        QStringLiteral("dir"));
    const QCommandLineOption edit(QStringLiteral("edit"), QStringLiteral("Open the console in edit mode (the designer)."));
    const QCommandLineOption select(QStringLiteral("select"),
        QStringLiteral("With --edit: select this component (by its id) to show its properties."), QStringLiteral("id"));
    const QCommandLineOption system(QStringLiteral("system"),
        QStringLiteral("The system the console follows (\"$main\" in its paths), e.g. the vehicle an AUV console is for."),
        QStringLiteral("name"));
    const QCommandLineOption palette(QStringLiteral("palette"),
        QStringLiteral("Colour palette: day, dusk or night."), QStringLiteral("name"));
    const QCommandLineOption gps(QStringLiteral("gps"),
        QStringLiteral("Own ship's position from NMEA: serial:/dev/ttyUSB0, socket://host:port or an NMEA file (replayed)."),
        QStringLiteral("source"));
    const QCommandLineOption uiScale(QStringLiteral("ui-scale"),
        QStringLiteral("Size of text and controls, 0.75 to 2 (touch targets never under 9 mm); default as last time."),
        QStringLiteral("factor"));
    const QCommandLineOption screenInches(QStringLiteral("screen-inches"),
        QStringLiteral("The screen's diagonal in inches, for a screen that does not report its size (controls are sized in mm from it)."),
        QStringLiteral("inches"));
    const QCommandLineOption charts(QStringLiteral("charts"),
        QStringLiteral("Nautical charts (S-57 ENC) for the maps: a cell (.000), an exchange set or a folder of cells (docs/charts.md)."),
        QStringLiteral("path"));
    const QCommandLineOption safetyDepth(QStringLiteral("safety-depth"),
        QStringLiteral("Charted water shallower than this stands out on the maps, in metres (default 5)."), QStringLiteral("metres"));
    const QCommandLineOption displayRate(QStringLiteral("display-rate"),
        QStringLiteral("Vehicle data shown at most this many times a second while it keeps changing (default 10; 0: every frame)."),
        QStringLiteral("hz"));
    const QCommandLineOption restingRate(QStringLiteral("resting-rate"),
        QStringLiteral("The same after %1 s without a touch, click or key, until the next (default 3; 0: as the display rate). "
                       "Saves a tablet's battery.").arg(CommandLine::restAfterS),
        QStringLiteral("hz"));
    const QCommandLineOption size(QStringLiteral("size"),
        QStringLiteral("Window size, e.g. 1280x800."), QStringLiteral("WxH"));
    const QCommandLineOption selfTest(QStringLiteral("self-test"),
        QStringLiteral("Load every QML file of the project and every console; exit 0 only if "
                       "all load without errors or warnings."));
    const QCommandLineOption imcPort(QStringLiteral("imc-port"),
        QStringLiteral("Local UDP port for IMC, on 127.0.0.1 (default 6001; 0 turns IMC off)."), QStringLiteral("port"));
    const QCommandLineOption imcBind(QStringLiteral("imc-bind"),
        QStringLiteral("Address or network interface IMC listens and sends on (default 127.0.0.1, or the "
                       "settings' imc/bind). On a field network discovery also uses its broadcast address "
                       "and IMC's multicast group."),
        QStringLiteral("address|interface"));
    const QCommandLineOption imcPeer(QStringLiteral("imc-peer"),
        QStringLiteral("An IMC vehicle to talk to, as host:port (repeat for several)."), QStringLiteral("host:port"));
    const QCommandLineOption systemId(QStringLiteral("system-id"),
        QStringLiteral("This console's IMC and DDS system id, a console (CCU) id from 0x4000 to 0x5FFF (default 0x4001). "
                       "Two consoles on one network or DDS domain need different ids (neptus-logd uses 0x4002)."),
        QStringLiteral("id"));
    const QCommandLineOption ddsDomain(QStringLiteral("dds-domain"),
        QStringLiteral("Cyclone DDS domain id (default 0; -1 turns DDS off)."), QStringLiteral("id"));
    const QCommandLineOption ddsConfig(QStringLiteral("dds-config"),
        QStringLiteral("Cyclone DDS XML configuration (default: dds/loopback.xml, loopback only)."), QStringLiteral("file"));
    const QCommandLineOption ddsKeys(QStringLiteral("dds-keys"),
        QStringLiteral("DDS Security: a key set made by tools/dds-keys (docs/dds-security.md); with "
                       "--dds-identity. Without keys, secured vehicles and consoles do not talk to this one."),
        QStringLiteral("dir"));
    const QCommandLineOption ddsIdentity(QStringLiteral("dds-identity"),
        QStringLiteral("DDS Security: the name this console's keys were made for (a folder of --dds-keys)."),
        QStringLiteral("name"));
    const QCommandLineOption defs(QStringLiteral("defs"),
        QStringLiteral("Message definition file to load instead of the shipped ones (repeatable)."), QStringLiteral("file"));
    const QCommandLineOption defsFor(QStringLiteral("defs-for"),
        QStringLiteral("Decode what SYSTEM (an IMC id like 0x00d1, or the name it announces) sends, and encode "
                       "what goes to it, with the definitions in FILE (IMC.xml or IMC.xml.gz); also written "
                       "--defs-for SYSTEM FILE (repeatable)."),
        QStringLiteral("system=file"));
    const QCommandLineOption imcDiscovery(QStringLiteral("imc-discovery"),
        QStringLiteral("IMC discovery (announce to and listen on ports 30100-30104): on or off (default on)."),
        QStringLiteral("on|off"));
    const QCommandLineOption mavlink(QStringLiteral("mavlink"),
        QStringLiteral("A MAVLink link (ArduPilot, PX4): udp:14550 (listen on loopback), udp:ADDRESS:PORT, tcp:HOST:PORT "
                       "(a vehicle or SITL), serial:/dev/ttyUSB0[:57600] (a telemetry radio); repeatable (docs/mavlink.md)."),
        QStringLiteral("link"));
    const QCommandLineOption mavlinkPeer(QStringLiteral("mavlink-peer"),
        QStringLiteral("A MAVLink vehicle to send to over UDP before it is heard, as host:port (repeatable)."), QStringLiteral("host:port"));
    const QCommandLineOption mavlinkKey(QStringLiteral("mavlink-key"),
        QStringLiteral("Sign MAVLink frames with the key in this file: a passphrase (as MAVProxy and QGroundControl make "
                       "keys of one) or 64 hex digits."),
        QStringLiteral("file"));
    const QCommandLineOption mavlinkRequireSigning(QStringLiteral("mavlink-require-signing"),
        QStringLiteral("With --mavlink-key: refuse MAVLink frames that are unsigned or badly signed."));
    const QCommandLineOption mavlinkDialect(QStringLiteral("mavlink-dialect"),
        QStringLiteral("MAVLink message definitions to read instead of the shipped ardupilotmega.xml."), QStringLiteral("file"));
    const QCommandLineOption dumpTree(QStringLiteral("dump-tree"),
        QStringLiteral("On exit, write every variable of the tree (path, value, unit) to this file."), QStringLiteral("file"));
    const QCommandLineOption forgetAfter(QStringLiteral("forget-after"),
        QStringLiteral("Forget a system silent this long: its variables, alarms, track and statistics (default: "
                       "the settings' systems/forgetAfter, else never; unnamed systems heard under 5 s go after "
                       "10 min anyway). Heard again, it comes back."),
        QStringLiteral("seconds"));
    const QCommandLineOption mission(QStringLiteral("mission"),
        QStringLiteral("A mission file (docs/missions.md) whose plans the plan panel offers to send and start."),
        QStringLiteral("file"));
    const QCommandLineOption share(QStringLiteral("share"),
        QStringLiteral("Share the --mission with the other consoles on DDS (their edits come here, ours go there); "
                       "with no --mission, join the first shared mission heard."));
    const QCommandLineOption name(QStringLiteral("console-name"),
        QStringLiteral("This console's name to the others, said with every change it shares (default: user@host)."),
        QStringLiteral("name"));
    const QCommandLineOption quitAfter(QStringLiteral("quit-after"),
        QStringLiteral("Exit after this many milliseconds."), QStringLiteral("ms"));
    const QCommandLineOption logDir(QStringLiteral("log-dir"),
        QStringLiteral("Where the console records what it receives and sends (a folder per session; default: the settings' "
                       "log/folder, else logs/ in the user's data folder)."),
        QStringLiteral("folder"));
    const QCommandLineOption noRecord(QStringLiteral("no-record"),
        QStringLiteral("Record nothing this time: no log, and no database unless --database names one."));
    const QCommandLineOption database(QStringLiteral("database"),
        QStringLiteral("The operation's database: postgresql://user@host/name (shared by many consoles) or a SQLite file "
                       "(default: the settings' database/url, else operation.db beside the logs)."),
        QStringLiteral("url"));
    const QCommandLineOption replay(QStringLiteral("replay"),
        QStringLiteral("Review a log (a folder with Data.lsf[.gz] and IMC.xml[.gz]; repeat for several logs of one mission): "
                       "the console is fed from it, with a timeline, and sends nothing."),
        QStringLiteral("log"));
    const QCommandLineOption replayFrom(QStringLiteral("replay-from"),
        QStringLiteral("With --replay: open the logs this many seconds after their start."), QStringLiteral("seconds"));
    const QCommandLineOption replayPlay(QStringLiteral("replay-play"), QStringLiteral("With --replay: start playing at once."));
    const QCommandLineOption replaySession(QStringLiteral("replay-session"),
        QStringLiteral("Review what a session of the operation recorded: its logs, found in the operation's database "
                       "(--database, or the default beside the logs); a session id (its first characters; neptus-log sessions "
                       "lists them) or a console's name (its latest session)."),
        QStringLiteral("session"));
    const QCommandLineOption webPort(QStringLiteral("web-port"),
        QStringLiteral("Serve the live web page (read-only) on this port (0: any free one; default: the settings' web/port, else none)."),
        QStringLiteral("port"));
    const QCommandLineOption webBind(QStringLiteral("web-bind"),
        QStringLiteral("Address the web page listens on (default 127.0.0.1; any other needs --web-token)."), QStringLiteral("address"));
    const QCommandLineOption webToken(QStringLiteral("web-token"),
        QStringLiteral("The web page's access token (at least 16 characters): ?token=... or Authorization: Bearer."),
        QStringLiteral("token"));
    const QCommandLineOption webCert(QStringLiteral("web-cert"), QStringLiteral("Serve the web page over HTTPS with this PEM certificate."),
                                     QStringLiteral("file"));
    const QCommandLineOption webKey(QStringLiteral("web-key"), QStringLiteral("The PEM private key of --web-cert."), QStringLiteral("file"));
    const QCommandLineOption webTiles(QStringLiteral("web-tiles"),
        QStringLiteral("Map tiles for the web page: a URL with {z}/{x}/{y} (default: the offline coastline only)."), QStringLiteral("url"));
    parser.addOptions({mavlink, mavlinkPeer, mavlinkKey, mavlinkRequireSigning, mavlinkDialect});
    parser.addOptions({logDir, noRecord, database, replay, replaySession, replayFrom, replayPlay, webPort, webBind, webToken, webCert, webKey, webTiles});
    parser.addOptions({charts, safetyDepth, displayRate, restingRate, screenInches});
    parser.addOptions({console, screenshot, screenshotDelay, components, edit, select, system, palette, uiScale, gps, size, selfTest,
                       imcPort, imcBind, imcPeer, systemId, ddsDomain, ddsConfig, ddsKeys, ddsIdentity, defs, defsFor, imcDiscovery, dumpTree, quitAfter, forgetAfter, mission, share, name});
    // "--defs-for SYSTEM FILE" (two words, as the documentation writes it) is
    // "--defs-for SYSTEM=FILE" to the parser, which takes one value per option.
    QStringList words = arguments;
    for (qsizetype i = 0; i + 2 < words.size(); ++i) {
        if (words[i] == u"--defs-for" && !words[i + 1].contains(u'=') && !words[i + 2].startsWith(u'-')) {
            words[i + 1] += u'=' + words[i + 2];
            words.removeAt(i + 2);
        }
    }
    if (!parser.parse(words))
        return std::unexpected(parser.errorText());
    if (parser.isSet(QStringLiteral("help")))
        return std::unexpected(parser.helpText());
    if (parser.isSet(QStringLiteral("version")))
        return std::unexpected(QStringLiteral("neptus " NEPTUS_VERSION));
    if (!parser.positionalArguments().isEmpty())
        return std::unexpected(QStringLiteral("unexpected argument '%1' (see --help)")
                                   .arg(parser.positionalArguments().first()));

    CommandLine result;
    result.consoleFile = parser.isSet(console)
        ? QFileInfo(parser.value(console)).absoluteFilePath()
        : QDir(neptus::dataPath(QStringLiteral("consoles"))).filePath(QStringLiteral("Default.qml"));
    if (!QFileInfo(result.consoleFile).isFile())
        return std::unexpected(QStringLiteral("console file '%1' does not exist").arg(result.consoleFile));
    result.screenshotFile = parser.value(screenshot);
    if (parser.isSet(screenshotDelay)) {
        bool ok = false;
        result.screenshotDelayMs = parser.value(screenshotDelay).toInt(&ok);
        if (!ok || result.screenshotDelayMs < 0 || result.screenshotDelayMs > 600000)
            return std::unexpected(QStringLiteral("--screenshot-delay must be milliseconds (0 to 600000), not '%1'")
                                       .arg(parser.value(screenshotDelay)));
    }
    result.selfTest = parser.isSet(selfTest);
    if (parser.isSet(charts)) {
        result.charts = QFileInfo(parser.value(charts)).absoluteFilePath();
        if (!QFileInfo::exists(result.charts))
            return std::unexpected(QStringLiteral("--charts: '%1' does not exist").arg(parser.value(charts)));
    }
    // A number option within [lowest, highest] read into `to` (left as it is when not given), or why not.
    const auto readNumber = [&parser](const QCommandLineOption &option, double lowest, double highest, const QString &what,
                                      double &to) -> std::expected<void, QString> {
        if (!parser.isSet(option))
            return {};
        bool ok = false;
        const double value = parser.value(option).toDouble(&ok);
        if (!ok || !(value >= lowest && value <= highest))
            return std::unexpected(QStringLiteral("--%1 must be %2, not '%3'").arg(option.names().constFirst(), what, parser.value(option)));
        to = value;
        return {};
    };
    for (const auto &read : {readNumber(safetyDepth, 0, 1000, QStringLiteral("metres (0 to 1000)"), result.safetyDepth),
                             readNumber(displayRate, 0, 1000, QStringLiteral("updates a second (0 to 1000; 0: every frame)"), result.displayRate),
                             readNumber(restingRate, 0, 1000, QStringLiteral("updates a second (0 to 1000; 0: as the display rate)"), result.restingRate),
                             readNumber(screenInches, 3, 120, QStringLiteral("a screen's diagonal, 3 to 120 inches"), result.screenInches),
                             readNumber(uiScale, 0.75, 2, QStringLiteral("a number from 0.75 to 2"), result.uiScale)})
        if (!read)
            return std::unexpected(read.error());
    result.logDirectory = parser.isSet(logDir) ? QFileInfo(parser.value(logDir)).absoluteFilePath() : QString();
    result.record = !parser.isSet(noRecord);
    if (parser.isSet(webPort)) {
        bool ok = false;
        const uint port = parser.value(webPort).toUInt(&ok);
        if (!ok || port > 65535)
            return std::unexpected(QStringLiteral("--web-port: '%1' is not a port").arg(parser.value(webPort)));
        result.webPort = int(port);
    }
    if (parser.isSet(webBind)) {
        result.webBind = parser.value(webBind);
        if (QHostAddress(result.webBind).isNull())
            return std::unexpected(QStringLiteral("--web-bind: '%1' is not an address").arg(result.webBind));
    }
    result.webToken = parser.value(webToken);
    result.webCertificate = parser.value(webCert);
    result.webKey = parser.value(webKey);
    result.webTiles = parser.value(webTiles);
    if (parser.isSet(database)) {
        result.database = parser.value(database);
        if (auto parsed = neptus::db::Location::parse(result.database); !parsed)
            return std::unexpected(QStringLiteral("--database: %1").arg(parsed.error()));
    }
    for (const QString &log : parser.values(replay)) {
        if (!QFileInfo::exists(log))
            return std::unexpected(QStringLiteral("--replay: '%1' does not exist").arg(log));
        result.replayLogs << QFileInfo(log).absoluteFilePath();
    }
    if (parser.isSet(replaySession)) {
        auto logs = sessionLogs(result.databaseUrl(true), parser.value(replaySession));
        if (!logs)
            return std::unexpected(QStringLiteral("--replay-session: %1").arg(logs.error()));
        result.replayLogs << *logs;
    }
    if (parser.isSet(replayFrom)) {
        bool ok = false;
        result.replayFrom = parser.value(replayFrom).toDouble(&ok);
        if (!ok || result.replayFrom < 0)
            return std::unexpected(QStringLiteral("--replay-from must be seconds from the log's start, not '%1'").arg(parser.value(replayFrom)));
    }
    result.replayPlay = parser.isSet(replayPlay);
    if ((parser.isSet(replayFrom) || result.replayPlay) && result.replayLogs.isEmpty())
        return std::unexpected(QStringLiteral("--replay-from and --replay-play go with --replay LOG"));
    for (const QString &directory : parser.values(components)) {
        if (!QFileInfo(directory).isDir())
            return std::unexpected(QStringLiteral("--components: '%1' is not a directory").arg(directory));
        result.componentDirectories << QFileInfo(directory).absoluteFilePath();
    }
    result.edit = parser.isSet(edit);
    result.select = parser.value(select);
    if (!result.select.isEmpty() && !result.edit)
        return std::unexpected(QStringLiteral("--select needs --edit"));
    result.system = parser.value(system);
    result.palette = parser.value(palette).toLower();
    if (!result.palette.isEmpty() && result.palette != u"day" && result.palette != u"dusk"
        && result.palette != u"night")
        return std::unexpected(QStringLiteral("--palette must be day, dusk or night, not '%1'")
                                   .arg(parser.value(palette)));
    result.gps = parser.value(gps);
    if (!result.gps.isEmpty() && !result.gps.startsWith(u"serial:") && !result.gps.startsWith(u"socket://")) {
        const QFileInfo file(result.gps);
        if (!file.isFile() || !file.isReadable())
            return std::unexpected(QStringLiteral("--gps: %1 is not a readable NMEA file (or serial:DEVICE, socket://HOST:PORT)").arg(result.gps));
        result.gps = file.absoluteFilePath();
    }
    if (parser.isSet(size)) {
        static const QRegularExpression format(QStringLiteral("^(\\d{2,5})x(\\d{2,5})$"));
        const auto match = format.match(parser.value(size));
        if (!match.hasMatch())
            return std::unexpected(QStringLiteral("--size must look like 1280x800, not '%1'")
                                       .arg(parser.value(size)));
        result.windowSize = QSize(match.captured(1).toInt(), match.captured(2).toInt());
    }
    if (parser.isSet(imcPort)) {
        bool ok = false;
        const uint port = parser.value(imcPort).toUInt(&ok);
        if (!ok || port > 65535)
            return std::unexpected(QStringLiteral("--imc-port must be a port number, not '%1'").arg(parser.value(imcPort)));
        result.imcPort = static_cast<quint16>(port);
    }
    if (parser.isSet(systemId)) {
        bool ok = false;
        const uint id = parser.value(systemId).toUInt(&ok, 0);
        if (!ok || id < 0x4000 || id > 0x5FFF)
            return std::unexpected(QStringLiteral("--system-id must be a console id from 0x4000 to 0x5FFF (IMC's CCU range), not '%1'")
                                       .arg(parser.value(systemId)));
        result.systemId = static_cast<quint16>(id);
    }
    if (parser.isSet(ddsDomain)) {
        bool ok = false;
        result.ddsDomain = parser.value(ddsDomain).toInt(&ok);
        if (!ok || result.ddsDomain < -1 || result.ddsDomain > 232)
            return std::unexpected(QStringLiteral("--dds-domain must be a domain id from 0 to 232, or -1, not '%1'")
                                       .arg(parser.value(ddsDomain)));
    }
    if (parser.isSet(ddsConfig)) {
        result.ddsConfig = QFileInfo(parser.value(ddsConfig)).absoluteFilePath();
        if (!QFileInfo(result.ddsConfig).isFile())
            return std::unexpected(QStringLiteral("DDS configuration '%1' does not exist").arg(result.ddsConfig));
    }
    if (parser.isSet(ddsKeys) != parser.isSet(ddsIdentity))
        return std::unexpected(QStringLiteral("--dds-keys and --dds-identity go together (the key set, and whose keys in it)"));
    if (parser.isSet(ddsKeys)) {
        result.ddsKeys = QFileInfo(parser.value(ddsKeys)).absoluteFilePath();
        result.ddsIdentity = parser.value(ddsIdentity);
        if (!QFileInfo(result.ddsKeys).isDir())
            return std::unexpected(QStringLiteral("--dds-keys: '%1' is not a folder (make one with tools/dds-keys)").arg(result.ddsKeys));
    }
    for (const QString &file : parser.values(defs)) {
        if (!QFileInfo(file).isFile())
            return std::unexpected(QStringLiteral("--defs: '%1' does not exist").arg(file));
        result.definitionFiles << QFileInfo(file).absoluteFilePath();
    }
    for (const QString &value : parser.values(defsFor)) {
        const qsizetype equals = value.indexOf(u'=');
        if (equals <= 0 || equals == value.size() - 1)
            return std::unexpected(QStringLiteral("--defs-for must look like 0x00d1=IMC.xml or lauv-xplore-1=IMC.xml.gz, not '%1'")
                                       .arg(value));
        const QString file = value.mid(equals + 1);
        if (!QFileInfo(file).isFile())
            return std::unexpected(QStringLiteral("--defs-for: '%1' does not exist").arg(file));
        result.definitionsFor.append({value.left(equals), QFileInfo(file).absoluteFilePath()});
    }
    if (parser.isSet(imcDiscovery)) {
        const QString value = parser.value(imcDiscovery).toLower();
        if (value != u"on" && value != u"off")
            return std::unexpected(QStringLiteral("--imc-discovery must be on or off, not '%1'").arg(parser.value(imcDiscovery)));
        result.imcDiscovery = value == u"on";
    }
    result.dumpTreeFile = parser.value(dumpTree);
    result.share = parser.isSet(share);
    result.name = parser.value(name).trimmed();
    if (parser.isSet(name) && result.name.isEmpty())
        return std::unexpected(QStringLiteral("--console-name: give this console a name"));
    if (parser.isSet(quitAfter)) {
        bool ok = false;
        result.quitAfterMs = parser.value(quitAfter).toInt(&ok);
        if (!ok || result.quitAfterMs <= 0)
            return std::unexpected(QStringLiteral("--quit-after must be a number of milliseconds, not '%1'")
                                       .arg(parser.value(quitAfter)));
    }
    if (parser.isSet(mission)) {
        result.missionFile = QFileInfo(parser.value(mission)).absoluteFilePath();
        if (!QFileInfo(result.missionFile).isFile())
            return std::unexpected(QStringLiteral("--mission: no file %1").arg(result.missionFile));
    }
    if (parser.isSet(forgetAfter)) {
        bool ok = false;
        result.forgetAfterSeconds = parser.value(forgetAfter).toDouble(&ok);
        if (!ok || !(result.forgetAfterSeconds > 0) || result.forgetAfterSeconds > 1e9)
            return std::unexpected(QStringLiteral("--forget-after must be a number of seconds above 0, not '%1'")
                                       .arg(parser.value(forgetAfter)));
    }
    if (parser.isSet(imcBind)) {
        auto address = localAddress(parser.value(imcBind));
        if (!address)
            return std::unexpected(QStringLiteral("--imc-bind: %1").arg(address.error()));
        result.imcBind = *address;
    }
    for (const QString &value : parser.values(mavlink)) {
        if (auto link = neptus::transport::parseMavlinkLink(value); !link)
            return std::unexpected(QStringLiteral("--mavlink: %1").arg(link.error()));
        result.mavlinkLinks.append(value);
    }
    // host:port values of an option (--imc-peer, --mavlink-peer); an error shows one that is not.
    const auto peers = [&](const QCommandLineOption &option, const char *example,
                           QList<std::pair<QHostAddress, quint16>> &into) -> std::expected<void, QString> {
        for (const QString &value : parser.values(option)) {
            const auto peer = neptus::transport::hostAndPort(value);
            if (!peer)
                return std::unexpected(QStringLiteral("--%1 must look like %2, not '%3'").arg(option.names().constFirst(),
                                                                                             QLatin1StringView(example), value));
            into.append(*peer);
        }
        return {};
    };
    if (auto read = peers(mavlinkPeer, "127.0.0.1:14555", result.mavlinkPeers); !read)
        return std::unexpected(read.error());
    if (parser.isSet(mavlinkKey)) {
        auto key = neptus::transport::mavlinkKeyFromFile(parser.value(mavlinkKey));
        if (!key)
            return std::unexpected(QStringLiteral("--mavlink-key: %1").arg(key.error()));
        result.mavlinkKey = *key;
    }
    result.mavlinkRequireSigning = parser.isSet(mavlinkRequireSigning);
    if (result.mavlinkRequireSigning && result.mavlinkKey.isEmpty())
        return std::unexpected(QStringLiteral("--mavlink-require-signing needs --mavlink-key"));
    result.mavlinkDialect = parser.value(mavlinkDialect);
    if (auto read = peers(imcPeer, "127.0.0.1:6002", result.imcPeers); !read)
        return std::unexpected(read.error());
    return result;
}

std::expected<QString, QString> CommandLine::localAddress(const QString &addressOrInterface)
{
    QStringList there;
    const QHostAddress asAddress(addressOrInterface);
    for (const QNetworkInterface &interface : QNetworkInterface::allInterfaces()) {
        for (const QNetworkAddressEntry &entry : interface.addressEntries()) {
            if (entry.ip().protocol() != QAbstractSocket::IPv4Protocol)
                continue;
            if (entry.ip() == asAddress || interface.name() == addressOrInterface)
                return entry.ip().toString();
            there << QStringLiteral("%1 (%2)").arg(entry.ip().toString(), interface.name());
        }
    }
    return std::unexpected(QStringLiteral("'%1' is no IPv4 address or interface of this machine; there are: %2")
                               .arg(addressOrInterface, there.join(QStringLiteral(", "))));
}
