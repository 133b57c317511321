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

#include <QDateTime>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSaveFile>
#include <QUrl>
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

namespace {

// The console each program of the next test opens: a map with its plan
// editor open, and an operator the test drives through a cue file (a JSON
// list of steps, read every 100 ms; each step done once, in order). Edits go
// through the editor's model, as a drag on the map does; what the panel
// says of the sharing is printed as it changes.
//   {"at": EPOCH_MS, "plan": P, "maneuver": M, "lat": .., "lon": ..}  move M at that moment
//   {"undo": true}, {"save": true}, {"shot": FILE}, {"quit": true}
// A timed step blocks the console's event loop from 1.5 s before its moment
// until it is done, so that two consoles given the same moment both edit
// before either has read the other's change (a collision, every run).
constexpr auto operatorConsole = R"(import QtQuick
import Neptus.Components

Console {
    id: layout
    designWidth: 1280
    designHeight: 800
    title: "Shared mission, NAME"
    Map2D { id: map; x: 0; y: 0; width: 1280; height: 800; editingPlan: true }
    Item {
        id: operator
        property int done: 0
        property bool reading: false
        readonly property var desk: Session.session ? Session.session.plans : null
        function say(what) { console.log("NAME " + what) }
        function report() { say("status: " + desk.shareStatus + " | with: " + desk.sharedWith.join(",")) }
        Connections {
            target: operator.desk
            function onSharingChanged() { operator.report() }
        }
        // (The console is made once the window is drawn: sharing may have begun before.)
        Component.onCompleted: if (desk) report()
        function step(s) {
            const model = map.planEditor ? map.planEditor.model : null
            if (!model)
                return false
            if (s.at !== undefined) {
                if (Date.now() < s.at - 1500)
                    return false
                while (Date.now() < s.at) {}
                model.planId = s.plan
                say("moved " + s.plan + "/" + s.maneuver + ": " + model.moveManeuver(s.maneuver, s.lat, s.lon))
            } else if (s.undo) {
                say("undo: " + model.undo())
            } else if (s.save) {
                say("saved: " + model.save())
            } else if (s.shot) {
                layout.grabToImage(r => say("shot: " + r.saveToFile(s.shot)))
            } else if (s.quit) {
                Qt.quit()
            }
            return true
        }
        Timer {
            interval: 100
            running: true
            repeat: true
            onTriggered: {
                if (operator.reading)
                    return
                operator.reading = true
                const request = new XMLHttpRequest()
                request.onreadystatechange = () => {
                    if (request.readyState !== XMLHttpRequest.DONE)
                        return
                    operator.reading = false
                    let steps = []
                    try { steps = JSON.parse(request.responseText) } catch (e) { return }
                    while (operator.done < steps.length && operator.step(steps[operator.done]))
                        ++operator.done
                }
                request.open("GET", "CUE")
                request.send()
            }
        }
    }
}
)";

// One of the console programs of the next test.
struct Operator
{
    Operator(QString name, QString mission, QString systemId)
        : name(std::move(name))
        , mission(std::move(mission))
        , systemId(std::move(systemId))
    {}
    QString name, mission, systemId, cue, shot;
    QProcess process;
    QString said;

    void start(const QTemporaryDir &dir, const QString &consoleFile)
    {
        cue = dir.filePath(name + u"-cue.json"_s);
        shot = dir.filePath(name + u".png"_s);
        cues({});
        const QString console = dir.filePath(name + u".qml"_s);
        QFile qml(console);
        ASSERT_TRUE(qml.open(QIODevice::WriteOnly));
        qml.write(QString::fromUtf8(operatorConsole).replace(u"NAME"_s, name).replace(u"CUE"_s, QUrl::fromLocalFile(cue).toString()).toUtf8());
        qml.close();
        ASSERT_TRUE(QFile::copy(consoleFile, mission));
        QFile::setPermissions(mission, QFile::ReadOwner | QFile::WriteOwner);
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(u"QML_XHR_ALLOW_FILE_READ"_s, u"1"_s);
        env.insert(u"XDG_CONFIG_HOME"_s, dir.filePath(name + u"-config"_s));
        env.insert(u"XDG_DATA_HOME"_s, dir.filePath(name + u"-data"_s));
        process.setProcessEnvironment(env);
        process.setProcessChannelMode(QProcess::MergedChannels);
        process.start(test::programPath(u"neptus"_s),
                      {u"--console"_s, console, u"--mission"_s, mission, u"--share"_s, u"--console-name"_s, name, u"--dds-domain"_s,
                       u"25"_s, u"--system-id"_s, systemId, u"--imc-discovery"_s, u"off"_s, u"--imc-port"_s, u"0"_s, u"--no-record"_s,
                       u"--size"_s, u"1280x800"_s});
        ASSERT_TRUE(process.waitForStarted(5000));
    }
    QJsonArray steps;
    void cues(const QJsonArray &more)
    {
        for (const QJsonValue &v : more)
            steps.append(v);
        QSaveFile file(cue);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        file.write(QJsonDocument(steps).toJson());
        ASSERT_TRUE(file.commit());
    }
    bool says(const QString &what)
    {
        said += QString::fromUtf8(process.readAll());
        return said.contains(what);
    }
};

QJsonObject move(qint64 at, const QString &plan, const QString &maneuver, double lat, double lon)
{
    return {{u"at"_s, at}, {u"plan"_s, plan}, {u"maneuver"_s, maneuver}, {u"lat"_s, lat}, {u"lon"_s, lon}};
}

double latOf(const QString &file, const QString &plan, const QString &maneuver)
{
    const auto m = mission::loadMission(file);
    if (!m)
        return 0;
    for (const auto &p : m->plans)
        if (p.id == plan)
            for (const auto &x : p.maneuvers)
                if (x.id == maneuver)
                    return x.number(u"lat"_s);
    return 0;
}

} // namespace

// Two console programs share one mission and edit it, each in turn and then
// both at the same moment (issue #38). Each program's operator is its
// console file: edits made through the plan editor, as a drag makes them.
TEST(SharedMission, TwoConsoleProgramsEditOneMissionBothWaysAndASimultaneousEditIsResolvedAsDocumented)
{
    QTemporaryDir dir;
    const QString example = test::sourcePath(u"docs/examples/leixoes.xml"_s);
    // (Two consoles on one DDS domain need ids of their own: --system-id.)
    Operator a(u"console-a"_s, dir.filePath(u"a.xml"_s), u"0x4001"_s), b(u"console-b"_s, dir.filePath(u"b.xml"_s), u"0x4010"_s);
    a.start(dir, example);
    b.start(dir, example);
    const auto both = [&] {
        a.says({});
        b.says({});
        return "\n--- console-a:\n" + a.said.toStdString() + "\n--- console-b:\n" + b.said.toStdString();
    };

    // Each hears the other (the panel says with whom it shares).
    ASSERT_TRUE(QTest::qWaitFor([&] { return a.says(u"with: console-b"_s) && b.says(u"with: console-a"_s); }, 30000)) << both();

    // A moves the survey's first Goto: B's panel and file have it.
    a.cues({move(QDateTime::currentMSecsSinceEpoch() + 1500, u"survey"_s, u"go"_s, 41.1716, -8.7160)});
    ASSERT_TRUE(QTest::qWaitFor([&] { return b.says(u"status: plan survey changed by console-a"_s) && latOf(b.mission, u"survey"_s, u"go"_s) == 41.1716; }, 15000)) << both();

    // B moves the patrol's first Goto: A's panel and file have it.
    b.cues({move(QDateTime::currentMSecsSinceEpoch() + 1500, u"patrol"_s, u"out"_s, 41.1693, -8.7178)});
    ASSERT_TRUE(QTest::qWaitFor([&] { return a.says(u"status: plan patrol changed by console-b"_s); }, 15000)) << both();
    ASSERT_TRUE(QTest::qWaitFor([&] { return latOf(a.mission, u"patrol"_s, u"out"_s) == 41.1693; }, 5000)) << both();

    // Both move the survey's surfacing point at the same moment. As
    // docs/dds.md says: the same version, so the author's name decides
    // (console-b's is kept on both), and each panel says what happened.
    // (A console kept from its cue past the moment by a busy machine reads the
    // other's change first: then no collision, and the test tries again, as
    // two operators would not, at a new moment. Each try moves to new places.)
    const double aLats[] = {41.1703, 41.1704, 41.1705}, bLats[] = {41.1700, 41.1699, 41.1698};
    double aLat = 0, bLat = 0;
    bool collided = false;
    for (int attempt = 0; attempt < 3 && !collided; ++attempt) {
        aLat = aLats[attempt];
        bLat = bLats[attempt];
        const qint64 moment = QDateTime::currentMSecsSinceEpoch() + 3000;
        a.cues({move(moment, u"survey"_s, u"surface"_s, aLat, -8.7150)});
        b.cues({move(moment, u"survey"_s, u"surface"_s, bLat, -8.7160)});
        collided = QTest::qWaitFor([&] {
            return a.says(u"status: plan survey changed by console-b at the same moment as here: theirs kept"_s)
                && b.says(u"status: plan survey changed by console-a at the same moment as here: yours kept"_s);
        }, 10000);
    }
    ASSERT_TRUE(collided) << both();
    // What each looks like now, then both save: the same mission in both files.
    a.cues({QJsonObject{{u"shot"_s, a.shot}}, QJsonObject{{u"save"_s, true}}});
    b.cues({QJsonObject{{u"shot"_s, b.shot}}, QJsonObject{{u"save"_s, true}}});
    ASSERT_TRUE(QTest::qWaitFor([&] { return a.says(u"saved: true"_s) && b.says(u"saved: true"_s); }, 15000)) << both();
    EXPECT_TRUE(QTest::qWaitFor([&] { return a.says(u"shot: true"_s) && b.says(u"shot: true"_s); }, 10000)) << both();
    EXPECT_EQ(latOf(a.mission, u"survey"_s, u"surface"_s), bLat) << both();
    EXPECT_EQ(latOf(b.mission, u"survey"_s, u"surface"_s), bLat) << both();
    EXPECT_EQ(latOf(a.mission, u"survey"_s, u"go"_s), 41.1716);
    EXPECT_EQ(latOf(b.mission, u"patrol"_s, u"out"_s), 41.1693);
    const auto missionA = mission::loadMission(a.mission), missionB = mission::loadMission(b.mission);
    ASSERT_TRUE(missionA && missionB);
    EXPECT_EQ(mission::writeMission(*missionA), mission::writeMission(*missionB)) << "both consoles end with the same mission";

    // A's operator takes theirs back with Undo: a new change, which B gets.
    b.says({});
    b.said.clear();
    a.cues({QJsonObject{{u"undo"_s, true}}});
    ASSERT_TRUE(QTest::qWaitFor([&] { return latOf(b.mission, u"survey"_s, u"surface"_s) == aLat; }, 15000)) << both();
    EXPECT_TRUE(QTest::qWaitFor([&] { return b.says(u"status: plan survey changed by console-a,"_s); }, 5000)) << "no collision this time: " << both();

    a.cues({QJsonObject{{u"quit"_s, true}}});
    b.cues({QJsonObject{{u"quit"_s, true}}});
    ASSERT_TRUE(a.process.waitForFinished(15000) && b.process.waitForFinished(15000)) << both();
    EXPECT_EQ(a.process.exitCode(), 0) << both();
    EXPECT_EQ(b.process.exitCode(), 0) << both();
    // For a look: each console's panel as the collision was told.
    if (const QString keep = qEnvironmentVariable("NEPTUS_KEEP_SHOTS"); !keep.isEmpty()) {
        QFile::copy(a.shot, keep + u"/shared-collision-console-a.png"_s);
        QFile::copy(b.shot, keep + u"/shared-collision-console-b.png"_s);
    }
}
