#pragma once

#include "charts/Chart.h"

#include <QString>
#include <QStringList>

#include <chrono>
#include <expected>
#include <functional>
#include <memory>

// ENC cells on disk, read through the neptus-chart-import helper (GDAL, in
// its own process: a cell that crashes or hangs GDAL costs an error naming
// it, never the console) and cached: a cell is read once per edition and
// update, then loaded from the cache on every later start.
namespace neptus::charts {

// The base cells (*.000) of a cell file, an exchange set (its CATALOG.031
// folder) or any folder holding them (searched down to 4 levels), sorted.
// An error names the path when there is none.
std::expected<QStringList, QString> findCells(const QString &path);

// The cache folder: $XDG_CACHE_HOME/neptus-qt/charts (~/.cache/…) unless given.
QString defaultCacheDir();
// neptus-chart-import beside the running program.
QString defaultHelper();

struct LoadOptions
{
    QString cacheDir;     // defaultCacheDir() when empty
    QString helper;       // defaultHelper() when empty
    std::chrono::milliseconds timeout{120'000};
};

// A cell (its .000; its updates .001… beside it are applied): from the cache
// when it holds this cell's files as they are now, else read by the helper
// and cached. `fromCache` says which.
std::expected<Cell, QString> loadCell(const QString &cellPath, const LoadOptions &options = {}, bool *fromCache = nullptr);

// Every cell of `path` (findCells), `progress(done, total, cell)` before
// each; the first failure ends it, naming the cell.
std::expected<std::vector<Cell>, QString> loadCells(const QString &path, const LoadOptions &options = {},
                                                    const std::function<void(int, int, const QString &)> &progress = {});

// The cells of `path` for everyone in this process who asks (the maps, the
// vehicles' depth watch, the plan editor): read once (loadCells, with the
// default options) and shared while anyone holds them. Blocking: call it on a
// worker thread. Thread-safe. `progress` as loadCells's, for the asker that
// reads them (one who waits for another's read hears nothing).
std::expected<std::shared_ptr<const std::vector<Cell>>, QString> sharedCells(
    const QString &path, const std::function<void(int, int, const QString &)> &progress = {});

// The console's own charts (the chart manager): cells copied, with their
// updates, into one folder, a folder per cell, so that a console on a boat
// needs nothing else once they are added (no stick left in, no internet).
// $XDG_DATA_HOME/neptus-qt/charts (~/.local/share/…) unless given.
QString defaultLibraryDir();
// Adds the cells of a cell file (its updates beside it come too), an
// exchange set (its folder or its CATALOG.031), a folder of cells, or a zip
// of any of those (unpacked by
// libarchive; only cell files are taken, and no name may leave the folder).
// A cell already there is replaced whole (a new edition, or more updates).
// Returns the names of the cells added ("US4MD81M"); an error names the
// source, or the zip entry, that was wrong; a cell whose copy failed is left
// as it was held.
std::expected<QStringList, QString> addToLibrary(const QString &source, const QString &libraryDir = {});
// Takes a cell out of the library by name.
std::expected<void, QString> removeFromLibrary(const QString &cellName, const QString &libraryDir = {});
// The cells the library holds, by name, sorted.
QStringList libraryCells(const QString &libraryDir = {});

} // namespace neptus::charts
