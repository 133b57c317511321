#pragma once

// The Qt application a fuzz target's code needs (event loop, timers,
// QCoreApplication::applicationDirPath for helper programs), made on the
// first input and never destroyed: objects a target keeps across inputs are
// destroyed after it at exit and may still use it.
#include <QAbstractItemModel>
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

// Reads every row a model shows (up to `budget` rows), as a view would.
inline int readModel(const QAbstractItemModel &model, const QModelIndex &parent, int budget)
{
    for (int row = 0; row < model.rowCount(parent) && budget > 0; ++row) {
        for (int column = 0; column < model.columnCount(parent); ++column)
            model.data(model.index(row, column, parent), Qt::DisplayRole);
        --budget;
        budget = readModel(model, model.index(row, 0, parent), budget);
    }
    return budget;
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
