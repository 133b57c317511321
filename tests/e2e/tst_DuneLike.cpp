// The console against the simulator in its DUNE-like mode (--like-dune): a
// vehicle that answers as a stock DUNE does — found only through IMC
// discovery, streaming from its next contact refresh, a START answered three
// times, plan ends in its own words (src/Plan/Engine, src/Supervisors/Vehicle).
// A plan sent, started and completed; started again and aborted: the plan
// log and the alarm window show each end once, with the vehicle's words,
// and no "communications lost" while it announces before it streams.
#include "mission/MissionXml.h"
#include "plans/PlanDesk.h"
#include "session/Console.h"

#include "Missions.h"
#include "QtPrinters.h"
#include "Schemas.h"
#include "SimProcess.h"

#include <QTest>

#include <gtest/gtest.h>

using namespace neptus;
using namespace Qt::StringLiterals;

namespace {

const QByteArray missionText = R"X(<?xml version="1.0" encoding="UTF-8"?>
<mission format="1" id="dune" name="DUNE-like">
  <home lat="41.1705" lon="-8.7150" height="0"/>
  <vehicle id="lauv-simulator-1"/>
  <plan id="survey" vehicle="lauv-simulator-1" start="go">
    <maneuvers>
      <Goto id="go" lat="41.1712" lon="-8.7150" z="2" z_units="DEPTH" speed="1.6" speed_units="METERS_PS"/>
      <StationKeeping id="wait" lat="41.1712" lon="-8.7150" z="0" z_units="DEPTH" speed="1.6" speed_units="METERS_PS"
                      duration="20" radius="10"/>
    </maneuvers>
    <transition from="go" to="wait"/>
  </plan>
</mission>
)X";

// What the alarm window lists for a node, as it changes: each distinct line once.
struct AlarmLines
{
    const alarms::AlarmGraph &graph;
    QString origin;
    QStringList seen;
    void look()
    {
        for (const alarms::AlarmGraph::Alarm &a : graph.activeAlarms()) {
            const QString line = u"%1 %2\t%3"_s.arg(alarms::levelName(a.level), a.message).arg(a.sinceMs);
            if (a.origin == origin && !seen.contains(line))
                seen << line;
        }
    }
    QStringList messages() const
    {
        QStringList out;
        for (const QString &line : seen)
            out << line.section(u'\t', 0, 0);
        return out;
    }
};

} // namespace

TEST(DuneLike, APlanCompletesThenAnotherIsAbortedEachEndSaidOnceInTheVehiclesWords)
{
    session::Console console(test::shippedSchema());
    transport::ImcUdpConfig config;
    config.port = 0; // IMC discovery on its standard ports, as a stock DUNE needs
    ASSERT_TRUE(console.startImc(config));
    test::SimProcess vehicle;
    vehicle.start({u"--id"_s, u"0xd1"_s, u"--name"_s, u"lauv-simulator-1"_s, u"--port"_s, u"16023"_s, u"--like-dune"_s,
                   u"--time-factor"_s, u"10"_s});
    const QString name = u"lauv-simulator-1"_s;
    tree::VariableTree &tree = console.tree();
    alarms::AlarmGraph &graph = console.alarmGraph();
    const auto text = [&](const QString &path) {
        const tree::NodeId node = tree.find(path);
        return node == tree::noNode ? QString() : tree.snapshot(node).text;
    };

    // Found, and streaming within one contact refresh; no silence alarm meanwhile.
    alarms::Level worst = alarms::Normal;
    ASSERT_TRUE(QTest::qWaitFor([&] {
        const auto node = graph.find(u"systems/lauv-simulator-1"_s);
        if (node != alarms::AlarmGraph::noNode)
            worst = std::max(worst, graph.ownLevel(node));
        return !text(name + u"/EstimatedState/depth"_s).isEmpty() && !text(name + u"/PlanControlState/state"_s).isEmpty();
    }, 12000)) << vehicle.output.constData();
    EXPECT_LT(worst, alarms::Warning) << "announced before it streamed: no 'communications lost'";

    plans::PlanDesk desk(test::shippedSchema(), tree, graph, [&](quint16 id, const msg::Message &m) { return console.send(id, m); });
    QObject::connect(&console, &session::Console::planMessageReceived, &desk, &plans::PlanDesk::receive);
    auto read = mission::readMission(missionText, u"dune.xml"_s);
    ASSERT_TRUE(read) << test::errorsText(read.error()).toStdString();
    desk.setMission(*read);
    const auto log = [&] { return desk.log(name).join(u'\n'); };
    AlarmLines window{graph, u"systems/lauv-simulator-1/plan"_s, {}};
    const auto waitFor = [&](const std::function<bool()> &done, int ms) {
        return QTest::qWaitFor([&] {
            window.look();
            return done();
        }, ms);
    };

    ASSERT_TRUE(desk.refresh(name));
    ASSERT_TRUE(waitFor([&] { return desk.fetched(name); }, 10000)) << log().toStdString();
    ASSERT_TRUE(desk.send(name, u"survey"_s));
    ASSERT_TRUE(waitFor([&] { return desk.sync(name, u"survey"_s) == plans::Sync::Same; }, 10000)) << log().toStdString();

    // Started: DUNE's first reply answers the START, its second is no end.
    ASSERT_TRUE(desk.start(name, u"survey"_s));
    ASSERT_TRUE(waitFor([&] { return text(name + u"/PlanControlState/state"_s) == u"EXECUTING"; }, 10000)) << log().toStdString();
    waitFor([] { return false; }, 1500);
    EXPECT_TRUE(log().contains(u"START survey: plan loaded"_s)) << log().toStdString();
    EXPECT_FALSE(log().contains(u"completed"_s)) << "no early 'completed'\n" << log().toStdString();
    EXPECT_TRUE(window.seen.isEmpty()) << window.seen.join(u'\n').toStdString();

    // Completed: once, in the log and the alarm window.
    ASSERT_TRUE(waitFor([&] { return log().contains(u"survey completed"_s); }, 60000)) << log().toStdString();
    waitFor([] { return false; }, 2000);
    EXPECT_EQ(desk.log(name).filter(u"survey completed"_s).size(), 1) << log().toStdString();
    EXPECT_EQ(window.messages().join(u'\n').toStdString(), "Info plan survey completed");

    // Started again and aborted: a Warning with DUNE's words, once.
    ASSERT_TRUE(desk.start(name, u"survey"_s));
    ASSERT_TRUE(waitFor([&] { return text(name + u"/PlanControlState/state"_s) == u"EXECUTING"; }, 10000)) << log().toStdString();
    ASSERT_TRUE(desk.abort(name));
    const QString words = u"got abort request from system neptus-qt - 0x4001 @ 0xFF"_s;
    ASSERT_TRUE(waitFor([&] { return log().contains(u"survey failed: "_s + words); }, 10000)) << log().toStdString();
    // BLOCKED, then READY again a second later: no second end.
    ASSERT_TRUE(waitFor([&] { return text(name + u"/PlanControlState/state"_s) == u"READY"; }, 10000));
    waitFor([] { return false; }, 2000);
    EXPECT_EQ(desk.log(name).filter(u"survey failed"_s).size(), 1) << log().toStdString();
    EXPECT_EQ(desk.log(name).filter(u"survey completed"_s).size(), 1) << log().toStdString();
    EXPECT_EQ(window.messages().join(u'\n').toStdString(), (u"Info plan survey completed\nWarning plan survey failed: "_s + words).toStdString());
    EXPECT_TRUE(vehicle.output.contains("received Abort")) << vehicle.output.constData();
}
