#include "mission/MissionXml.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include "Missions.h"
#include "SmallDisk.h"

#include <gtest/gtest.h>

using namespace neptus::mission;
using neptus::test::everything;
using namespace Qt::StringLiterals;
using neptus::test::errorsText;

namespace {

std::expected<Mission, Errors> read(const QByteArray &text)
{
    return readMission(text, u"test.xml"_s);
}

// The plan of `everything` with its maneuvers replaced.
QByteArray withManeuvers(const char *maneuvers, const char *transitions = "")
{
    return QByteArray(R"X(<mission format="1" id="m"><home lat="0" lon="0"/><vehicle id="v"/>
<plan id="p" vehicle="v" start="a">
<maneuvers>)X") + maneuvers + "</maneuvers>" + transitions + "</plan></mission>";
}

} // namespace

TEST(MissionXml, ReadsEveryElement)
{
    const auto mission = read(everything);
    ASSERT_TRUE(mission) << errorsText(mission.error()).toStdString();
    EXPECT_EQ(mission->id, u"harbour"_s);
    EXPECT_DOUBLE_EQ(mission->home.lat, 41.185);
    EXPECT_EQ(mission->vehicles, (QStringList{u"lauv-xplore-1"_s, u"x8-02"_s}));
    ASSERT_EQ(mission->maps.size(), 1);
    EXPECT_EQ(mission->maps[0].features.size(), 11);
    const Feature &transponder = mission->maps[0].features[1];
    EXPECT_EQ(transponder.kind, u"transponder"_s);
    EXPECT_EQ(transponder.position.north, 100.0);
    EXPECT_EQ(transponder.position.depth, 10.0);
    EXPECT_EQ(transponder.attributes.value(u"config"_s), u"lsts3.conf"_s);
    EXPECT_EQ(mission->maps[0].features[3].points.size(), 3);
    EXPECT_EQ(mission->maps[0].features[8].points.size(), 2); // image corners

    ASSERT_EQ(mission->plans.size(), 1);
    const Plan &plan = mission->plans[0];
    EXPECT_EQ(plan.maneuvers.size(), 15);
    EXPECT_EQ(plan.transitions.size(), 2);
    EXPECT_EQ(plan.transitions[1].condition, u"ManeuverIsDone"_s); // the default
    ASSERT_EQ(plan.transitions[1].actions.size(), 1);
    EXPECT_EQ(plan.transitions[1].actions[0].name, u"PlanControl"_s);
    ASSERT_EQ(plan.startActions.size(), 1);
    EXPECT_EQ(plan.startActions[0].children[0].text, u"Sidescan"_s);
    ASSERT_EQ(plan.variables.size(), 1);
    EXPECT_EQ(plan.variables[0].name, u"target_depth"_s);
    EXPECT_EQ(plan.variables[0].value, u"5"_s);
    EXPECT_TRUE(plan.variables[0].type.isEmpty());
    const Maneuver *rows = plan.maneuver(u"rows"_s);
    ASSERT_TRUE(rows);
    EXPECT_EQ(rows->number(u"hstep"_s), 10.0);
    EXPECT_EQ(rows->text(u"flags"_s), u"SQUARE_CURVE"_s);
    EXPECT_EQ(plan.maneuver(u"traj"_s)->points[1].t, 30.0);
    EXPECT_EQ(plan.maneuvers[0].line.value, 29);

    ASSERT_EQ(mission->checklists.size(), 1);
    const ChecklistItem &battery = mission->checklists[0].groups[0].items[0];
    EXPECT_EQ(battery.variable, u"lauv-xplore-1/FuelLevel/value"_s);
    EXPECT_EQ(battery.min, 80.0);
    EXPECT_TRUE(mission->checklists[0].groups[0].items[1].checked);
}

TEST(MissionXml, WriteReadWriteIsAFixpoint)
{
    const auto mission = read(everything);
    ASSERT_TRUE(mission);
    const QByteArray first = writeMission(*mission);
    const auto again = read(first);
    ASSERT_TRUE(again) << errorsText(again.error()).toStdString() << "\n" << first.constData();
    EXPECT_EQ(*again, *mission);
    EXPECT_EQ(writeMission(*again), first);
}

TEST(MissionXml, AMissionMadeInCodeIsValid)
{
    Mission mission;
    mission.id = u"made"_s;
    mission.home = {38.5, -28.6, 0};
    mission.vehicles = {u"auv"_s};
    Plan plan;
    plan.id = u"p"_s;
    plan.vehicle = u"auv"_s;
    plan.start = u"a"_s;
    Maneuver a;
    a.id = u"a"_s;
    a.type = u"Goto"_s;
    a.set(u"lat"_s, 38.5);
    a.set(u"lon"_s, -28.6);
    a.set(u"speed"_s, 0.1 + 0.2); // the shortest text that reads back the same
    plan.maneuvers.append(a);
    mission.plans.append(plan);
    const QByteArray text = writeMission(mission);
    EXPECT_TRUE(text.contains(R"(speed="0.30000000000000004")")) << text.constData();
    const auto back = read(text);
    ASSERT_TRUE(back) << errorsText(back.error()).toStdString();
    EXPECT_EQ(*back, mission);
    EXPECT_EQ(back->plans[0].maneuvers[0].number(u"speed"_s), 0.1 + 0.2);
}

TEST(MissionXml, SchemaErrorsNameTheFileLineAndElement)
{
    struct Case
    {
        const char *what;
        QByteArray text;
        int line;
        const char *says;
    };
    const QList<Case> cases{
        {"missing latitude", withManeuvers("<Goto id='a' lon='1'/>"), 3, "Element 'Goto': The attribute 'lat' is required"},
        {"latitude out of range", withManeuvers("\n<Goto id='a' lat='91' lon='1'/>"), 4, "The value '91' is greater than the maximum value allowed ('90')"},
        {"unknown maneuver", withManeuvers("\n\n<Teleport id='a' lat='1' lon='1'/>"), 5, "Element 'Teleport': This element is not expected"},
        {"unknown parameter", withManeuvers("<Goto id='a' lat='1' lon='1' warp='9'/>"), 3, "The attribute 'warp' is not allowed"},
        {"bad enumeration", withManeuvers("<Goto id='a' lat='1' lon='1' z_units='FATHOMS'/>"), 3, "FATHOMS"},
        {"duplicate maneuver", withManeuvers("<Goto id='a' lat='1' lon='1'/>\n<Goto id='a' lat='1' lon='1'/>"), 4, "Element 'Goto': maneuver id 'a' is used twice (first at line 3)"},
        {"transition to nowhere", withManeuvers("<Goto id='a' lat='1' lon='1'/>", "\n<transition from='a' to='b'/>"), 4, "Element 'transition': 'b' names no maneuver of plan 'p'"},
        {"start nowhere", QByteArray(withManeuvers("<Goto id='b' lat='1' lon='1'/>")), 2, "Element 'plan': start 'a' names no maneuver of plan 'p'"},
        {"plan for an unlisted vehicle", QByteArray(withManeuvers("<Goto id='a' lat='1' lon='1'/>")).replace("vehicle=\"v\" start", "vehicle=\"w\" start"), 2, "Element 'plan': vehicle 'w' does not take part in the mission"},
        {"not a number", withManeuvers("<Goto id='a' lat='1' lon='1' speed='NaN'/>"), 3, "'NaN' is not a finite number"},
        {"duplicate plan", QByteArray(withManeuvers("<Goto id='a' lat='1' lon='1'/>")).replace("</mission>",
             "\n<plan id=\"p\" vehicle=\"v\" start=\"a\"><maneuvers><Goto id='a' lat='1' lon='1'/></maneuvers></plan></mission>"),
         4, "Element 'plan': plan id 'p' is used twice (first at line 2)"},
    };
    for (const Case &c : cases) {
        const auto result = read(c.text);
        ASSERT_FALSE(result) << c.what;
        const auto &first = result.error().first();
        EXPECT_EQ(first.file, u"test.xml"_s) << c.what;
        EXPECT_EQ(first.line, c.line) << c.what << ": " << first.toString().toStdString();
        EXPECT_TRUE(first.message.contains(QString::fromUtf8(c.says))) << c.what << ": " << first.toString().toStdString();
    }
}

TEST(MissionXml, PositionsAreGivenOneWay)
{
    const QByteArray both = R"(<mission format="1" id="m"><home lat="0" lon="0"/>
<map id="x"><mark id="a" lat="1" lon="1" north="3" east="4"/></map></mission>)";
    const auto result = read(both);
    ASSERT_FALSE(result);
    EXPECT_EQ(result.error().first().line, 2);
    EXPECT_TRUE(result.error().first().message.contains(u"not both or neither"_s));
    const QByteArray half = R"(<mission format="1" id="m"><home lat="0" lon="0"/>
<map id="x"><mark id="a" lat="1"/></map></mission>)";
    EXPECT_FALSE(read(half));
}

TEST(MissionXml, HostileDocumentsAreRefused)
{
    const QByteArray entity = R"(<?xml version="1.0"?><!DOCTYPE m [<!ENTITY x SYSTEM "file:///etc/passwd">]>
<mission format="1" id="m"><description>&x;</description><home lat="0" lon="0"/></mission>)";
    const auto result = read(entity);
    ASSERT_FALSE(result);
    EXPECT_TRUE(result.error().first().message.contains(u"DOCTYPE"_s));
    EXPECT_FALSE(read("<mission"));
    EXPECT_FALSE(read(""));
}

TEST(MissionXml, SavingIsAtomicAndKeepsThePreviousVersion)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(u"m.xml"_s);
    auto mission = read(everything);
    ASSERT_TRUE(mission);
    ASSERT_TRUE(saveMission(*mission, path));
    mission->name = u"Renamed"_s;
    ASSERT_TRUE(saveMission(*mission, path));
    const auto now = loadMission(path);
    ASSERT_TRUE(now);
    EXPECT_EQ(now->name, u"Renamed"_s);
    const auto before = loadMission(path + u".bak"_s);
    ASSERT_TRUE(before);
    EXPECT_EQ(before->name, u"Harbour survey"_s);
    EXPECT_EQ(QDir(dir.path()).entryList(QDir::Files).size(), 2); // no temporary left behind
    const auto missing = loadMission(dir.filePath(u"none.xml"_s));
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().first().file, dir.filePath(u"none.xml"_s));
}

// A save on a full filesystem (ENOSPC, the sandbox's small disk for saves):
// an error that says so, the mission on disk as it was and no temporary left;
// once there is room the same save goes through. Also when the new version
// fits but the copy of the previous one (.bak) does not.
TEST(MissionXml, ASaveOnAFullDiskFailsSayingSoAndLeavesTheMissionAsItWas)
{
    const QString disk = neptus::test::smallDisk(u"mission-saves"_s);
    if (disk.isEmpty())
        GTEST_SKIP() << neptus::test::noSmallDisk;
    QTemporaryDir dir(disk + u"/mission-XXXXXX"_s);
    ASSERT_TRUE(dir.isValid());
    const QString path = dir.filePath(u"m.xml"_s);
    auto mission = read(everything);
    ASSERT_TRUE(mission);
    ASSERT_TRUE(saveMission(*mission, path));
    const QByteArray saved = [&] { QFile f(path); f.open(QIODevice::ReadOnly); return f.readAll(); }();
    mission->name = u"Renamed"_s;
    const auto unchanged = [&] {
        QFile f(path);
        return f.open(QIODevice::ReadOnly) && f.readAll() == saved && QDir(dir.path()).entryList(QDir::Files) == QStringList{u"m.xml"_s};
    };
    neptus::test::DiskFiller filler(disk);
    filler.fill(0);
    auto full = saveMission(*mission, path);
    ASSERT_FALSE(full);
    EXPECT_TRUE(full.error().contains(u"No space left on device"_s)) << full.error().toStdString();
    EXPECT_TRUE(full.error().contains(path)) << full.error().toStdString();
    EXPECT_TRUE(unchanged()) << "the mission on disk was touched";
    // Room for the new version, not for the copy of the old one beside it.
    filler.free();
    filler.fill(saved.size() + 2048);
    full = saveMission(*mission, path);
    ASSERT_FALSE(full) << "room was left for " << saved.size() + 2048 << " bytes";
    EXPECT_TRUE(full.error().contains(u"No space left on device"_s)) << full.error().toStdString();
    EXPECT_TRUE(unchanged());
    filler.free();
    ASSERT_TRUE(saveMission(*mission, path));
    EXPECT_EQ(loadMission(path)->name, u"Renamed"_s);
    EXPECT_EQ(loadMission(path + u".bak"_s)->name, u"Harbour survey"_s);
}
