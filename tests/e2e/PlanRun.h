#pragma once

// Plans run end to end by a console against neptus-sim processes: a mission
// near the simulator, sending and starting it, following it to its end.
#include "mission/ImcPlan.h"
#include "mission/MissionXml.h"
#include "plans/PlanClient.h"
#include "plans/PlanDatabase.h"
#include "runs/PlanRuns.h"
#include "session/Console.h"

#include "Missions.h"
#include "Schemas.h"

#include <QTest>

#include <gtest/gtest.h>

namespace neptus::test {

using namespace Qt::StringLiterals;
using namespace neptus;

// Near the simulator's reference point (off Leixões, by Porto).
inline QByteArray missionFor(const char *vehicle, double z, const char *units)
{
    return QStringLiteral(R"X(<?xml version="1.0" encoding="UTF-8"?>
<mission format="1" id="e2e" name="e2e">
  <home lat="41.1705" lon="-8.7150" height="0"/>
  <vehicle id="%1"/>
  <plan id="survey" vehicle="%1" start="go">
    <maneuvers>
      <Goto id="go" lat="41.1712" lon="-8.7150" z="%2" z_units="%3" speed="1.5" speed_units="METERS_PS"/>
      <Loiter id="circle" lat="41.1712" lon="-8.7150" z="%2" z_units="%3" speed="1.5" speed_units="METERS_PS"
              duration="45" radius="15" type="CIRCULAR" direction="CLOCKW"/>
      <Rows id="rows" lat="41.1715" lon="-8.7145" z="%2" z_units="%3" speed="1.5" speed_units="METERS_PS"
            width="40" length="50" hstep="20" bearing="0"/>
    </maneuvers>
    <transition from="go" to="circle"/>
    <transition from="circle" to="rows"/>
  </plan>
</mission>
)X")
        .arg(QLatin1StringView(vehicle))
        .arg(z)
        .arg(QLatin1StringView(units))
        .toUtf8();
}

struct Replies
{
    std::vector<plans::PlanClient::Reply> all;
    std::optional<plans::PlanClient::Reply> of(quint16 id) const
    {
        for (const auto &r : all)
            if (r.requestId == id)
                return r;
        return std::nullopt;
    }
};

// Sends a plan, checks it is held, starts it and follows it to its end;
// `watcher`, another console, sees it run too (from the vehicle's reports).
inline void runPlan(session::Console &console, quint16 id, const QString &name, const QByteArray &mission,
             session::Console *watcher = nullptr)
{
    const auto schema = test::shippedSchema();
    auto m = mission::readMission(mission, u"e2e.xml"_s);
    ASSERT_TRUE(m) << test::errorsText(m.error()).toStdString();
    const auto spec = mission::planSpecification(m->plans.first(), *schema);
    ASSERT_TRUE(spec) << spec.error().toStdString();

    plans::PlanClient client(schema, id, [&](const msg::Message &message) {
        const auto sent = console.send(id, message);
        ASSERT_TRUE(sent) << sent.error().toStdString();
    });
    QObject::connect(&console, &session::Console::planMessageReceived, &client, &plans::PlanClient::receive);
    Replies replies;
    QObject::connect(&client, &plans::PlanClient::replied, [&](const auto &r) { replies.all.push_back(r); });
    // How the plan ends: from the vehicle's PlanControlState, as the console's desk follows it.
    plans::PlanRuns runs;
    std::optional<plans::PlanRuns::Event> ended;
    QObject::connect(&console, &session::Console::planMessageReceived, &client, [&](const msg::Message &message) {
        for (const auto &e : runs.observe(message, QDateTime::currentMSecsSinceEpoch()))
            if (e.kind == plans::PlanRuns::Event::Kind::Ended)
                ended = e;
    });
    const auto answered = [&](quint16 request) {
        EXPECT_TRUE(QTest::qWaitFor([&] { return replies.of(request).has_value(); }, 10000)) << "request " << request;
        return replies.of(request).value_or(plans::PlanClient::Reply{});
    };

    // Sent, and held exactly: the vehicle's MD5 for it is ours.
    const msg::Codec codec(schema);
    const auto stored = answered(client.set(*spec));
    ASSERT_TRUE(stored.ok) << stored.info.toStdString();
    const auto state = answered(client.getState(true));
    ASSERT_TRUE(state.ok && state.arg) << state.info.toStdString();
    EXPECT_EQ(plans::compare(codec, *spec, *state.arg), plans::Sync::Same);
    // A plan changed here after sending is seen to differ before START.
    mission::Plan edited = m->plans.first();
    edited.maneuvers[0].set(u"speed"_s, 1.2);
    EXPECT_EQ(plans::compare(codec, *mission::planSpecification(edited, *schema), *state.arg), plans::Sync::Differs);

    const auto started = answered(client.start(u"survey"_s));
    ASSERT_TRUE(started.ok) << started.info.toStdString();

    // Followed in the tree: the vehicle's own reports, maneuver by maneuver.
    tree::VariableTree &tree = console.tree();
    std::vector<QString> maneuvers;
    double progress = 0;
    const auto value = [&](const QString &field) {
        const tree::NodeId node = tree.find(name + u"/PlanControlState/"_s + field);
        return node == tree::noNode ? QVariant() : tree.snapshot(node).value;
    };
    ASSERT_TRUE(QTest::qWaitFor([&] {
        if (tree.snapshot(tree.find(name + u"/PlanControlState/state"_s)).text == u"EXECUTING") {
            const QString man = value(u"man_id"_s).toString();
            if (!man.isEmpty() && (maneuvers.empty() || maneuvers.back() != man))
                maneuvers.push_back(man);
            progress = std::max(progress, value(u"plan_progress"_s).toDouble());
        }
        return ended.has_value();
    }, 40000)) << "maneuvers seen: " << QStringList(maneuvers.begin(), maneuvers.end()).join(u", "_s).toStdString();
    EXPECT_EQ(maneuvers, (std::vector<QString>{u"go"_s, u"circle"_s, u"rows"_s}));
    if (watcher) {
        const tree::VariableTree &other = watcher->tree();
        const auto seen = [&](const char *field) {
            const tree::NodeId node = other.find(name + u"/PlanControlState/"_s + QLatin1StringView(field));
            return node == tree::noNode ? QString() : other.snapshot(node).text;
        };
        EXPECT_EQ(seen("plan_id"), u"survey"_s) << "the second console knows which plan runs";
        EXPECT_TRUE(QTest::qWaitFor([&] { return seen("last_outcome") == u"SUCCESS"; }, 5000)) << "and how it ended";
    }
    EXPECT_GT(progress, 50);
    EXPECT_EQ(ended->outcome, plans::PlanRuns::Outcome::Completed);
    EXPECT_EQ(ended->plan, u"survey"_s);
    EXPECT_TRUE(QTest::qWaitFor([&] { return tree.snapshot(tree.find(name + u"/PlanControlState/last_outcome"_s)).text == u"SUCCESS"; }, 5000));
}

// A console's IMC/UDP link to vehicles on these loopback ports (its own ports chosen by the system).
inline transport::ImcUdpConfig imcTo(std::initializer_list<quint16> ports)
{
    transport::ImcUdpConfig config;
    config.port = 0;
    config.discoveryPort = 0;
    config.heartbeatMs = 200;
    for (const quint16 port : ports)
        config.destinations.append({QHostAddress::LocalHost, port});
    return config;
}

inline bool heard(const tree::VariableTree &tree, const QString &system)
{
    const tree::NodeId node = tree.find(system + u"/EstimatedState/depth"_s);
    return node != tree::noNode && tree.snapshot(node).present;
}

} // namespace neptus::test
