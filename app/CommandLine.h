#pragma once

#include <QString>
#include <QStringList>
#include <QHostAddress>
#include <QList>
#include <QSize>

#include <utility>

#include <expected>

// What the `neptus` command line asks for, already checked.
struct CommandLine
{
    QString consoleFile;     // layout to open
    QString missionFile;     // mission whose plans are offered (--mission)
    bool share = false;      // share it with the other consoles (--share)
    QString name;            // this console's name to the others (--console-name)
    QString screenshotFile;  // render, save a PNG, exit
    int screenshotDelayMs = 0; // wait this long after the first frame
    QString palette;         // day, dusk or night; empty = as last time
    double uiScale = 0;      // 0.75 to 2; 0 = as last time
    double screenInches = 0; // the screen's diagonal when it reports no size of its own; 0 = as reported
    QString gps;             // own ship's NMEA source: serial:…, socket://…, or a file's absolute path
    QStringList componentDirectories;   // --components, before the standard ones
    bool edit = false;                  // start in edit mode
    QString select;                     // with edit: the component selected
    QString system;                     // the console's main system ($main)
    QString charts;                     // S-57 charts for the maps (absolute path)
    double safetyDepth = 5;             // metres
    double displayRate = 10;            // vehicle data shown a second at most (0: every frame)
    double restingRate = 3;             // the same after restAfterS without input (0: never rests)
    static constexpr int restAfterS = 20;
    QSize windowSize{1280, 800};
    QStringList definitionFiles;        // --defs: instead of msgdefs/
    QList<std::pair<QString, QString>> definitionsFor; // --defs-for SYSTEM=FILE
    quint16 imcPort = 6001;             // IMC over UDP
    quint16 systemId = 0x4001;          // this console's IMC and DDS system id (--system-id; 0x4001 as LSTS Neptus on loopback)
    QString imcBind;                    // its address ("10.0.0.5"); empty: settings, else 127.0.0.1
    QList<std::pair<QHostAddress, quint16>> imcPeers; // static IMC destinations (--imc-peer host:port)
    bool imcDiscovery = true;           // announce to and listen on 30100-30104
    QStringList mavlinkLinks;           // --mavlink udp:14550, tcp:host:port, serial:/dev/ttyUSB0[:baud] (checked)
    QList<std::pair<QHostAddress, quint16>> mavlinkPeers; // --mavlink-peer: UDP vehicles to call before they are heard
    QByteArray mavlinkKey;              // --mavlink-key: the 32-byte signing key its file makes (passphrase or 64 hex digits)
    bool mavlinkRequireSigning = false; // --mavlink-require-signing
    QString mavlinkDialect;             // --mavlink-dialect: a MAVLink XML instead of ardupilotmega.xml
    QString dumpTreeFile;               // write the variable tree there on exit
    int quitAfterMs = 0;                // run this long, then exit (0: until closed)
    double forgetAfterSeconds = 0;      // forget systems silent this long (0: the settings', else never)
    int ddsDomain = 0;                  // -1: no DDS
    QString ddsConfig;                  // Cyclone XML; empty: dds/loopback.xml
    QString ddsKeys, ddsIdentity;       // DDS Security; empty: none
    QString logDirectory;               // where recordings go (--log-dir); empty: the settings', else the user's data folder
    bool record = true;                 // record every message received and sent (off: --no-record)
    QString database;                   // the operation's database (--database); empty: the settings', else beside the logs
    int webPort = -1;                   // the live web page's port (--web-port); -1: the settings' web/port, else none
    QString webBind, webToken, webCertificate, webKey, webTiles;
    QStringList replayLogs;             // --replay: feed the console from these logs instead of the network
    double replayFrom = 0;              // --replay-from: seconds into the logs to open them at
    bool replayPlay = false;            // --replay-play: start playing at once
    bool selfTest = false;

    // Parses arguments (argv[0] included). An error is a message for the user.
    static std::expected<CommandLine, QString> parse(const QStringList &arguments);
    // Where logs go: --log-dir, else the settings' log/folder, else logs/ in the user's data folder.
    QString logRoot() const;
    // The operation's database: --database, else the settings' database/url, else (if `orBesideTheLogs`)
    // operation.db in logRoot(); empty when none.
    QString databaseUrl(bool orBesideTheLogs) const;
    // An IPv4 address of this machine, given as itself or as the name of the
    // interface that has it ("eth0"); an error says what there is instead.
    static std::expected<QString, QString> localAddress(const QString &addressOrInterface);
};
