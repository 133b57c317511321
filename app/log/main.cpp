// neptus-log: what is in a log, and the log in other forms. Reads ours and
// DUNE's (a folder with Data.lsf or Data.lsf.gz and IMC.xml[.gz]); several
// logs of one mission are merged by time.
//   neptus-log info LOG...
//   neptus-log export --to csv|kml|geojson|gpx [--out PATH] LOG...
//   neptus-log slice --from T --to T --out DIR LOG...   (T: seconds from the start, or UTC "2026-11-24T10:00:05")
//   neptus-log merge --out DIR LOG...
//   neptus-log sessions DATABASE    (the operation's database: who recorded, and the logs, to open with --replay)
#include "database/Database.h"
#include "log/LogExport.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDateTime>
#include <QFileInfo>
#include <QLocale>
#include <QTextStream>
#include <QTimeZone>

#include <cstdio>
#include <unistd.h>

using namespace neptus;

namespace {

constexpr int usageError = 2;

int fail(const QString &message)
{
    std::fprintf(stderr, "neptus-log: %s\n", qPrintable(message));
    return 1;
}

// "exporting: 45 %" on a terminal, rewritten in place.
log::Progress progressSaying(const char *what)
{
    if (!isatty(STDERR_FILENO))
        return {};
    return [what, last = -1](double fraction) mutable {
        const int percent = int(fraction * 100);
        if (percent != last) {
            last = percent;
            std::fprintf(stderr, "\r%s: %3d %%%s", what, percent, percent >= 100 ? "\n" : "");
        }
        return true;
    };
}

QString timeText(double t)
{
    return QDateTime::fromMSecsSinceEpoch(qint64(t * 1000), QTimeZone::UTC).toString(Qt::ISODateWithMs);
}

// Seconds from the logs' start ("90", "1:30") or a UTC time, as a log time.
std::expected<double, QString> parseTime(const QString &text, double begin)
{
    bool ok = false;
    if (const double seconds = text.toDouble(&ok); ok)
        return begin + seconds;
    if (const QStringList parts = text.split(u':'); parts.size() == 2 || parts.size() == 3) {
        double seconds = 0;
        bool all = true;
        for (const QString &part : parts) {
            seconds = seconds * 60 + part.toDouble(&ok);
            all = all && ok;
        }
        if (all)
            return begin + seconds;
    }
    QDateTime at = QDateTime::fromString(text, Qt::ISODateWithMs);
    if (at.isValid()) {
        if (at.timeSpec() == Qt::LocalTime)
            at.setTimeZone(QTimeZone::UTC);
        return at.toMSecsSinceEpoch() / 1000.0;
    }
    return std::unexpected(QStringLiteral("'%1' is not a time: seconds from the start (90, 1:30) or UTC (2026-11-24T10:00:05)").arg(text));
}

QString utc(qint64 ms)
{
    return QDateTime::fromMSecsSinceEpoch(ms, QTimeZone::UTC).toString(QStringLiteral("yyyy-MM-dd HH:mm:ss"));
}

// The operation's sessions (each console or recorder node that wrote the
// database) and the logs they recorded, oldest first.
int sessions(const QString &database)
{
    const auto location = db::Location::parse(database);
    if (!location)
        return fail(location.error());
    auto reader = db::Reader::open(*location);
    if (!reader)
        return fail(reader.error());
    const auto all = (*reader)->sessions();
    const auto logs = (*reader)->logs();
    if (!all || !logs)
        return fail(all ? logs.error() : all.error());
    QTextStream out(stdout);
    out << location->display() << ": " << all->size() << " sessions, " << logs->size() << " logs\n";
    for (const auto &s : *all) {
        out << "\n" << utc(s.startMs) << " – " << utc(s.lastMs).mid(11) << " UTC  " << s.console << " on " << s.host << " (" << s.program << ")\n";
        for (const auto &l : *logs)
            if (l.session == s.session)
                out << "    " << l.folder << "  " << QString::number((l.endMs - l.beginMs) / 1000.0, 'f', 0) << " s, " << l.packets
                    << " packets\n";
    }
    return 0;
}

int info(const log::LogSet &logs)
{
    const log::LogSummary summary = log::summarize(logs);
    const QLocale c = QLocale::c();
    QTextStream out(stdout);
    for (const auto &file : logs.logs())
        out << "log       " << file->folder() << "\n";
    out << "span      " << timeText(summary.begin) << " to " << timeText(summary.end) << " ("
        << QString::number(summary.end - summary.begin, 'f', 1) << " s)\n";
    out << "packets   " << c.toString(summary.packets) << "\n";
    for (const QString &damage : summary.damage)
        out << "damage    " << damage << "\n";
    out << "systems   " << summary.systems.size() << "\n";
    for (const auto &system : summary.systems)
        out << "  " << msg::systemLabel(system.id) << "  " << qSetFieldWidth(24) << Qt::left << system.name
            << qSetFieldWidth(12) << Qt::right << c.toString(system.packets) << qSetFieldWidth(0) << Qt::left << "\n";
    out << "types     " << summary.types.size() << "\n";
    for (const auto &[abbrev, count] : summary.types)
        out << "  " << qSetFieldWidth(28) << Qt::left << abbrev << qSetFieldWidth(12) << Qt::right << c.toString(count)
            << qSetFieldWidth(0) << Qt::left << "\n";
    return 0;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("neptus-log"));
    QCoreApplication::setApplicationVersion(QStringLiteral(NEPTUS_VERSION));
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Logs (Data.lsf with IMC.xml): their contents, exports, slices, merges."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("command"), QStringLiteral("info, export, slice, merge, or sessions DATABASE"));
    parser.addPositionalArgument(QStringLiteral("logs"), QStringLiteral("log folders (or their Data.lsf[.gz])"), QStringLiteral("LOG..."));
    const QCommandLineOption to(QStringLiteral("to"), QStringLiteral("export format: csv, kml, geojson or gpx"), QStringLiteral("format"));
    const QCommandLineOption outPath(QStringLiteral("out"), QStringLiteral("where to write"), QStringLiteral("path"));
    const QCommandLineOption from(QStringLiteral("from"), QStringLiteral("slice start"), QStringLiteral("time"));
    const QCommandLineOption until(QStringLiteral("until"), QStringLiteral("slice end (also --to with slice)"), QStringLiteral("time"));
    parser.addOptions({to, outPath, from, until});
    parser.process(app);

    const QStringList positional = parser.positionalArguments();
    if (positional.size() < 2) {
        std::fprintf(stderr, "%s", qPrintable(parser.helpText()));
        return usageError;
    }
    const QString command = positional.front();
    if (command == u"sessions")
        return sessions(positional.at(1));
    if (!QStringList{QStringLiteral("info"), QStringLiteral("export"), QStringLiteral("slice"), QStringLiteral("merge")}.contains(command))
        return fail(QStringLiteral("unknown command '%1' (info, export, slice, merge)").arg(command)), usageError;

    std::vector<std::shared_ptr<const log::LogFile>> files;
    for (const QString &path : positional.mid(1)) {
        auto file = log::LogFile::open(path);
        if (!file)
            return fail(file.error());
        if (!(*file)->damage().isEmpty())
            std::fprintf(stderr, "neptus-log: warning: %s\n", qPrintable((*file)->damage()));
        files.push_back(*file);
    }
    const log::LogSet logs(files);
    const QString name = QFileInfo(files.front()->folder()).fileName();

    if (command == u"info")
        return info(logs);

    if (command == u"export") {
        const QString format = parser.value(to).toLower();
        if (format == u"csv") {
            const QString folder = parser.isSet(outPath) ? parser.value(outPath) : name + QStringLiteral("-csv");
            auto written = log::exportCsv(logs, folder, progressSaying("exporting"));
            if (!written)
                return fail(written.error());
            std::printf("%lld CSV files in %s\n", static_cast<long long>(written->size()), qPrintable(folder));
            return 0;
        }
        const auto track = log::trackFormat(format);
        if (!track)
            return fail(QStringLiteral("--to must be csv, kml, geojson or gpx, not '%1'").arg(parser.value(to))), usageError;
        const QString file = parser.isSet(outPath) ? parser.value(outPath) : name + u'.' + format;
        if (auto done = log::exportTracks(logs, *track, file, progressSaying("exporting")); !done)
            return fail(done.error());
        std::printf("%s\n", qPrintable(file));
        return 0;
    }

    if (!parser.isSet(outPath))
        return fail(QStringLiteral("%1 needs --out DIR, a new folder for the new log").arg(command)), usageError;
    double begin = logs.begin(), end = logs.end();
    if (command == u"slice") {
        const QString fromText = parser.value(from);
        const QString toText = parser.isSet(until) ? parser.value(until) : parser.value(to);
        if (fromText.isEmpty() && toText.isEmpty())
            return fail(QStringLiteral("slice needs --from and/or --to")), usageError;
        if (!fromText.isEmpty()) {
            auto t = parseTime(fromText, logs.begin());
            if (!t)
                return fail(t.error()), usageError;
            begin = *t;
        }
        if (!toText.isEmpty()) {
            auto t = parseTime(toText, logs.begin());
            if (!t)
                return fail(t.error()), usageError;
            end = *t;
        }
        if (end < begin)
            return fail(QStringLiteral("the slice ends (%1) before it begins (%2)").arg(timeText(end), timeText(begin))), usageError;
    }
    auto written = log::writeLog(logs, begin, end, parser.value(outPath), progressSaying("writing"));
    if (!written)
        return fail(written.error());
    std::printf("%lld packets in %s\n", static_cast<long long>(*written), qPrintable(parser.value(outPath)));
    return 0;
}
