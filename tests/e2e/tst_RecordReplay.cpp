// The mission afterwards: a console records a simulated vehicle running a
// plan; the console program, started on that log (--replay), ends in the
// same state as the console that lived it; the log's exports read back in
// their formats (neptus-log, as a user runs it) and open in GDAL, the reader
// QGIS uses; GPX validates against GPX 1.1's schema.
#include "log/LogFile.h"
#include "log/Recorder.h"
#include "xml/XmlSchema.h"

#include "PlanRun.h"
#include "SimProcess.h"
#include "TrackFiles.h"

#include <QDirIterator>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QXmlStreamReader>

using namespace neptus;
using namespace Qt::StringLiterals;
using namespace neptus::test;

namespace {

// A tree's values: without message rates and counts (statistics of
// arrivals, which a replay opened at its end has not seen one by one),
// without the link a system was heard on (a log does not say) and without
// empty nodes.
QStringList treeValues(const QString &dump)
{
    static const QRegularExpression statistics(uR"((\s·\s)?([0-9.]+/s|[0-9]+ received|[0-9]+ sent|via [^\t]+)(?=\t|\s·))"_s);
    QStringList values;
    for (QString line : dump.split(u'\n')) {
        line.replace(statistics, QString());
        line.replace(u" · \t"_s, u"\t"_s);
        line.replace(u" \t"_s, u"\t"_s);
        if (line.section(u'\t', 1, 1).trimmed().isEmpty())
            continue;
        values.append(line);
    }
    values.sort();
    return values;
}

QString difference(const QStringList &live, const QStringList &replayed)
{
    const QSet<QString> a(live.begin(), live.end()), b(replayed.begin(), replayed.end());
    QStringList only;
    for (const QString &line : a - b)
        only.append(u"live only:     "_s + line);
    for (const QString &line : b - a)
        only.append(u"replayed only: "_s + line);
    only.sort();
    return only.mid(0, 20).join(u'\n');
}

QByteArray run(const QString &program, const QStringList &arguments, int *exitCode = nullptr)
{
    QProcess process;
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(program.startsWith(u'/') ? program : programPath(program), arguments);
    EXPECT_TRUE(process.waitForFinished(60000)) << program.toStdString();
    if (exitCode)
        *exitCode = process.exitCode();
    return process.readAll();
}

} // namespace

TEST(RecordReplay, AVehicleRunningAPlanIsRecordedAndTheReplayEndsInTheLiveConsolesState)
{
    QTemporaryDir logs;
    SimProcess vehicle;
    vehicle.start({u"--id"_s, u"0x1f"_s, u"--name"_s, u"lauv-sim-1"_s, u"--port"_s, u"16140"_s, u"--time-factor"_s, u"30"_s});

    log::RecorderConfig config;
    config.root = logs.path();
    config.name = u"e2e"_s;
    config.system = 0x4001;
    config.definitionFiles = msg::Schema::filesIn(msgdefsDirectory());
    log::Recorder recorder(config);
    ASSERT_TRUE(recorder.start().has_value());
    {
        session::Console console(shippedSchema());
        console.setRecorder(&recorder);
        ASSERT_TRUE(console.startImc(imcTo({16140})));
        ASSERT_TRUE(QTest::qWaitFor([&] { return heard(console.tree(), u"lauv-sim-1"_s); }, 15000));
        runPlan(console, 0x1f, u"lauv-sim-1"_s, missionFor("lauv-sim-1", 2, "DEPTH"));
        // The vehicle goes quiet; what the console knows then is what it recorded.
        vehicle.process->kill();
        vehicle.process->waitForFinished();
        QTest::qWait(500);
        const QString live = console.dumpTree();
        recorder.stop();
        EXPECT_EQ(recorder.status().lost, 0u);
        EXPECT_TRUE(recorder.status().problem.isEmpty()) << recorder.status().problem.toStdString();

        // The console program, fed from the log and opened at its end.
        const QString folder = recorder.status().folder;
        const QString dump = logs.filePath(u"replayed-tree.txt"_s);
        int exitCode = -1;
        const QByteArray output = run(u"neptus"_s, {u"--replay"_s, folder, u"--replay-from"_s, u"100000"_s,
                                                    u"--console"_s, sourcePath(u"qml/consoles/Inspector.qml"_s),
                                                    u"--quit-after"_s, u"3000"_s, u"--dump-tree"_s, dump}, &exitCode);
        ASSERT_EQ(exitCode, 0) << output.constData();
        EXPECT_TRUE(output.contains("neptus: replaying")) << output.constData();
        QFile replayed(dump);
        ASSERT_TRUE(replayed.open(QIODevice::ReadOnly)) << output.constData();
        const QStringList liveValues = treeValues(live), replayedValues = treeValues(QString::fromUtf8(replayed.readAll()));
        EXPECT_GT(liveValues.size(), 100);
        const QString different = difference(liveValues, replayedValues);
        EXPECT_TRUE(different.isEmpty()) << different.toStdString();
        // The plan as the vehicle told it, and the commands the console sent.
        EXPECT_TRUE(replayedValues.contains(u"lauv-sim-1/PlanControlState/last_outcome\tSUCCESS\t"_s));
        EXPECT_TRUE(std::any_of(replayedValues.begin(), replayedValues.end(),
                                [](const QString &l) { return l.startsWith(u"lauv-sim-1/out/PlanControl/"_s); }));
    }

    // Exports, from the command line.
    const QString folder = recorder.status().folder;
    auto log = log::LogFile::open(folder);
    ASSERT_TRUE(log.has_value());
    qint64 states = 0;
    for (qsizetype i = 0; i < (*log)->count(); ++i)
        states += (*log)->source(i) == 0x1f && (*log)->schemas().defaultSchema().byId((*log)->messageId(i))
                  && (*log)->schemas().defaultSchema().byId((*log)->messageId(i))->abbrev == u"EstimatedState";
    ASSERT_GT(states, 100);
    const QDir out(logs.filePath(u"exports"_s));
    for (const char *format : {"csv", "kml", "geojson", "gpx"}) {
        const QString target = out.filePath(format == std::string("csv") ? u"csv"_s : u"track."_s + QLatin1StringView(format));
        int exitCode = -1;
        const QByteArray output = run(u"neptus-log"_s, {u"export"_s, u"--to"_s, QLatin1StringView(format), u"--out"_s, target, folder}, &exitCode);
        ASSERT_EQ(exitCode, 0) << format << ": " << output.constData();
    }
    // CSV: a row per EstimatedState, every row as many cells as the header, numbers where numbers go.
    QFile csv(out.filePath(u"csv/EstimatedState.csv"_s));
    ASSERT_TRUE(csv.open(QIODevice::ReadOnly));
    const QList<QByteArray> rows = csv.readAll().trimmed().split('\n');
    ASSERT_EQ(rows.size(), 1 + states);
    const qsizetype columns = rows.front().split(',').size();
    for (const QByteArray &row : rows.mid(1)) {
        const QList<QByteArray> cells = row.split(',');
        ASSERT_EQ(cells.size(), columns) << row.constData();
        bool ok = false;
        cells[0].toDouble(&ok);
        ASSERT_TRUE(ok) << row.constData();
    }
    // GeoJSON: parsed, one line of the vehicle's positions.
    QFile geojson(out.filePath(u"track.geojson"_s));
    ASSERT_TRUE(geojson.open(QIODevice::ReadOnly));
    QJsonParseError error{};
    const QJsonObject collection = QJsonDocument::fromJson(geojson.readAll(), &error).object();
    ASSERT_EQ(error.error, QJsonParseError::NoError) << error.errorString().toStdString();
    const QJsonArray features = collection.value(u"features"_s).toArray();
    ASSERT_EQ(features.size(), 1);
    const qsizetype points = features[0].toObject().value(u"geometry"_s).toObject().value(u"coordinates"_s).toArray().size();
    EXPECT_GT(points, 100);
    // KML and GPX: well-formed XML in their namespaces, with the same points.
    for (const auto &[file, ns] : {std::pair{u"track.kml"_s, u"http://www.opengis.net/kml/2.2"_s},
                                   std::pair{u"track.gpx"_s, u"http://www.topografix.com/GPX/1/1"_s}}) {
        const auto contents = readTrackFile(out.filePath(file));
        EXPECT_TRUE(contents.error.isEmpty()) << file.toStdString() << ": " << contents.error.toStdString();
        EXPECT_EQ(contents.rootNamespace, ns);
        EXPECT_EQ(contents.points, points) << file.toStdString();
    }
    const auto gpxSchema = xml::XmlSchema::load(sourcePath(u"tests/data/schemas/gpx-1.1.xsd"_s));
    ASSERT_TRUE(gpxSchema.has_value()) << gpxSchema.error().toString().toStdString();
    const auto gpx = xml::XmlDocument::load(out.filePath(u"track.gpx"_s));
    ASSERT_TRUE(gpx.has_value());
    for (const xml::XmlError &problem : gpxSchema->validate(*gpx))
        ADD_FAILURE() << problem.toString().toStdString();
    // ...and the schema bites: a latitude out of range, a point before its track.
    for (const char *bad : {R"(<gpx xmlns="http://www.topografix.com/GPX/1/1" version="1.1" creator="t"><trk><trkseg><trkpt lat="91" lon="0"/></trkseg></trk></gpx>)",
                            R"(<gpx xmlns="http://www.topografix.com/GPX/1/1" version="1.1" creator="t"><trkpt lat="1" lon="0"/></gpx>)"}) {
        const auto document = xml::XmlDocument::parse(QByteArrayView(bad), u"bad.gpx"_s);
        ASSERT_TRUE(document.has_value());
        EXPECT_FALSE(gpxSchema->validate(*document).isEmpty()) << bad;
    }

    // Opened by GDAL (ogrinfo), a reader of each format: every point, every row.
    auto ogr = [&](const QStringList &arguments) {
        int exitCode = -1;
        const QString output = QString::fromUtf8(run(u"/usr/bin/ogrinfo"_s, QStringList{u"-ro"_s} + arguments, &exitCode));
        EXPECT_EQ(exitCode, 0) << output.toStdString();
        return output;
    };
    auto number = [](const QString &output, const QString &pattern) {
        const QRegularExpressionMatch match = QRegularExpression(pattern).match(output);
        return match.hasMatch() ? match.captured(1).toLongLong() : -1;
    };
    for (const QString &file : {u"track.kml"_s, u"track.geojson"_s}) {
        const QString output = ogr({u"-al"_s, u"-geom=SUMMARY"_s, out.filePath(file)});
        EXPECT_EQ(number(output, u"Feature Count: (\\d+)"_s), 1) << file.toStdString() << output.toStdString();
        EXPECT_EQ(number(output, u"LINESTRING[^:]*: (\\d+) points"_s), points) << file.toStdString() << output.toStdString();
    }
    const QString trackPoints = ogr({u"-so"_s, out.filePath(u"track.gpx"_s), u"track_points"_s});
    EXPECT_EQ(number(trackPoints, u"Feature Count: (\\d+)"_s), points) << trackPoints.toStdString();
    const QString rowsRead = ogr({u"-al"_s, u"-so"_s, out.filePath(u"csv/EstimatedState.csv"_s)});
    EXPECT_EQ(number(rowsRead, u"Feature Count: (\\d+)"_s), states) << rowsRead.toStdString();
}
