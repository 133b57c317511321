#pragma once

// The Qt application a fuzz target's code needs (event loop, timers,
// QCoreApplication::applicationDirPath for helper programs), made on the
// first input and never destroyed: objects a target keeps across inputs are
// destroyed after it at exit and may still use it.
#include <QCoreApplication>

namespace neptus::test {

inline void ensureFuzzApplication()
{
    static int argc = 1;
    static char name[] = "fuzz";
    static char *argv[] = {name, nullptr};
    static auto *app = new QCoreApplication(argc, argv);
    Q_UNUSED(app);
}

} // namespace neptus::test
