// neptus-chart: nautical charts (S-57 ENC cells) from the command line, for
// scripts, tests and a laptop without a screen (docs/charts.md).
//
//   neptus-chart info PATH [--json]               cells, edition and update, coverage, features
//   neptus-chart depth PATH LON LAT [--radius M] [--json]
//                                                 land, or the charted depth, and any hazard
//                                                 or restricted area at that point
//   neptus-chart add SOURCE [--library DIR]       copy cells (a cell, an exchange set, a folder
//                                                 or a zip) into the console's charts
//   neptus-chart remove CELL [--library DIR]      take a cell out of them
//   neptus-chart list [--library DIR] [--json]    what they hold (info of the charts folder)
//
// PATH is a cell (.000), an exchange set or a folder of cells; --cache DIR
// says where read cells are kept (default ~/.cache/neptus-qt/charts).
#include "charts/ChartFiles.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <QLocale>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cstdio>

using namespace neptus::charts;
using namespace Qt::StringLiterals;

namespace {

int fail(const QString &why)
{
    std::fprintf(stderr, "neptus-chart: %s\n", qPrintable(why));
    return 1;
}

QString metres(double value) { return QString::number(value, 'f', 1) + u" m"_s; }

QString usageBand(int band)
{
    static const QStringList names{u"overview"_s, u"general"_s, u"coastal"_s, u"approach"_s, u"harbour"_s, u"berthing"_s};
    return band >= 1 && band <= 6 ? names[band - 1] : u"unknown"_s;
}

QJsonArray found(const std::vector<PointReport::Found> &list)
{
    QJsonArray out;
    for (const auto &f : list) {
        QJsonObject o{{u"class"_s, f.objectClass}, {u"what"_s, className(f.objectClass)}, {u"distance"_s, f.distance}};
        if (!f.name.isEmpty())
            o.insert(u"name"_s, f.name);
        if (f.depth)
            o.insert(u"depth"_s, *f.depth);
        out.append(o);
    }
    return out;
}

QString inWords(const std::vector<PointReport::Found> &list)
{
    QStringList out;
    for (const auto &f : list)
        out << className(f.objectClass) + (f.name.isEmpty() ? QString() : u" \""_s + f.name + u'"')
                   + (f.depth ? u", charted depth "_s + metres(*f.depth) : QString())
                   + (f.distance > 0 ? u", "_s + QString::number(f.distance, 'f', 0) + u" m away"_s : u" (here)"_s);
    return out.isEmpty() ? u"none"_s : out.join(u"; "_s);
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(u"neptus-chart"_s);
    QCommandLineParser parser;
    parser.setApplicationDescription(u"Nautical charts (S-57 ENC): info PATH | depth PATH LON LAT | add SOURCE | remove CELL | list"_s);
    parser.addHelpOption();
    parser.addPositionalArgument(u"command"_s, u"info, depth, add, remove or list"_s);
    parser.addPositionalArgument(u"path"_s, u"a cell (.000), an exchange set or a folder of cells"_s);
    const QCommandLineOption json(u"json"_s, u"Answer in JSON."_s);
    const QCommandLineOption radius(u"radius"_s, u"depth: metres around the point to look for point hazards (25)."_s, u"metres"_s, u"25"_s);
    const QCommandLineOption cache(u"cache"_s, u"Where read cells are kept."_s, u"dir"_s);
    const QCommandLineOption library(u"library"_s, u"The console's charts folder (default ~/.local/share/neptus-qt/charts)."_s, u"dir"_s);
    parser.addOptions({json, radius, cache, library});
    // Western longitudes and southern latitudes are numbers, not options: kept from the parser's eyes.
    const QString marker = u"\u0001"_s;
    // (A number after an option that takes a value is that value: left as it is, for its own check.)
    QStringList arguments = app.arguments();
    for (qsizetype i = 1; i < arguments.size(); ++i) {
        bool number = false;
        (void)arguments[i].toDouble(&number);
        const bool optionValue = arguments[i - 1] == u"--radius" || arguments[i - 1] == u"--cache" || arguments[i - 1] == u"--library";
        if (number && arguments[i].startsWith(u'-') && !optionValue)
            arguments[i].prepend(marker);
    }
    parser.process(arguments);
    QStringList args = parser.positionalArguments();
    for (QString &a : args)
        if (a.startsWith(marker))
            a.remove(0, 1);
    const QString libraryDir = parser.isSet(library) ? parser.value(library) : defaultLibraryDir();
    if (args.size() == 2 && args[0] == u"add") {
        const auto added = addToLibrary(args[1], libraryDir);
        if (!added)
            return fail(added.error());
        std::printf("added %s to %s\n", qPrintable(added->join(u", "_s)), qPrintable(QDir(libraryDir).absolutePath()));
        return 0;
    }
    if (args.size() == 2 && args[0] == u"remove") {
        if (const auto removed = removeFromLibrary(args[1], libraryDir); !removed)
            return fail(removed.error());
        std::printf("removed %s from %s\n", qPrintable(args[1]), qPrintable(QDir(libraryDir).absolutePath()));
        return 0;
    }
    if (args.size() == 1 && args[0] == u"list") {
        if (libraryCells(libraryDir).isEmpty()) { // not an error: a console with no charts of its own yet
            std::printf(parser.isSet(json) ? "{\"cells\": []}\n" : "%s holds no charts (neptus-chart add SOURCE)\n",
                        qPrintable(QDir(libraryDir).absolutePath()));
            return 0;
        }
        args = {u"info"_s, libraryDir};
    }
    if (args.size() < 2 || (args[0] != u"info" && args[0] != u"depth"))
        return fail(u"usage: neptus-chart info PATH | depth PATH LON LAT | add SOURCE | remove CELL | list (--help)"_s);
    LoadOptions options;
    options.cacheDir = parser.value(cache);
    // Progress on standard error: reading a large exchange set takes a while the first time.
    const auto cells = loadCells(args[1], options, [](int done, int total, const QString &cell) {
        std::fprintf(stderr, "reading %s (%d of %d)\n", qPrintable(cell), done + 1, total);
    });
    if (!cells)
        return fail(cells.error());

    if (args[0] == u"info") {
        QJsonArray list;
        for (const Cell &c : *cells) {
            const auto b = c.bounds();
            const auto counts = c.counts();
            if (parser.isSet(json)) {
                QJsonObject features;
                for (auto it = counts.cbegin(); it != counts.cend(); ++it)
                    features.insert(it.key(), it.value());
                list.append(QJsonObject{{u"name"_s, c.name}, {u"edition"_s, c.edition}, {u"update"_s, c.update},
                                        {u"issued"_s, c.issuedDate()}, {u"usageBand"_s, c.usageBand}, {u"scale"_s, c.scale},
                                        {u"coverage"_s, QJsonObject{{u"west"_s, b.west}, {u"south"_s, b.south}, {u"east"_s, b.east},
                                                                    {u"north"_s, b.north}}},
                                        {u"features"_s, features}});
                continue;
            }
            std::printf("%s: edition %d, update %d (%s), usage band %d (%s), 1:%s\n", qPrintable(c.name), c.edition, c.update,
                        qPrintable(c.issuedDate()), c.usageBand, qPrintable(usageBand(c.usageBand)),
                        qPrintable(QLocale(QLocale::English).toString(c.scale)));
            if (b.valid)
                std::printf("  coverage: longitude %.5f … %.5f, latitude %.5f … %.5f\n", b.west, b.east, b.south, b.north);
            for (auto it = counts.cbegin(); it != counts.cend(); ++it)
                std::printf("  %-8s %-28s %d\n", qPrintable(it.key()), qPrintable(className(it.key())), it.value());
        }
        if (parser.isSet(json))
            std::printf("%s", QJsonDocument(QJsonObject{{u"cells"_s, list}}).toJson().constData());
        return 0;
    }

    if (args.size() != 4)
        return fail(u"usage: neptus-chart depth PATH LON LAT"_s);
    bool okLon = false, okLat = false, okRadius = false;
    const double lon = args[2].toDouble(&okLon), lat = args[3].toDouble(&okLat);
    const double around = parser.value(radius).toDouble(&okRadius);
    if (!okLon || !okLat || std::abs(lon) > 180 || std::abs(lat) > 90)
        return fail(u"'%1 %2' is not a longitude and latitude in degrees"_s.arg(args[2], args[3]));
    if (!okRadius || around < 0)
        return fail(u"--radius '%1' is not a distance in metres"_s.arg(parser.value(radius)));
    const PointReport r = reportAt(*cells, lon, lat, around);
    if (parser.isSet(json)) {
        QJsonObject o{{u"lon"_s, lon}, {u"lat"_s, lat}, {u"covered"_s, r.covered}};
        if (r.covered) {
            o.insert(u"cell"_s, r.cell);
            o.insert(u"land"_s, r.land);
            if (r.depthMin) {
                QJsonObject depth{{u"min"_s, *r.depthMin}};
                if (r.depthMax)
                    depth.insert(u"max"_s, *r.depthMax);
                if (!r.depthArea.isEmpty())
                    depth.insert(u"area"_s, r.depthArea);
                o.insert(u"depth"_s, depth);
            }
            if (!r.place.isEmpty())
                o.insert(u"place"_s, r.place);
            if (r.sounding)
                o.insert(u"sounding"_s, QJsonObject{{u"depth"_s, *r.sounding}, {u"distance"_s, r.soundingDistance}});
            o.insert(u"hazards"_s, found(r.hazards));
            o.insert(u"restrictions"_s, found(r.restrictions));
        }
        std::printf("%s", QJsonDocument(o).toJson().constData());
        return 0;
    }
    if (!r.covered) {
        std::printf("%.6f, %.6f: no chart covers this point\n", lon, lat);
        return 0;
    }
    QString what;
    if (r.land)
        what = u"land"_s;
    else if (r.depthMin)
        what = u"charted depth %1–%2%3"_s.arg(QString::number(*r.depthMin, 'f', 1),
                                             r.depthMax ? metres(*r.depthMax) : u"?"_s,
                                             r.depthArea.isEmpty() ? QString() : u" (depth area \"%1\")"_s.arg(r.depthArea));
    else
        what = u"no depth area charted here"_s;
    if (!r.place.isEmpty())
        what += u", in "_s + r.place;
    std::printf("%.6f, %.6f (%s): %s\n", lon, lat, qPrintable(r.cell), qPrintable(what));
    if (r.sounding)
        std::printf("  nearest sounding: %s, %.0f m away\n", qPrintable(metres(*r.sounding)), r.soundingDistance);
    std::printf("  hazards: %s\n", qPrintable(inWords(r.hazards)));
    std::printf("  restricted areas: %s\n", qPrintable(inWords(r.restrictions)));
    return 0;
}
