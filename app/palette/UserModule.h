#pragma once

#include "PaletteEntry.h"

#include <QList>
#include <QString>

// The QML module the user's components are imported from (Neptus.User): a
// qmldir, in a folder made for the life of the process, naming each user
// component's file where it lies.
class UserModule
{
public:
    static constexpr auto uri = "Neptus.User";

    // The import path holding Neptus/User/qmldir.
    static QString importPath();
    // Writes the qmldir for `entries` (unchanged if it already says that); false if it cannot.
    static bool write(const QList<PaletteEntry> &entries);
};
