#pragma once

#include "PaletteEntry.h"

class QQmlEngine;

// Compiles a user component with the console's engine: a component that does
// not compile becomes an "error" entry with its QML errors (file:line:column);
// one without a manifest list of properties gets the properties it declares
// (numbers, texts, paths, booleans, colours) for the property editor.
void compileComponent(QQmlEngine &engine, PaletteEntry &entry);
