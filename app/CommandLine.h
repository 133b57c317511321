#pragma once

#include <QString>
#include <QStringList>
#include <QSize>

#include <expected>

// What the `neptus` command line asks for, already checked.
struct CommandLine
{
    QString consoleFile;     // layout to open
    QString screenshotFile;  // render, save a PNG, exit
    int screenshotDelayMs = 0; // wait this long after the first frame
    QString palette;         // day, dusk or night; empty = as last time
    QStringList componentDirectories;   // --components, before the standard ones
    bool edit = false;                  // start in edit mode
    QString select;                     // with edit: the component selected
    QString system;                     // the console's main system ($main)
    QSize windowSize{1280, 800};
    quint16 imcPort = 6001;             // IMC over UDP, on 127.0.0.1
    QStringList imcPeers;               // static IMC destinations, "host:port"
    int ddsDomain = 0;                  // -1: no DDS
    QString ddsConfig;                  // Cyclone XML; empty: dds/loopback.xml
    bool selfTest = false;

    // Parses arguments (argv[0] included). An error is a message for the user.
    static std::expected<CommandLine, QString> parse(const QStringList &arguments);
};
