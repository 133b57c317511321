#pragma once

#include <QDateTime>
#include <QString>
#include <QUrl>
#include <QVariantList>

// One component the designer offers: built in (module Neptus.Components,
// described by palette.json) or the user's (a Name.qml in a component
// directory, described by an optional Name.json beside it).
struct PaletteEntry
{
    QString name, module, displayName, category, description;
    QUrl icon, source;
    QVariantList properties;
    double defaultWidth = 0, defaultHeight = 0; // as placed; 0: the designer's default
    QString status = QStringLiteral("ready");    // or "error", with errorString
    QString errorString;
    bool builtIn = false;
    QDateTime modified; // of the .qml and .json, the later
    qint64 size = -1;
};
