// Two consoles planning together: the console program shares its mission
// over DDS (--share); a second console (this test, a session::Console with
// its DDS link and a MissionShare, as the console program has them) joins,
// gets the whole mission from the first, then edits it: the console program
// shows the change (its plan desk has it, and its mission file, with who
// made it) within seconds. On loopback only, a DDS domain of its own.
#include "Paths.h"
#include "mission/MissionXml.h"
#include "plans/MissionShare.h"
#include "session/Console.h"

#include "Schemas.h"

#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

using namespace neptus;
using namespace Qt::StringLiterals;

TEST(SharedMission, OneConsoleEditsASharedMissionTheOtherShowsTheChange)
{
    QTemporaryDir dir;
    const QString file = dir.filePath(u"leixoes.xml"_s), shot = dir.filePath(u"console-a.png"_s);
    ASSERT_TRUE(QFile::copy(test::sourcePath(u"docs/examples/leixoes.xml"_s), file));
    QFile::setPermissions(file, QFile::ReadOwner | QFile::WriteOwner);

    // Console A: the program, sharing its mission; it draws itself after 14 s and exits.
    QProcess a;
    a.setProcessChannelMode(QProcess::MergedChannels);
    a.start(test::programPath(u"neptus"_s),
            {u"--mission"_s, file, u"--share"_s, u"--console-name"_s, u"console-a"_s, u"--dds-domain"_s, u"21"_s,
             u"--imc-discovery"_s, u"off"_s, u"--imc-port"_s, u"0"_s, u"--no-record"_s, u"--screenshot"_s, shot, u"--screenshot-delay"_s, u"14000"_s});
    ASSERT_TRUE(a.waitForStarted(5000));
    const auto output = [&] { return a.readAll().toStdString(); };

    // Console B: joins with no mission of its own.
    session::Console b(test::shippedSchema());
    transport::DdsConfig config{21, {}, 0x4002, u"console-b"_s};
    ASSERT_TRUE(b.startDds(config).has_value());
    plans::MissionShare share(b.sharedSchema(), u"console-b"_s, [&](const msg::Message &m) { return b.broadcast(m); });
    QObject::connect(&b, &session::Console::sharedMissionReceived, &share, &plans::MissionShare::receive);
    ASSERT_TRUE(share.start({}).has_value());
    ASSERT_TRUE(QTest::qWaitFor([&] { return share.mission().plans.size() == 3 && !share.mission().maps.isEmpty(); }, 20000))
        << "B got A's mission: " << output();
    EXPECT_EQ(share.mission().id, u"leixoes"_s);
    EXPECT_EQ(share.authorOf(u"plan:survey"_s), u"console-a"_s);

    // B adds a mark and moves the survey's first maneuver.
    mission::Mission edited = share.mission();
    mission::Feature mark;
    mark.kind = u"mark"_s;
    mark.id = u"buoy-b"_s;
    mark.name = u"Buoy from B"_s;
    mark.position.lat = 41.1420;
    mark.position.lon = -8.6100;
    edited.maps[0].features.append(mark);
    edited.plans[0].maneuvers[0].set(u"lat"_s, 41.1419);
    share.update(edited);

    // A has it: its mission file (written by its plan desk on every change) holds both.
    ASSERT_TRUE(QTest::qWaitFor([&] {
        QFile f(file);
        return f.open(QIODevice::ReadOnly) && f.readAll().contains("id=\"buoy-b\"");
    }, 10000)) << output();
    const auto mission = mission::loadMission(file);
    ASSERT_TRUE(mission.has_value());
    EXPECT_DOUBLE_EQ(mission->plans[0].maneuvers[0].number(u"lat"_s), 41.1419);
    EXPECT_TRUE(QFile::exists(file + u".bak"_s)) << "the previous file kept";

    ASSERT_TRUE(a.waitForFinished(30000));
    const std::string said = output();
    EXPECT_EQ(a.exitCode(), 0) << said;
    EXPECT_NE(said.find("sharing the mission as console-a"), std::string::npos) << said;
    EXPECT_TRUE(QFile::exists(shot)) << said;
    // For a look: the console with B's mark on its map.
    if (const QString keep = qEnvironmentVariable("NEPTUS_KEEP_SHOTS"); !keep.isEmpty())
        QFile::copy(shot, keep + u"/shared-mission-console-a.png"_s);
}
