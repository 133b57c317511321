// neptus-chart-import CELL.000: reads an S-57 cell (its updates beside it
// applied) with GDAL's S-57 driver and writes the features the console uses
// to standard output (engine/charts/Chart.h, encodeCell). The console and
// neptus-chart run it as a separate process, so that GDAL crashing or hanging
// on a damaged cell cannot take them with it. Exit 0 with the cell; 1 with
// the reason on standard error.
#include "charts/S57Reader.h"

#include <QCoreApplication>
#include <QFile>

#include <cstdio>

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    if (args.size() != 2) {
        std::fprintf(stderr, "usage: neptus-chart-import CELL.000\n");
        return 2;
    }
    const auto cell = neptus::charts::readS57(args[1]);
    if (!cell) {
        std::fprintf(stderr, "%s\n", qPrintable(cell.error()));
        return 1;
    }
    const QByteArray bytes = neptus::charts::encodeCell(*cell);
    QFile out;
    if (!out.open(stdout, QIODevice::WriteOnly) || out.write(bytes) != bytes.size()) {
        std::fprintf(stderr, "%s: could not hand the cell over\n", qPrintable(args[1]));
        return 1;
    }
    return 0;
}
