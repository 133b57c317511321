// How the console follows a vehicle's plans (PlanRuns): from its
// PlanControlState, with the words of its PlanControl replies, in the order
// and with the texts a real DUNE uses (src/Plan/Engine/Task.cpp; the fixture
// log ../shared/fixtures/dune-log): each run starts once and ends once.
#include "runs/PlanRuns.h"

#include "core/Gzip.h"
#include "messages/Codec.h"

#include <QtEndian>

#include "Fixtures.h"
#include "Schemas.h"

#include <gtest/gtest.h>

using namespace neptus;
using namespace Qt::StringLiterals;
using Event = plans::PlanRuns::Event;
using Outcome = plans::PlanRuns::Outcome;

namespace {

constexpr quint16 vehicle = 0x00d1;

struct Dune
{
    std::shared_ptr<const msg::Schema> schema = test::shippedSchema();
    plans::PlanRuns runs;
    std::vector<Event> events;
    qint64 now = 1'700'000'000'000;

    void hear(const msg::Message &m)
    {
        for (Event &e : runs.observe(m, now))
            events.push_back(std::move(e));
    }
    void after(qint64 ms)
    {
        now += ms;
        for (Event &e : runs.poll(now))
            events.push_back(std::move(e));
    }
    void set(msg::Message &m, const char *field, const char *name) const
    {
        const int i = m.def()->indexOf(QString::fromLatin1(field));
        m.setInteger(i, *m.field(i).enumeration->parse(QString::fromLatin1(name)));
    }
    // A PlanControlState as DUNE fills it.
    void state(const char *state, const char *plan, const char *maneuver = "", const char *outcome = "NONE")
    {
        msg::Message m(schema->byAbbrev(u"PlanControlState"));
        m.header.src = vehicle;
        set(m, "state", state);
        set(m, "last_outcome", outcome);
        m.setBytes(m.def()->indexOf(u"plan_id"), plan);
        m.setBytes(m.def()->indexOf(u"man_id"), maneuver);
        hear(m);
    }
    // A PlanControl reply, with the id and op of the request the vehicle last answered.
    void reply(const char *type, const char *op, quint16 request, const char *plan, const char *info)
    {
        msg::Message m(schema->byAbbrev(u"PlanControl"));
        m.header.src = vehicle;
        m.header.dst = 0x4001;
        set(m, "type", type);
        set(m, "op", op);
        m.setInteger(m.def()->indexOf(u"request_id"), request);
        m.setBytes(m.def()->indexOf(u"plan_id"), plan);
        m.setBytes(m.def()->indexOf(u"info"), info);
        hear(m);
    }
    std::vector<Event> ends() const
    {
        std::vector<Event> out;
        std::copy_if(events.begin(), events.end(), std::back_inserter(out), [](const Event &e) { return e.kind == Event::Kind::Ended; });
        return out;
    }
    int count(Event::Kind kind) const
    {
        return int(std::count_if(events.begin(), events.end(), [&](const Event &e) { return e.kind == kind; }));
    }
};

} // namespace

// DUNE's three SUCCESS replies to a START: the first two (the same second)
// are not the plan's end; "plan completed" is, with READY and SUCCESS.
TEST(PlanRuns, DunesThreeRepliesToAStartEndTheRunOnceWithItsRealOutcome)
{
    Dune d;
    d.state("READY", "", "", "NONE");
    d.state("INITIALIZING", "", "", "NONE"); // still the previous plan's id
    d.reply("SUCCESS", "START", 7, "plan1", "plan loaded");
    d.state("EXECUTING", "plan1", "goto1");
    d.reply("SUCCESS", "START", 7, "plan1", "goto1: executing maneuver");
    for (int i = 0; i < 600; ++i) { // 3 Hz for the minutes it runs
        d.after(333);
        d.state("EXECUTING", "plan1", i < 300 ? "goto1" : "sk2");
    }
    EXPECT_TRUE(d.ends().empty()) << "no early 'completed'";
    d.reply("SUCCESS", "START", 7, "plan1", "plan completed");
    d.state("READY", "plan1", "", "SUCCESS");
    d.after(333);
    d.state("READY", "plan1", "", "SUCCESS");

    ASSERT_EQ(d.count(Event::Kind::Started), 1);
    EXPECT_EQ(d.events.front().plan, u"plan1"_s);
    EXPECT_EQ(d.events.front().maneuver, u"goto1"_s);
    EXPECT_FALSE(d.events.front().joined);
    EXPECT_EQ(d.count(Event::Kind::Maneuver), 1);
    ASSERT_EQ(d.ends().size(), 1u);
    EXPECT_EQ(d.ends()[0].outcome, Outcome::Completed);
    EXPECT_EQ(d.ends()[0].plan, u"plan1"_s);
    EXPECT_EQ(d.ends()[0].system, vehicle);
    EXPECT_FALSE(d.runs.running(vehicle));
}

// Abort: DUNE's supervisor fails the plan with its words (sent to whoever
// last made a request), BLOCKED, then READY a second later: one end, a failure, with the reason.
TEST(PlanRuns, AnAbortIsAFailureInTheVehiclesWords)
{
    Dune d;
    d.state("EXECUTING", "plan1", "goto1");
    d.reply("FAILURE", "GET", 9, "plan1", "got abort request from system neptus-qt - 0x4001 @ 0xFF");
    d.state("BLOCKED", "plan1", "", "FAILURE");
    d.after(1000);
    d.state("READY", "plan1", "", "FAILURE");
    ASSERT_EQ(d.ends().size(), 1u);
    EXPECT_EQ(d.ends()[0].outcome, Outcome::Failed);
    EXPECT_EQ(d.ends()[0].reason, u"got abort request from system neptus-qt - 0x4001 @ 0xFF"_s);
}

// STOP: DUNE answers the STOP "OK", the START nothing; READY with FAILURE is a stop, not a failure.
TEST(PlanRuns, AStopAnsweredOkIsAStop)
{
    Dune d;
    d.state("EXECUTING", "plan1", "goto1");
    d.reply("SUCCESS", "STOP", 8, "plan1", "OK");
    d.state("READY", "plan1", "", "FAILURE");
    ASSERT_EQ(d.ends().size(), 1u);
    EXPECT_EQ(d.ends()[0].outcome, Outcome::Stopped);
}

// A console that starts (or restarts) in the middle of a plan learns of it
// from the first state it hears, and sees its end; one that hears a plan
// ended before it came reports nothing.
TEST(PlanRuns, AConsoleThatJoinsMidPlanSeesThePlanAndItsEnd)
{
    Dune d;
    d.state("EXECUTING", "survey", "rows3");
    ASSERT_EQ(d.events.size(), 1u);
    EXPECT_EQ(d.events[0].kind, Event::Kind::Started);
    EXPECT_TRUE(d.events[0].joined);
    EXPECT_EQ(d.events[0].maneuver, u"rows3"_s);
    ASSERT_TRUE(d.runs.running(vehicle));
    d.reply("FAILURE", "GET", 3, "survey", "Goto maneuver error: vehicle too far from path");
    d.state("READY", "survey", "", "FAILURE");
    ASSERT_EQ(d.ends().size(), 1u);
    EXPECT_EQ(d.ends()[0].outcome, Outcome::Failed);
    EXPECT_EQ(d.ends()[0].reason, u"Goto maneuver error: vehicle too far from path"_s);

    Dune late;
    late.state("READY", "survey", "", "SUCCESS");
    late.state("BLOCKED", "survey", "", "FAILURE");
    EXPECT_TRUE(late.events.empty()) << "an end before this console came is nobody's news";
}

// Over DDS the reply and the state travel on different topics: an end whose
// reason comes after it waits for it (and is told without it when it never comes).
TEST(PlanRuns, AFailureWaitsBrieflyForItsReason)
{
    Dune d;
    d.state("EXECUTING", "plan1", "goto1");
    d.state("READY", "plan1", "", "FAILURE");
    EXPECT_TRUE(d.ends().empty());
    EXPECT_TRUE(d.runs.waiting());
    d.after(200);
    d.reply("FAILURE", "START", 7, "plan1", "Motor: motor jammed");
    ASSERT_EQ(d.ends().size(), 1u);
    EXPECT_EQ(d.ends()[0].reason, u"Motor: motor jammed"_s);

    d.state("EXECUTING", "plan2", "a");
    d.state("BLOCKED", "plan2", "", "FAILURE");
    d.after(plans::PlanRuns::reasonWaitMs - 1);
    EXPECT_EQ(d.ends().size(), 1u);
    d.after(1);
    ASSERT_EQ(d.ends().size(), 2u);
    EXPECT_EQ(d.ends()[1].outcome, Outcome::Failed);
    EXPECT_TRUE(d.ends()[1].reason.isEmpty());
    EXPECT_FALSE(d.runs.waiting());

    // A stop whose "OK" comes after the state is a stop.
    d.state("EXECUTING", "plan3", "a");
    d.state("READY", "plan3", "", "FAILURE");
    d.reply("SUCCESS", "STOP", 12, "plan3", "OK");
    ASSERT_EQ(d.ends().size(), 3u);
    EXPECT_EQ(d.ends()[2].outcome, Outcome::Stopped);
}

// A START over a running plan: DUNE fails the old one silently
// (INITIALIZING still naming it) and runs the new one.
TEST(PlanRuns, AnotherPlanStartedEndsTheOneRunningOnce)
{
    Dune d;
    d.state("EXECUTING", "plan1", "goto1");
    d.state("INITIALIZING", "plan1", "", "FAILURE");
    d.reply("SUCCESS", "START", 4, "plan2", "plan loaded");
    d.state("EXECUTING", "plan2", "a");
    ASSERT_EQ(d.ends().size(), 1u);
    EXPECT_EQ(d.ends()[0].plan, u"plan1"_s);
    EXPECT_EQ(d.ends()[0].outcome, Outcome::Replaced);
    EXPECT_EQ(d.ends()[0].reason, u"plan2"_s);
    EXPECT_EQ(d.count(Event::Kind::Started), 2);
    EXPECT_EQ(d.runs.running(vehicle)->plan, u"plan2"_s);
}

// Words said long before the end (a refused request) are not its reason.
TEST(PlanRuns, AnOldFailureIsNotTheReason)
{
    Dune d;
    d.state("EXECUTING", "plan1", "goto1");
    d.reply("FAILURE", "LOAD", 5, "x", "cannot load plan now");
    d.after(60'000);
    d.state("BLOCKED", "plan1", "", "FAILURE");
    d.after(plans::PlanRuns::reasonWaitMs);
    ASSERT_EQ(d.ends().size(), 1u);
    EXPECT_TRUE(d.ends()[0].reason.isEmpty());
}

// The real DUNE log: the plan (already executing when the log opened) and
// its second maneuver. DUNE closes the log with the plan: its last packets
// are the "plan completed" reply and states still EXECUTING, the READY after
// them unlogged; that reply alone is no end.
TEST(PlanRuns, TheRealDuneLogRunsOnePlanAndItsReplyIsNoEnd)
{
    NEPTUS_REQUIRE_FIXTURE(logPath, "dune-log/Data.lsf.gz");
    NEPTUS_REQUIRE_FIXTURE(definitions, "dune-log/IMC.xml.gz");
    const auto schema = msg::Schema::load({definitions});
    ASSERT_TRUE(schema);
    const msg::Codec codec(*schema);
    const auto log = readFileMaybeGzip(logPath, qsizetype(64) << 20);
    ASSERT_TRUE(log) << log.error().toStdString();
    plans::PlanRuns runs;
    std::vector<Event> events;
    int states = 0;
    for (qsizetype at = 0; at + 20 <= log->size();) {
        const auto size = qFromLittleEndian<quint16>(log->constData() + at + 4);
        const QByteArrayView packet(log->constData() + at, 20 + size + 2);
        at += packet.size();
        const auto id = qFromLittleEndian<quint16>(packet.data() + 2);
        const msg::MessageDef *def = (*schema)->byId(id);
        if (!def || (def->abbrev != u"PlanControlState" && def->abbrev != u"PlanControl"))
            continue;
        auto m = codec.decode(packet);
        ASSERT_TRUE(m) << m.error().toString().toStdString();
        states += def->abbrev == u"PlanControlState";
        for (Event &e : runs.observe(*m, qint64(m->header.timestamp * 1000)))
            events.push_back(std::move(e));
    }
    EXPECT_EQ(states, 395);
    ASSERT_EQ(events.size(), 2u);
    EXPECT_EQ(events[0].kind, Event::Kind::Started);
    EXPECT_EQ(events[0].plan, u"goto-and-wait"_s);
    EXPECT_EQ(events[0].maneuver, u"G1"_s);
    EXPECT_TRUE(events[0].joined) << "the log opened with the plan executing";
    EXPECT_EQ(events[1].kind, Event::Kind::Maneuver);
    EXPECT_EQ(events[1].maneuver, u"S2"_s);
    ASSERT_TRUE(runs.running(0x00d1));
    EXPECT_EQ(runs.running(0x00d1)->plan, u"goto-and-wait"_s);
}
