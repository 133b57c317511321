#pragma once

#include "PaletteEntry.h"

#include <QList>

// What describes a component to the designer: palette.json for the built-in
// ones, and a Name.json beside a user's Name.qml (display name, category,
// description, icon, properties, size when placed).
QList<PaletteEntry> builtInEntries();
// Fills `entry` from its manifest, when there is one; a broken manifest makes
// the entry an "error" saying where.
void readManifest(PaletteEntry &entry, const QString &jsonFile);
