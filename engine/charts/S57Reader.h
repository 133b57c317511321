#pragma once

#include "charts/Chart.h"

#include <QString>

#include <expected>

// Reads an S-57 cell with GDAL's S57 driver, its updates (.001 …) applied,
// keeping the object classes of keptClasses(). GDAL is large C code reading
// files from outside: only the neptus-chart-import helper and the tests link
// this, never the console.
namespace neptus::charts {

std::expected<Cell, QString> readS57(const QString &path);

} // namespace neptus::charts
