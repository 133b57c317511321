// Logs (engine/log): what the recorder writes reads back as it was, a real
// DUNE log reads with the counts its README gives, damage is said by byte
// offset, parts rotate, a killed recorder loses at most the last second, a
// full disk is survived, and seeking gives the state a full replay gives.

#include "Fixtures.h"
#include "Schemas.h"
#include "SmallDisk.h"
#include "TrackFiles.h"
#include "log/LogExport.h"
#include "log/LogFile.h"
#include "log/Recorder.h"
#include "log/Replay.h"
#include "xml/XmlSchema.h"
#include "messages/Codec.h"
#include "qmlmodels/ReplayModel.h"
#include "session/ConsoleReplay.h"

#include <QElapsedTimer>
#include <QCoreApplication>
#include <cmath>
#include <QDateTime>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QXmlStreamReader>
#include <QRandomGenerator>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>
#include <QScopeGuard>

#include <libxml/parserInternals.h>

#include <gtest/gtest.h>

using namespace neptus;
using namespace Qt::StringLiterals;

namespace {

// `count` EstimatedState and Heartbeat packets from two systems, 10 ms apart from `start`.
std::vector<QByteArray> makePackets(int count, double start = 1.7e9)
{
    const auto schema = test::shippedSchema();
    const msg::Codec codec(schema);
    std::vector<QByteArray> packets;
    msg::Message state(schema->byAbbrev(u"EstimatedState"));
    msg::Message heartbeat(schema->byAbbrev(u"Heartbeat"));
    const int depth = state.def()->fieldIndex.value(QStringLiteral("depth"));
    for (int i = 0; i < count; ++i) {
        msg::Message &m = i % 10 == 9 ? heartbeat : state;
        m.header.timestamp = start + i * 0.01;
        m.header.src = i % 2 ? 0x00d1 : 0x00d2;
        m.header.srcEnt = 1;
        if (&m == &state)
            m.setNumber(depth, i * 0.5);
        packets.push_back(*codec.encode(m));
    }
    return packets;
}

log::RecorderConfig configIn(const QString &root)
{
    log::RecorderConfig config;
    config.root = root;
    config.name = QStringLiteral("test");
    config.system = 0x4001;
    config.definitionFiles = msg::Schema::filesIn(test::msgdefsDirectory());
    config.flushMs = 20;
    return config;
}

QStringList partsIn(const QString &root)
{
    QStringList parts;
    QDirIterator it(root, {QStringLiteral("Data.lsf")}, QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext())
        parts.append(QFileInfo(it.next()).absolutePath());
    parts.sort();
    return parts;
}

std::shared_ptr<const log::LogFile> openLog(const QString &path)
{
    auto log = log::LogFile::open(path);
    EXPECT_TRUE(log.has_value()) << qPrintable(log.error());
    return log ? *log : nullptr;
}

} // namespace

TEST(Log, WhatIsRecordedReadsBackByteForByteWithItsDefinitionsAndIndex)
{
    QTemporaryDir root;
    const auto packets = makePackets(5000);
    {
        log::Recorder recorder(configIn(root.path()));
        ASSERT_TRUE(recorder.start().has_value());
        for (const QByteArray &p : packets)
            recorder.record(p);
        recorder.stop();
        EXPECT_EQ(recorder.status().packets, 5000u);
        EXPECT_EQ(recorder.status().lost, 0u);
        EXPECT_TRUE(recorder.status().problem.isEmpty());
    }
    const QStringList parts = partsIn(root.path());
    ASSERT_EQ(parts.size(), 1);
    const QDir part(parts.front());
    EXPECT_TRUE(part.exists(QStringLiteral("IMC.xml")));
    EXPECT_TRUE(part.exists(QStringLiteral("Meta.json")));
    EXPECT_TRUE(part.exists(QStringLiteral("Data.lsf.index")));
    // The index was written as the packets were (the recorder holds none in memory), and put in place at the end.
    EXPECT_FALSE(part.exists(QStringLiteral("Data.lsf.index.partial")));
    EXPECT_FALSE(part.exists(QStringLiteral("Data.lsf.times.partial")));
    EXPECT_TRUE(part.exists(QStringLiteral("IMC-extra-motor.xml")));

    auto log = openLog(part.path());
    ASSERT_TRUE(log);
    EXPECT_TRUE(log->indexReused()) << "the recorder's index was not taken";
    EXPECT_TRUE(log->damage().isEmpty()) << qPrintable(log->damage());
    EXPECT_EQ(log->recorder(), 0x4001);
    EXPECT_EQ(log->recorderName(), QStringLiteral("test"));
    ASSERT_EQ(log->count(), 5000);
    for (qsizetype i = 0; i < log->count(); ++i)
        ASSERT_EQ(log->packet(i).toByteArray(), packets[size_t(i)]) << "packet " << i;
    EXPECT_NEAR(log->end() - log->begin(), 49.99, 1e-6);
    auto decoded = log->decode(42);
    ASSERT_TRUE(decoded.has_value());
    EXPECT_EQ(decoded->abbrev(), QStringLiteral("EstimatedState"));
    EXPECT_DOUBLE_EQ(decoded->number(u"depth"), 21.0);
    // The extra definitions (Motor, id 1000) came along.
    EXPECT_NE(log->schemas().defaultSchema().byAbbrev(u"Motor"), nullptr);

    // Without the index the same packets, found by scanning; the index is made again.
    QFile::remove(part.filePath(QStringLiteral("Data.lsf.index")));
    auto scanned = openLog(part.path());
    ASSERT_TRUE(scanned);
    EXPECT_FALSE(scanned->indexReused());
    EXPECT_EQ(scanned->count(), 5000);
    EXPECT_TRUE(part.exists(QStringLiteral("Data.lsf.index")));
}

TEST(Log, TheDuneLogReadsWithTheCountsOfItsReadme)
{
    NEPTUS_REQUIRE_FIXTURE(folder, "dune-log");
    auto log = openLog(folder);
    ASSERT_TRUE(log);
    EXPECT_TRUE(log->damage().isEmpty()) << qPrintable(log->damage());
    EXPECT_EQ(log->count(), 179142);
    EXPECT_EQ(log->readBytes(), 8008290);
    EXPECT_EQ(log->schemas().defaultSchema().messages().size(), 350u) << "not its own IMC.xml.gz";
    QHash<QString, int> byType;
    int fromVehicle = 0, fromConsole = 0;
    for (qsizetype i = 0; i < log->count(); ++i) {
        const msg::MessageDef *def = log->schemas().defaultSchema().byId(log->messageId(i));
        byType[def ? def->abbrev : QStringLiteral("?")]++;
        fromVehicle += log->source(i) == 0x00D1;
        fromConsole += log->source(i) == 0x4001;
    }
    EXPECT_EQ(byType.size(), 61);
    EXPECT_EQ(fromVehicle, 179003);
    EXPECT_EQ(fromConsole, 139);
    EXPECT_EQ(byType.value(QStringLiteral("ServoPosition")), 55098);
    EXPECT_EQ(byType.value(QStringLiteral("EstimatedState")), 2755);
    EXPECT_EQ(byType.value(QStringLiteral("PlanControlState")), 395);
    EXPECT_EQ(byType.value(QStringLiteral("LogBookEntry")), 16);
    EXPECT_EQ(byType.value(QStringLiteral("PlanControl")), 2);
    EXPECT_EQ(byType.value(QStringLiteral("PlanSpecification")), 1);
    EXPECT_NEAR(log->end() - log->begin(), 137.8, 0.05);
    // Every packet decodes with the log's own definitions.
    for (qsizetype i = 0; i < log->count(); i += 97)
        ASSERT_TRUE(log->decode(i).has_value()) << "packet " << i;
}

TEST(Log, ADamagedLogIsReadUpToTheDamageWhichIsNamedByByteOffset)
{
    const auto packets = makePackets(100);
    QByteArray whole;
    for (const QByteArray &p : packets)
        whole += p;
    const auto schemas = std::make_shared<msg::SchemaSet>(test::shippedSchema());
    const auto startOf = [&](int packet) {
        qsizetype at = 0;
        for (int i = 0; i < packet; ++i)
            at += packets[size_t(i)].size();
        return at;
    };

    // Cut in the middle of packet 60.
    auto cut = log::LogFile::fromData(whole.left(startOf(60) + 30), schemas);
    EXPECT_EQ(cut->count(), 60);
    EXPECT_TRUE(cut->damage().contains(QStringLiteral("cut at byte %1").arg(startOf(60)))) << qPrintable(cut->damage());
    EXPECT_TRUE(cut->damage().contains(QStringLiteral("read 60 packets"))) << qPrintable(cut->damage());

    // Garbage where packet 40 starts.
    QByteArray garbage = whole;
    garbage[startOf(40)] = 'x';
    auto broken = log::LogFile::fromData(garbage, schemas);
    EXPECT_EQ(broken->count(), 40);
    EXPECT_TRUE(broken->damage().contains(QStringLiteral("at byte %1: no IMC sync number").arg(startOf(40))))
        << qPrintable(broken->damage());

    // A changed byte inside packet 10: that packet is left out, the rest read.
    QByteArray flipped = whole;
    flipped[startOf(10) + 25] = char(flipped[startOf(10) + 25] ^ 0x40);
    auto skipped = log::LogFile::fromData(flipped, schemas);
    EXPECT_EQ(skipped->count(), 99);
    EXPECT_TRUE(skipped->damage().contains(QStringLiteral("1 packets with a wrong checksum left out (the first at byte %1)")
                                               .arg(startOf(10))))
        << qPrintable(skipped->damage());

    // Nothing, and a folder that is not a log.
    EXPECT_EQ(log::LogFile::fromData({}, schemas)->count(), 0);
    QTemporaryDir empty;
    auto none = log::LogFile::open(empty.path());
    ASSERT_FALSE(none.has_value());
    EXPECT_TRUE(none.error().contains(QStringLiteral("no Data.lsf"))) << qPrintable(none.error());
    QFile(QDir(empty.path()).filePath(QStringLiteral("Data.lsf"))).open(QIODevice::WriteOnly);
    auto noDefinitions = log::LogFile::open(empty.path());
    ASSERT_FALSE(noDefinitions.has_value());
    EXPECT_TRUE(noDefinitions.error().contains(QStringLiteral("no IMC.xml"))) << qPrintable(noDefinitions.error());
}

TEST(Log, PartsRotateBySizeAndTimeAndReadTogetherAsOne)
{
    QTemporaryDir root;
    const auto packets = makePackets(3000);
    log::RecorderConfig config = configIn(root.path());
    config.maxPartBytes = 40000; // about 360 packets
    {
        log::Recorder recorder(config);
        ASSERT_TRUE(recorder.start().has_value());
        for (const QByteArray &p : packets)
            recorder.record(p);
        recorder.stop();
        EXPECT_GE(recorder.status().parts, 8);
    }
    const QStringList parts = partsIn(root.path());
    ASSERT_GE(parts.size(), 8);
    std::vector<std::shared_ptr<const log::LogFile>> logs;
    qsizetype total = 0;
    for (const QString &part : parts) {
        auto log = openLog(part);
        ASSERT_TRUE(log);
        EXPECT_TRUE(log->damage().isEmpty()) << qPrintable(log->damage());
        EXPECT_LE(QFileInfo(log->dataFile()).size(), config.maxPartBytes);
        total += log->count();
        logs.push_back(log);
    }
    EXPECT_EQ(total, 3000);
    // Merged by time (the parts given out of order), they are the recorded sequence again.
    std::reverse(logs.begin(), logs.end());
    const log::LogSet merged(logs);
    ASSERT_EQ(merged.count(), 3000);
    for (qsizetype k = 0; k < merged.count(); ++k)
        ASSERT_EQ(merged.packet(k).toByteArray(), packets[size_t(k)]) << "packet " << k;

    // By time: a part every 300 ms of recording.
    QTemporaryDir timed;
    config = configIn(timed.path());
    config.maxPartMs = 300;
    log::Recorder recorder(config);
    ASSERT_TRUE(recorder.start().has_value());
    for (int i = 0; i < 10; ++i) {
        for (int j = 0; j < 100; ++j)
            recorder.record(packets[size_t(i * 100 + j)]);
        QThread::msleep(100);
    }
    recorder.stop();
    const QStringList timedParts = partsIn(timed.path());
    EXPECT_GE(timedParts.size(), 3);
    EXPECT_LE(timedParts.size(), 5);
    qsizetype timedTotal = 0;
    for (const QString &part : timedParts)
        timedTotal += openLog(part)->count();
    EXPECT_EQ(timedTotal, 1000);
}

namespace {

struct Child
{
    QProcess process;
    QStringList lines;

    void start(const QStringList &arguments)
    {
        process.setProgram(test::programPath(QStringLiteral("log-child")));
        process.setArguments(arguments);
        process.start();
        ASSERT_TRUE(process.waitForStarted());
    }
    // The latest "status" line's fields, reading what is there.
    QStringList lastStatus()
    {
        process.waitForReadyRead(50);
        while (process.canReadLine())
            lines.append(QString::fromUtf8(process.readLine()).trimmed());
        for (auto it = lines.crbegin(); it != lines.crend(); ++it) {
            if (it->startsWith(QStringLiteral("status ")) || it->startsWith(QStringLiteral("done ")))
                return it->split(u' ');
        }
        return {};
    }
};

} // namespace

TEST(Log, AKilledRecorderLosesAtMostTheLastSecondAndItsLogOpens)
{
    QTemporaryDir root;
    auto *random = QRandomGenerator::global();
    for (int round = 0; round < 5; ++round) {
        const QString folder = QDir(root.path()).filePath(QString::number(round));
        Child child;
        child.start({folder, QStringLiteral("20000"), QStringLiteral("30")});
        // Killed at a random moment once it records (on a busy machine starting
        // can take longer than the shortest wait: nothing was written yet).
        QElapsedTimer starting;
        starting.start();
        while (child.lastStatus().value(2).toLongLong() == 0 && starting.elapsed() < 20000) {
        }
        ASSERT_GT(child.lastStatus().value(2).toLongLong(), 0) << "round " << round << ": the recorder wrote nothing in 20 s";
        QThread::msleep(random->bounded(1200));
        const double killedAt = QDateTime::currentMSecsSinceEpoch() / 1000.0;
        child.process.kill(); // SIGKILL
        child.process.waitForFinished();
        const QStringList parts = partsIn(folder);
        ASSERT_EQ(parts.size(), 1) << "round " << round;
        auto log = log::LogFile::open(parts.front());
        ASSERT_TRUE(log.has_value()) << qPrintable(log.error());
        ASSERT_GT((*log)->count(), 0) << "round " << round;
        // A cut last packet is the only damage a kill may leave.
        if (!(*log)->damage().isEmpty()) {
            EXPECT_TRUE((*log)->damage().contains(QStringLiteral("cut at byte"))) << qPrintable((*log)->damage());
        }
        const double lastRecorded = (*log)->time((*log)->count() - 1);
        EXPECT_GE(lastRecorded, killedAt - 1.0) << "round " << round << ": lost " << killedAt - lastRecorded << " s";
        // Every packet there decodes.
        for (qsizetype i = 0; i < (*log)->count(); i += 101)
            ASSERT_TRUE((*log)->decode(i).has_value());
    }
}

TEST(Log, AFullDiskRaisesAProblemLosesOnlyWhatDidNotFitAndRecordingCarriesOn)
{
    // A real full filesystem (ENOSPC): the sandbox's small disk for the recorder, filled but
    // 300 kB before recording starts, and freed half a second after the recorder says so.
    const QString disk = test::smallDisk(QStringLiteral("recorder"));
    if (disk.isEmpty())
        GTEST_SKIP() << neptus::test::noSmallDisk;
    QTemporaryDir root(disk + QStringLiteral("/log-XXXXXX"));
    ASSERT_TRUE(root.isValid());
    test::DiskFiller filler(disk);
    ASSERT_LE(filler.fill(300'000), 310'000);
    Child child;
    // (1000 packets a second, about 100 kB: the 2 MiB disk holds the whole run once freed.)
    child.start({root.path(), QStringLiteral("1000"), QStringLiteral("4")});
    bool sawProblem = false;
    QString problem;
    QElapsedTimer since;
    qint64 writtenWhenFreed = -1;
    while (child.process.state() != QProcess::NotRunning) {
        const QStringList status = child.lastStatus();
        if (status.size() > 4 && status[0] == QStringLiteral("status") && status[4] != QStringLiteral("-")
            && !sawProblem) {
            sawProblem = true;
            problem = status.mid(4).join(u' ');
            since.start();
        }
        if (sawProblem && since.isValid() && since.elapsed() > 500) {
            filler.free(); // room again
            since.invalidate();
            writtenWhenFreed = child.lastStatus().value(2).toLongLong();
        }
    }
    child.process.waitForFinished();
    while (child.process.canReadLine())
        child.lines.append(QString::fromUtf8(child.process.readLine()).trimmed());
    ASSERT_TRUE(sawProblem) << qPrintable(child.lines.join(u'\n'));
    EXPECT_TRUE(problem.contains(QStringLiteral("cannot write the log"))) << qPrintable(problem);
    EXPECT_TRUE(problem.contains(QStringLiteral("No space left on device"))) << qPrintable(problem);
    const QStringList done = child.lastStatus();
    ASSERT_EQ(done.value(0), QStringLiteral("done")) << qPrintable(child.lines.join(u'\n'));
    const qint64 sent = done[1].toLongLong(), written = done[2].toLongLong(), lost = done[3].toLongLong();
    EXPECT_EQ(written + lost, sent);
    EXPECT_GT(lost, 0);
    EXPECT_EQ(done.value(4), QStringLiteral("-")) << "recording did not recover once there was room: " << qPrintable(child.lines.mid(child.lines.size() - 5).join(u'\n'));
    // The log is whole: what was written, every packet readable, the lost stretch a gap in time.
    const QStringList parts = partsIn(root.path());
    ASSERT_EQ(parts.size(), 1);
    auto log = openLog(parts.front());
    ASSERT_TRUE(log);
    EXPECT_TRUE(log->damage().isEmpty()) << qPrintable(log->damage());
    EXPECT_EQ(log->count(), written);
    EXPECT_GT(written, writtenWhenFreed + 500) << "nothing written after the disk had room again";
}

namespace {

// A console's tree, its values: without the message rates, which measure
// arrivals over the last second (a seek has none to measure until it plays
// on), and without empty nodes (the fields of an inline message of another
// type, seen earlier, that the tree keeps as structure).
QStringList treeValues(session::Console &console)
{
    static const QRegularExpression rate(QStringLiteral(R"((\s·\s)?[0-9.]+/s\t)"));
    QStringList values;
    for (QString line : console.dumpTree().split(u'\n')) {
        line.replace(rate, QStringLiteral("\t"));
        if (line.section(u'\t', 1, 1).isEmpty())
            continue;
        values.append(line);
    }
    return values;
}

// The lines of one console's tree that the other's lacks, first few.
QString treeDifference(session::Console &a, session::Console &b)
{
    const QStringList linesA = treeValues(a);
    const QStringList linesB = treeValues(b);
    const QSet<QString> setA(linesA.begin(), linesA.end()), setB(linesB.begin(), linesB.end());
    QStringList only;
    for (const QString &line : setA - setB)
        only.append(QStringLiteral("seek only: ") + line);
    for (const QString &line : setB - setA)
        only.append(QStringLiteral("replay only: ") + line);
    only.sort();
    return only.mid(0, 12).join(u'\n') + (only.size() > 12 ? QStringLiteral("\n… %1 in all").arg(only.size()) : QString());
}

} // namespace

TEST(Log, SeekingGivesTheStateAFullReplayStoppedThereGives)
{
    NEPTUS_REQUIRE_FIXTURE(folder, "dune-log");
    auto log = openLog(folder);
    ASSERT_TRUE(log);
    const auto logs = std::make_shared<const log::LogSet>(std::vector{log});
    const auto schema = std::shared_ptr<const msg::Schema>(log->sharedSchemas(), &log->schemas().defaultSchema());

    ManualClock playedClock, seekedClock;
    session::Console played(schema, &playedClock), seeked(schema, &seekedClock);
    session::ConsoleReplay playedTarget(played, playedClock), seekedTarget(seeked, seekedClock);
    log::Player full(logs, &playedTarget), jumping(logs, &seekedTarget);
    EXPECT_TRUE(played.replaying());
    EXPECT_FALSE(played.send(0x00D1, msg::Message(schema->byAbbrev(u"Abort"))).has_value()) << "a replay sent a command";

    // Forward through the log; the seeking console jumps there, back and forth.
    const double begin = logs->begin();
    for (const double at : {35.0, 71.5, 100.25, 137.9}) {
        full.advanceTo(begin + at);
        jumping.seek(begin + 137.9);
        jumping.seek(begin + 1.0);
        jumping.seek(begin + at);
        const QString difference = treeDifference(seeked, played);
        ASSERT_TRUE(difference.isEmpty()) << "at " << at << " s:\n" << qPrintable(difference);
        EXPECT_EQ(seekedClock.now(), playedClock.now());
    }
    EXPECT_EQ(full.decodeErrors(), 0);
    // The vehicle's plan at the end, read from the tree as a console shows it.
    EXPECT_TRUE(played.dumpTree().contains(QStringLiteral("PlanControlState/plan_id\tgoto-and-wait")))
        << qPrintable(played.dumpTree().left(2000));
}

TEST(Log, ExportsOfTheDuneLogReadBackInTheirFormats)
{
    NEPTUS_REQUIRE_FIXTURE(folder, "dune-log");
    auto log = openLog(folder);
    ASSERT_TRUE(log);
    const log::LogSet logs(std::vector{log});
    QTemporaryDir out;
    const QDir dir(out.path());

    int progressCalls = 0;
    double lastProgress = 0;
    auto csv = log::exportCsv(logs, dir.filePath(QStringLiteral("csv")), [&](double f) {
        EXPECT_GE(f, lastProgress);
        lastProgress = f;
        ++progressCalls;
        return true;
    });
    ASSERT_TRUE(csv.has_value()) << qPrintable(csv.error());
    EXPECT_EQ(csv->size(), 61);
    EXPECT_GT(progressCalls, 50);
    EXPECT_DOUBLE_EQ(lastProgress, 1.0);
    QFile states(dir.filePath(QStringLiteral("csv/EstimatedState.csv")));
    ASSERT_TRUE(states.open(QIODevice::ReadOnly));
    const QList<QByteArray> rows = states.readAll().trimmed().split('\n');
    ASSERT_EQ(rows.size(), 1 + 2755);
    const QList<QByteArray> header = rows.front().split(',');
    EXPECT_EQ(header.value(0), "time");
    EXPECT_EQ(header.value(21), "depth (m)");
    for (const QByteArray &row : rows.mid(1)) {
        const QList<QByteArray> cells = row.split(',');
        ASSERT_EQ(cells.size(), header.size()) << row.constData();
        bool ok = false;
        cells[21].toDouble(&ok);
        ASSERT_TRUE(ok) << row.constData();
    }
    // Text with commas is quoted: the LogBookEntry texts.
    QFile book(dir.filePath(QStringLiteral("csv/LogBookEntry.csv")));
    ASSERT_TRUE(book.open(QIODevice::ReadOnly));
    EXPECT_EQ(book.readAll().trimmed().split('\n').size(), 1 + 16);

    // GeoJSON: one LineString for the vehicle, as many points as times, near Porto.
    ASSERT_TRUE(log::exportTracks(logs, log::TrackFormat::GeoJson, dir.filePath(QStringLiteral("t.geojson"))).has_value());
    QFile geojson(dir.filePath(QStringLiteral("t.geojson")));
    ASSERT_TRUE(geojson.open(QIODevice::ReadOnly));
    QJsonParseError error{};
    const QJsonObject collection = QJsonDocument::fromJson(geojson.readAll(), &error).object();
    ASSERT_EQ(error.error, QJsonParseError::NoError);
    EXPECT_EQ(collection.value(u"type").toString(), QStringLiteral("FeatureCollection"));
    const QJsonArray features = collection.value(u"features").toArray();
    ASSERT_EQ(features.size(), 1);
    const QJsonObject feature = features[0].toObject();
    EXPECT_EQ(feature.value(u"properties").toObject().value(u"system").toString(), QStringLiteral("lauv-simulator-1"));
    const QJsonArray coordinates = feature.value(u"geometry").toObject().value(u"coordinates").toArray();
    EXPECT_EQ(coordinates.size(), 2755);
    EXPECT_EQ(feature.value(u"properties").toObject().value(u"times").toArray().size(), coordinates.size());
    EXPECT_NEAR(coordinates[0].toArray()[0].toDouble(), -8.7062, 0.01);
    EXPECT_NEAR(coordinates[0].toArray()[1].toDouble(), 41.185, 0.01);

    // KML and GPX: XML in their namespaces with the same points.
    for (const auto &[format, name, namespaceUri] :
         {std::tuple{log::TrackFormat::Kml, QStringLiteral("t.kml"), QStringLiteral("http://www.opengis.net/kml/2.2")},
          std::tuple{log::TrackFormat::Gpx, QStringLiteral("t.gpx"), QStringLiteral("http://www.topografix.com/GPX/1/1")}}) {
        ASSERT_TRUE(log::exportTracks(logs, format, dir.filePath(name)).has_value());
        const auto contents = test::readTrackFile(dir.filePath(name));
        EXPECT_TRUE(contents.error.isEmpty()) << qPrintable(contents.error);
        EXPECT_EQ(contents.rootNamespace, namespaceUri);
        EXPECT_EQ(contents.points, 2755) << qPrintable(name);
    }
}

// The track exports against the schemas users' tools follow: GPX 1.1 as
// TopoGrafix publishes it and OGC KML 2.2 with its Atom and OASIS xAL imports,
// unmodified, from ../shared/fixtures/schemas (not our reading of the standards).
TEST(Log, TrackExportsPassTheOfficialGpxAndKmlSchemas)
{
    NEPTUS_REQUIRE_FIXTURE(folder, "dune-log");
    NEPTUS_REQUIRE_FIXTURE(schemas, "schemas");
    // ogckml22.xsd imports xAL by its absolute URL: the test's entity loader
    // gives libxml2 the copy beside it for that URL (nothing is fetched).
    static QByteArray xal;
    xal = QDir(schemas).filePath(u"kml-2.2/xAL.xsd"_s).toUtf8();
    static xmlExternalEntityLoader previous = xmlGetExternalEntityLoader();
    xmlSetExternalEntityLoader([](const char *url, const char *id, xmlParserCtxtPtr context) -> xmlParserInputPtr {
        if (url && QByteArrayView(url) == "http://docs.oasis-open.org/election/external/xAL.xsd")
            return xmlNewInputFromFile(context, xal.constData());
        return previous(url, id, context);
    });
    const auto restore = qScopeGuard([] { xmlSetExternalEntityLoader(previous); });

    auto log = openLog(folder);
    ASSERT_TRUE(log);
    const log::LogSet logs(std::vector{log});
    QTemporaryDir out;
    const QDir dir(out.path());
    for (const auto &[format, name, schema, bad] :
         {std::tuple{log::TrackFormat::Gpx, u"t.gpx"_s, u"gpx-1.1/gpx.xsd"_s,
                     QByteArray(R"(<gpx xmlns="http://www.topografix.com/GPX/1/1" version="1.1" creator="t"><trk><trkseg><trkpt lat="91" lon="0"/></trkseg></trk></gpx>)")},
          std::tuple{log::TrackFormat::Kml, u"t.kml"_s, u"kml-2.2/ogckml22.xsd"_s,
                     QByteArray(R"(<kml xmlns="http://www.opengis.net/kml/2.2"><Document><Placemark><LineString><coordinates>0,0</coordinates><altitudeMode>underwater</altitudeMode></LineString></Placemark></Document></kml>)")}}) {
        const auto official = xml::XmlSchema::load(QDir(schemas).filePath(schema));
        ASSERT_TRUE(official.has_value()) << qPrintable(schema) << ": " << official.error().toString().toStdString();
        ASSERT_TRUE(log::exportTracks(logs, format, dir.filePath(name)).has_value());
        const auto document = xml::XmlDocument::load(dir.filePath(name));
        ASSERT_TRUE(document.has_value());
        for (const xml::XmlError &problem : official->validate(*document))
            ADD_FAILURE() << qPrintable(name) << ": " << problem.toString().toStdString();
        // The schema bites: a latitude out of range; an altitude mode KML has not.
        const auto wrong = xml::XmlDocument::parse(QByteArrayView(bad), u"bad"_s);
        ASSERT_TRUE(wrong.has_value());
        EXPECT_FALSE(official->validate(*wrong).isEmpty()) << bad.constData();
    }
}

TEST(Log, ASliceHoldsItsTimeRangeAndTwoSlicesMergeIntoTheWhole)
{
    NEPTUS_REQUIRE_FIXTURE(folder, "dune-log");
    auto log = openLog(folder);
    ASSERT_TRUE(log);
    const log::LogSet logs(std::vector{log});
    QTemporaryDir out;
    const QDir dir(out.path());
    const double middle = logs.begin() + 60;
    auto first = log::writeLog(logs, logs.begin(), middle, dir.filePath(QStringLiteral("a")));
    auto second = log::writeLog(logs, std::nextafter(middle, INFINITY), logs.end(), dir.filePath(QStringLiteral("b")));
    ASSERT_TRUE(first.has_value()) << qPrintable(first.error());
    ASSERT_TRUE(second.has_value()) << qPrintable(second.error());
    EXPECT_EQ(*first, logs.upperBound(middle));
    EXPECT_EQ(*first + *second, log->count());
    auto a = openLog(dir.filePath(QStringLiteral("a")));
    auto b = openLog(dir.filePath(QStringLiteral("b")));
    ASSERT_TRUE(a && b);
    EXPECT_TRUE(a->indexReused());
    EXPECT_LE(a->end(), middle);
    EXPECT_GT(b->begin(), middle);
    // Merged again (given in either order), the packets are the original's, in its order.
    const log::LogSet merged(std::vector{b, a});
    auto whole = log::writeLog(merged, merged.begin(), merged.end(), dir.filePath(QStringLiteral("whole")));
    ASSERT_TRUE(whole.has_value());
    auto again = openLog(dir.filePath(QStringLiteral("whole")));
    ASSERT_EQ(again->count(), log->count());
    for (qsizetype i = 0; i < again->count(); i += 7)
        ASSERT_EQ(again->packet(i).toByteArray(), log->packet(i).toByteArray()) << "packet " << i;
    // Not into a folder that holds something.
    auto refused = log::writeLog(logs, logs.begin(), logs.end(), dir.filePath(QStringLiteral("a")));
    ASSERT_FALSE(refused.has_value());
    EXPECT_TRUE(refused.error().contains(QStringLiteral("not empty"))) << qPrintable(refused.error());
}

TEST(Log, TheTimelineMarksTheDuneLogsPlanItsLogBookAndNothingElse)
{
    NEPTUS_REQUIRE_FIXTURE(folder, "dune-log");
    auto log = openLog(folder);
    ASSERT_TRUE(log);
    const log::LogSet logs(std::vector{log});
    const auto plans = log::planEvents(logs);
    const auto markers = log::markersOf(logs, plans);
    std::vector<log::LogMarker> starts, ends, notes;
    for (const auto &m : markers) {
        (m.kind == log::LogMarker::PlanStart ? starts : m.kind == log::LogMarker::PlanEnd ? ends : notes).push_back(m);
        EXPECT_GE(m.time, logs.begin());
        EXPECT_LE(m.time, logs.end());
    }
    ASSERT_EQ(starts.size(), 1u);
    // DUNE opens the log as the plan starts: its first state already says EXECUTING.
    EXPECT_EQ(starts[0].text, QStringLiteral("lauv-simulator-1: plan goto-and-wait running as the log begins"));
    EXPECT_NEAR(starts[0].time - logs.begin(), 0, 0.5);
    // DUNE closes the log as the plan ends: after its last reply ("plan completed"), before a
    // state says so. The log cannot say how the plan ended; it says what the vehicle said last.
    ASSERT_EQ(ends.size(), 1u) << qPrintable(ends.empty() ? QString() : ends[0].text);
    EXPECT_EQ(ends[0].text, QStringLiteral("lauv-simulator-1: plan goto-and-wait running when the log ends (last said: plan completed)"))
        << qPrintable(ends[0].text);
    EXPECT_NEAR(ends[0].time - logs.begin(), 137.8, 0.5);
    // The same run in the review's plan list and the exports (one tracker: plans::PlanRuns).
    const auto runs = log::planRuns(logs, plans, log::tracks(logs));
    ASSERT_EQ(runs.size(), 1u);
    EXPECT_EQ(runs[0].plan, QStringLiteral("goto-and-wait"));
    EXPECT_EQ(runs[0].outcome, QStringLiteral("still running"));
    EXPECT_EQ(runs[0].reason, QStringLiteral("plan completed"));
    EXPECT_DOUBLE_EQ(runs[0].begin, starts[0].time);
    EXPECT_DOUBLE_EQ(runs[0].end, ends[0].time);
    EXPECT_GT(runs[0].distance, 100);
    // The log book's 16 entries (none is DEBUG), no entity went to fault.
    int logBook = 0;
    for (const auto &m : notes)
        logBook += m.text.contains(QStringLiteral("lauv-simulator-1 "));
    EXPECT_EQ(logBook, 16);
    EXPECT_TRUE(std::is_sorted(markers.begin(), markers.end(),
                               [](const auto &a, const auto &b) { return a.time < b.time; }));

    // The plan the console sent (PlanControl START with the PlanSpecification, and the PlanDB
    // one), for the vehicle, with its two maneuvers.
    const auto specifications = log::planSpecifications(logs);
    ASSERT_FALSE(specifications.empty());
    for (const auto &[vehicle, specification] : specifications) {
        EXPECT_EQ(vehicle, 0x00D1);
        EXPECT_EQ(specification.text(u"plan_id"), QStringLiteral("goto-and-wait"));
        EXPECT_EQ(specification.messages(specification.def()->indexOf(u"maneuvers")).size(), 2u);
    }
}

TEST(Log, DdsTrafficIsRecordedAsTheImcPacketsItsEnvelopesCarry)
{
    QTemporaryDir root;
    log::Recorder recorder(configIn(root.path()));
    ASSERT_TRUE(recorder.start().has_value());
    const auto schema = test::shippedSchema();
    {
        session::Console console(schema);
        console.setRecorder(&recorder);
        ASSERT_TRUE(console.startDds({23, {}, 0x4001}));
        transport::DdsTransport vehicle(schema, transport::DdsConfig{23, {}, 0x1f});
        ASSERT_TRUE(vehicle.start());
        msg::Message state(schema->byAbbrev(u"EstimatedState"));
        state.setNumber(state.def()->indexOf(u"depth"), 4.25);
        ASSERT_TRUE(QTest::qWaitFor([&] {
            vehicle.broadcast(state);
            return console.tree().find(u"0x001f/EstimatedState/depth") != tree::noNode;
        }, 10000));
        ASSERT_TRUE(console.send(0x1f, msg::Message(schema->byAbbrev(u"Abort"))).has_value());
        QTest::qWait(100);
    }
    recorder.stop();
    auto log = openLog(recorder.status().folder);
    ASSERT_TRUE(log);
    const log::LogSet logs(std::vector{log});
    bool heardState = false, sentAbort = false;
    for (qsizetype k = 0; k < logs.count(); ++k) {
        const auto m = logs.decode(k);
        ASSERT_TRUE(m.has_value());
        if (m->abbrev() == u"EstimatedState" && m->header.src == 0x1f) {
            heardState = true;
            EXPECT_DOUBLE_EQ(m->number(u"depth"), 4.25);
            EXPECT_FALSE(logs.sentByRecorder(k));
        }
        if (m->abbrev() == u"Abort") {
            sentAbort = true;
            EXPECT_EQ(m->header.src, 0x4001);
            EXPECT_EQ(m->header.dst, 0x1f);
            EXPECT_TRUE(logs.sentByRecorder(k));
        }
    }
    EXPECT_TRUE(heardState) << "what the vehicle sent over DDS";
    EXPECT_TRUE(sentAbort) << "what the console sent over DDS";
}

TEST(Log, TheTimelineMarksTheAlarmsTheConsoleItselfRaisesOnTheLog)
{
    // A named vehicle reports for 10 s, falls silent for 30 s, then is heard again: the console's
    // health monitor calls that communications lost, an Error no message in the log carries.
    const auto schema = test::shippedSchema();
    const msg::Codec codec(schema);
    QByteArray data;
    msg::Message announce(schema->byAbbrev(u"Announce"));
    announce.setBytes(announce.def()->indexOf(u"sys_name"), "auv-1");
    msg::Message state(schema->byAbbrev(u"EstimatedState"));
    const double start = 1.7e9;
    for (double t = 0; t < 50; t += 0.1) {
        if (t >= 10 && t < 40)
            continue;
        msg::Message &m = std::fmod(t, 1.0) < 0.05 ? announce : state;
        m.header.src = 0x1f;
        m.header.timestamp = start + t;
        data += *codec.encode(m);
    }
    const auto logs = std::make_shared<const log::LogSet>(
        std::vector{log::LogFile::fromData(data, std::make_shared<msg::SchemaSet>(schema))});
    ManualClock clock;
    session::Console console(schema, &clock);
    session::ConsoleReplay target(console, clock);
    ReplayModel replay(logs, &target);
    const auto alarms = [&] {
        QVariantList found;
        for (const QVariant &m : replay.markers())
            if (m.toMap().value(QStringLiteral("kind")).toString() == u"alarm")
                found.append(m);
        return found;
    };
    ASSERT_TRUE(QTest::qWaitFor([&] { return !alarms().isEmpty(); }, 10000)) << "no alarm marker";
    const QVariantMap first = alarms().front().toMap();
    const double at = first.value(QStringLiteral("time")).toDouble() - start;
    EXPECT_GT(at, 12.0) << qPrintable(first.value(QStringLiteral("text")).toString());
    EXPECT_LT(at, 40.0);
    EXPECT_TRUE(first.value(QStringLiteral("text")).toString().contains(QStringLiteral("auv-1")))
        << qPrintable(first.value(QStringLiteral("text")).toString());
    EXPECT_TRUE(first.value(QStringLiteral("text")).toString().contains(QStringLiteral("communications lost")))
        << qPrintable(first.value(QStringLiteral("text")).toString());
}
