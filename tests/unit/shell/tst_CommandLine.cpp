#include "CommandLine.h"
#include "database/Database.h"

#include <QDir>

#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace {
std::expected<CommandLine, QString> parse(QStringList arguments)
{
    arguments.prepend(QStringLiteral("neptus"));
    return CommandLine::parse(arguments);
}
} // namespace

TEST(CommandLine, DefaultsToTheShippedDefaultConsole)
{
    const auto line = parse({});
    ASSERT_TRUE(line) << line.error().toStdString();
    EXPECT_TRUE(line->consoleFile.endsWith(QStringLiteral("share/neptus-qt/consoles/Default.qml")))
        << line->consoleFile.toStdString() << ": the shipped consoles, found beside the program";
    EXPECT_EQ(line->windowSize, QSize(1280, 800));
    EXPECT_FALSE(line->selfTest);
    EXPECT_TRUE(line->screenshotFile.isEmpty());
}

TEST(CommandLine, ReadsEveryOption)
{
    QTemporaryDir dir;
    const QString console = dir.filePath(QStringLiteral("Mine.qml"));
    QFile file(console);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.close();
    const auto line = parse({QStringLiteral("--console"), console, QStringLiteral("--screenshot"),
                             QStringLiteral("out.png"), QStringLiteral("--palette"), QStringLiteral("Night"),
                             QStringLiteral("--size"), QStringLiteral("1920x1080"), QStringLiteral("--self-test"),
                             QStringLiteral("--imc-port"), QStringLiteral("6010"), QStringLiteral("--imc-peer"),
                             QStringLiteral("127.0.0.1:6002"), QStringLiteral("--components"), dir.path(),
                             QStringLiteral("--edit"), QStringLiteral("--select"), QStringLiteral("depth"),
                             QStringLiteral("--system"), QStringLiteral("lauv-1"), QStringLiteral("--system-id"),
                             QStringLiteral("0x4002")});
    ASSERT_TRUE(line) << line.error().toStdString();
    EXPECT_EQ(line->componentDirectories, QStringList{dir.path()});
    EXPECT_TRUE(line->edit);
    EXPECT_EQ(line->select, QStringLiteral("depth"));
    EXPECT_EQ(line->system, QStringLiteral("lauv-1"));
    EXPECT_EQ(line->consoleFile, console);
    EXPECT_EQ(line->screenshotFile, QStringLiteral("out.png"));
    EXPECT_EQ(line->palette, QStringLiteral("night"));
    EXPECT_EQ(line->windowSize, QSize(1920, 1080));
    EXPECT_TRUE(line->selfTest);
    EXPECT_EQ(line->imcPort, 6010);
    EXPECT_EQ(line->systemId, 0x4002);
    EXPECT_EQ(line->imcPeers, (QList<std::pair<QHostAddress, quint16>>{{QHostAddress(QStringLiteral("127.0.0.1")), 6002}}));
}

TEST(CommandLine, NamesWhatIsWrong)
{
    auto line = parse({QStringLiteral("--console"), QStringLiteral("/nonexistent/Nope.qml")});
    ASSERT_FALSE(line);
    EXPECT_TRUE(line.error().contains(QStringLiteral("/nonexistent/Nope.qml"))) << line.error().toStdString();

    line = parse({QStringLiteral("--ui-scale"), QStringLiteral("1.5")});
    ASSERT_TRUE(line);
    EXPECT_EQ(line->uiScale, 1.5);
    line = parse({QStringLiteral("--ui-scale"), QStringLiteral("5")});
    ASSERT_FALSE(line);
    EXPECT_TRUE(line.error().contains(QStringLiteral("0.75 to 2"))) << line.error().toStdString();
    line = parse({QStringLiteral("--gps"), QStringLiteral("/nonexistent/track.nmea")});
    ASSERT_FALSE(line);
    EXPECT_TRUE(line.error().contains(QStringLiteral("not a readable NMEA file"))) << line.error().toStdString();
    line = parse({QStringLiteral("--gps"), QStringLiteral("socket://192.168.1.20:10110")});
    ASSERT_TRUE(line);
    EXPECT_EQ(line->gps, QStringLiteral("socket://192.168.1.20:10110"));
    line = parse({QStringLiteral("--palette"), QStringLiteral("purple")});
    ASSERT_FALSE(line);
    EXPECT_TRUE(line.error().contains(QStringLiteral("purple")));

    line = parse({QStringLiteral("--size"), QStringLiteral("big")});
    ASSERT_FALSE(line);
    EXPECT_TRUE(line.error().contains(QStringLiteral("1280x800")));

    line = parse({QStringLiteral("--bogus")});
    ASSERT_FALSE(line);
    EXPECT_TRUE(line.error().contains(QStringLiteral("bogus")));

    line = parse({QStringLiteral("--imc-port"), QStringLiteral("70000")});
    ASSERT_FALSE(line);
    EXPECT_TRUE(line.error().contains(QStringLiteral("70000")));

    line = parse({QStringLiteral("--system-id"), QStringLiteral("0x1f")});
    ASSERT_FALSE(line);
    EXPECT_TRUE(line.error().contains(QStringLiteral("0x4000 to 0x5FFF"))) << line.error().toStdString();

    line = parse({QStringLiteral("--imc-peer"), QStringLiteral("nohostport")});
    ASSERT_FALSE(line);
    EXPECT_TRUE(line.error().contains(QStringLiteral("127.0.0.1:6002")));
    // A host name was taken and then became a null address: now said at once.
    line = parse({QStringLiteral("--imc-peer"), QStringLiteral("auv.local:6002")});
    ASSERT_FALSE(line);
    EXPECT_TRUE(line.error().contains(QStringLiteral("auv.local:6002")));

    line = parse({QStringLiteral("--components"), QStringLiteral("/nonexistent/components")});
    ASSERT_FALSE(line);
    EXPECT_TRUE(line.error().contains(QStringLiteral("/nonexistent/components")));

    line = parse({QStringLiteral("--select"), QStringLiteral("depth")});
    ASSERT_FALSE(line);
    EXPECT_TRUE(line.error().contains(QStringLiteral("--edit")));

    line = parse({QStringLiteral("stray")});
    ASSERT_FALSE(line);
    EXPECT_TRUE(line.error().contains(QStringLiteral("stray")));

    line = parse({});
    ASSERT_TRUE(line);
    EXPECT_EQ(line->displayRate, 10.0);
    EXPECT_EQ(line->restingRate, 3.0);
    line = parse({QStringLiteral("--resting-rate"), QStringLiteral("2"), QStringLiteral("--display-rate"), QStringLiteral("20")});
    ASSERT_TRUE(line);
    EXPECT_EQ(line->restingRate, 2.0);
    EXPECT_EQ(line->displayRate, 20.0);
    line = parse({QStringLiteral("--screen-inches"), QStringLiteral("10.1")});
    ASSERT_TRUE(line);
    EXPECT_EQ(line->screenInches, 10.1);
    line = parse({QStringLiteral("--screen-inches"), QStringLiteral("0.5")});
    ASSERT_FALSE(line);
    EXPECT_TRUE(line.error().contains(QStringLiteral("--screen-inches"))) << line.error().toStdString();
    line = parse({QStringLiteral("--resting-rate"), QStringLiteral("slow")});
    ASSERT_FALSE(line);
    EXPECT_TRUE(line.error().contains(QStringLiteral("--resting-rate"))) << line.error().toStdString();
    EXPECT_TRUE(line.error().contains(QStringLiteral("slow"))) << line.error().toStdString();
}

TEST(CommandLine, DefinitionsPerSystemInBothSpellings)
{
    QTemporaryDir dir;
    const QString defs = dir.filePath(QStringLiteral("IMC.xml.gz"));
    QFile file(defs);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.close();
    const auto line = parse({QStringLiteral("--defs-for"), QStringLiteral("0x00d1"), defs, QStringLiteral("--defs-for"),
                             QStringLiteral("lauv-xplore-1=") + defs, QStringLiteral("--defs"), defs,
                             QStringLiteral("--imc-discovery"), QStringLiteral("off"), QStringLiteral("--dump-tree"),
                             QStringLiteral("tree.txt"), QStringLiteral("--quit-after"), QStringLiteral("5000")});
    ASSERT_TRUE(line) << line.error().toStdString();
    ASSERT_EQ(line->definitionsFor.size(), 2);
    EXPECT_EQ(line->definitionsFor[0], std::pair(QStringLiteral("0x00d1"), defs));
    EXPECT_EQ(line->definitionsFor[1], std::pair(QStringLiteral("lauv-xplore-1"), defs));
    EXPECT_EQ(line->definitionFiles, QStringList{defs});
    EXPECT_FALSE(line->imcDiscovery);
    EXPECT_EQ(line->dumpTreeFile, QStringLiteral("tree.txt"));
    EXPECT_EQ(line->quitAfterMs, 5000);
    EXPECT_TRUE(parse({})->imcDiscovery) << "on by default";

    const auto missing = parse({QStringLiteral("--defs-for"), QStringLiteral("0x00d1"), dir.filePath(QStringLiteral("no.xml"))});
    ASSERT_FALSE(missing);
    EXPECT_TRUE(missing.error().contains(QStringLiteral("no.xml"))) << missing.error().toStdString();
    const auto shapeless = parse({QStringLiteral("--defs-for"), QStringLiteral("0x00d1")});
    ASSERT_FALSE(shapeless);
    EXPECT_TRUE(shapeless.error().contains(QStringLiteral("--defs-for"))) << shapeless.error().toStdString();
    EXPECT_FALSE(parse({QStringLiteral("--imc-discovery"), QStringLiteral("maybe")}));
    EXPECT_FALSE(parse({QStringLiteral("--quit-after"), QStringLiteral("-1")}));
    EXPECT_EQ(parse({})->forgetAfterSeconds, 0) << "never, unless told";
    EXPECT_EQ(parse({QStringLiteral("--forget-after"), QStringLiteral("7200")})->forgetAfterSeconds, 7200);
    const auto forget = parse({QStringLiteral("--forget-after"), QStringLiteral("soon")});
    ASSERT_FALSE(forget);
    EXPECT_TRUE(forget.error().contains(QStringLiteral("--forget-after"))) << forget.error().toStdString();
    EXPECT_FALSE(parse({QStringLiteral("--forget-after"), QStringLiteral("0")}));
}

TEST(CommandLine, ImcBindTakesAnAddressOrAnInterfaceOfThisMachine)
{
    EXPECT_TRUE(parse({})->imcBind.isEmpty()) << "loopback unless told";
    auto line = parse({QStringLiteral("--imc-bind"), QStringLiteral("lo")});
    ASSERT_TRUE(line) << line.error().toStdString();
    EXPECT_EQ(line->imcBind, QStringLiteral("127.0.0.1")) << "an interface by name";
    line = parse({QStringLiteral("--imc-bind"), QStringLiteral("127.0.0.1")});
    ASSERT_TRUE(line) << line.error().toStdString();
    EXPECT_EQ(line->imcBind, QStringLiteral("127.0.0.1"));
    line = parse({QStringLiteral("--imc-bind"), QStringLiteral("192.0.2.77")});
    ASSERT_FALSE(line);
    EXPECT_TRUE(line.error().contains(QStringLiteral("'192.0.2.77' is no IPv4 address or interface of this machine")))
        << line.error().toStdString();
    EXPECT_TRUE(line.error().contains(QStringLiteral("127.0.0.1 (lo)"))) << "and says what there is";
}

TEST(CommandLine, RecordingAndReplayOptions)
{
    QTemporaryDir dir;
    auto line = parse({});
    ASSERT_TRUE(line);
    EXPECT_TRUE(line->record) << "recording is on by default";
    EXPECT_TRUE(line->replayLogs.isEmpty());
    line = parse({QStringLiteral("--no-record"), QStringLiteral("--log-dir"), dir.path()});
    ASSERT_TRUE(line) << line.error().toStdString();
    EXPECT_FALSE(line->record);
    EXPECT_EQ(line->logDirectory, dir.path());
    line = parse({QStringLiteral("--replay"), dir.path(), QStringLiteral("--replay"), dir.path(),
                  QStringLiteral("--replay-from"), QStringLiteral("71.5"), QStringLiteral("--replay-play")});
    ASSERT_TRUE(line) << line.error().toStdString();
    EXPECT_EQ(line->replayLogs.size(), 2);
    EXPECT_DOUBLE_EQ(line->replayFrom, 71.5);
    EXPECT_TRUE(line->replayPlay);
    for (const auto &[arguments, expected] :
         {std::pair{QStringList{QStringLiteral("--replay"), QStringLiteral("/no/such/log")}, "--replay: '/no/such/log' does not exist"},
          std::pair{QStringList{QStringLiteral("--replay-from"), QStringLiteral("3")}, "go with --replay LOG"},
          std::pair{QStringList{QStringLiteral("--replay"), dir.path(), QStringLiteral("--replay-from"), QStringLiteral("-3")},
                    "--replay-from must be seconds"}}) {
        const auto refused = parse(arguments);
        ASSERT_FALSE(refused.has_value()) << arguments.join(u' ').toStdString();
        EXPECT_TRUE(refused.error().contains(QString::fromUtf8(expected))) << refused.error().toStdString();
    }
}

TEST(CommandLine, ReplaySessionFindsTheLogsASessionRecordedInTheOperationsDatabase)
{
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("operation.db"));
    const QString logA = dir.filePath(QStringLiteral("20261124/120000-ops-a")), logB = dir.filePath(QStringLiteral("20261124/130000-ops-a"));
    QDir().mkpath(logA);
    QDir().mkpath(logB);
    QString session;
    {
        neptus::db::Writer::Options options;
        options.console = QStringLiteral("ops-a");
        neptus::db::Writer writer(*neptus::db::Location::parse(file), options);
        session = writer.session();
        writer.write(neptus::db::Row{neptus::db::Table::Log, {logA, 1000, 2000, 10, 100}});
        writer.write(neptus::db::Row{neptus::db::Table::Log, {logB, 3000, 4000, 10, 100}});
        ASSERT_TRUE(writer.flush());
    }
    for (const QString &wanted : {QStringLiteral("ops-a"), session.left(8)}) {
        const auto line = parse({QStringLiteral("--database"), file, QStringLiteral("--replay-session"), wanted});
        ASSERT_TRUE(line.has_value()) << line.error().toStdString();
        EXPECT_EQ(line->replayLogs, (QStringList{logA, logB})) << wanted.toStdString();
    }
    const auto unknown = parse({QStringLiteral("--database"), file, QStringLiteral("--replay-session"), QStringLiteral("ops-z")});
    ASSERT_FALSE(unknown.has_value());
    EXPECT_NE(unknown.error().indexOf(QStringLiteral("no session 'ops-z'")), -1) << unknown.error().toStdString();
    const auto noDatabase = parse({QStringLiteral("--database"), dir.filePath(QStringLiteral("none.db")), QStringLiteral("--replay-session"),
                                   QStringLiteral("ops-a")});
    ASSERT_FALSE(noDatabase.has_value());
    EXPECT_NE(noDatabase.error().indexOf(QStringLiteral("no database at")), -1);
}
