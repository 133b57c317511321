#pragma once

// Where tests find the sources and ../shared: through links the build makes
// beside the test programs (build/<preset>/test-paths/{source,shared}), not
// through paths compiled in, so that every clone shares the compiler cache.

#include "core/DataFiles.h"

#include <QDir>
#include <QString>

namespace neptus::test {

inline QString sourcePath(const QString &relative)
{
    return QDir::cleanPath(programDirectory() + QStringLiteral("/../test-paths/source/") + relative);
}

inline QString sharedPath(const QString &relative)
{
    return QDir::cleanPath(programDirectory() + QStringLiteral("/../test-paths/shared/") + relative);
}

// The project's shipped message definitions (msgdefs/), as the programs find them.
inline QString msgdefsDirectory()
{
    return dataPath(QStringLiteral("msgdefs"));
}

// A program built beside the test (neptus, neptus-sim, ...).
inline QString programPath(const QString &name)
{
    return programDirectory() + u'/' + name;
}

} // namespace neptus::test
