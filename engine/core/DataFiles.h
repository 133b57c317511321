#pragma once

#include <QString>

namespace neptus {

// Where the files the program ships live (message definitions, console
// layouts, the DDS configuration, later stylesheets and vehicle
// definitions): <prefix>/share/neptus-qt, next to the program's own bin/
// folder. The install tree is laid out so, and the build tree too (the build
// makes share/neptus-qt with links into the sources), so nothing reads the
// source tree by a path compiled in. NEPTUS_DATA_DIR overrides it.
QString dataDirectory();
// dataDirectory() + "/" + relative.
QString dataPath(const QString &relative);
// The folder of the running program (its bin/ folder).
QString programDirectory();

} // namespace neptus
