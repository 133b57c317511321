#pragma once

// The Qt application a fuzz target's code needs (event loop, timers,
// QCoreApplication::applicationDirPath for helper programs), made on the
// first input and never destroyed: objects a target keeps across inputs are
// destroyed after it at exit and may still use it.
#include <QCoreApplication>

#include <cstdio>
#include <cstdlib>

namespace neptus::test {

// A property every input must keep: broken, the target says which and stops
// (libFuzzer keeps the input as a crash).
inline void fuzzCheck(bool ok, const char *target, const char *what)
{
    if (!ok) {
        std::fprintf(stderr, "%s: %s\n", target, what);
        std::abort();
    }
}

inline void ensureFuzzApplication()
{
    static int argc = 1;
    static char name[] = "fuzz";
    static char *argv[] = {name, nullptr};
    static auto *app = new QCoreApplication(argc, argv);
    Q_UNUSED(app);
}

} // namespace neptus::test
