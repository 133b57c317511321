// What a console tells the operation's database (session::OperationsFeed):
// systems from their Announce, positions decimated, plan events from the
// vehicle's PlanControlState and replies, log-book entries, alarms raised,
// acknowledged and cleared, a database problem as the "database" alarm.
#include "database/Database.h"
#include "session/Console.h"
#include "session/OperationsFeed.h"

#include "Schemas.h"

#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <limits>

using namespace neptus;
using namespace Qt::StringLiterals;

namespace {

msg::Message make(const char *abbrev, quint16 src, std::initializer_list<std::pair<const char *, QVariant>> fields)
{
    msg::Message m(test::shippedSchema()->byAbbrev(QString::fromLatin1(abbrev)));
    m.header.src = src;
    for (const auto &[name, value] : fields) {
        const int i = m.def()->fieldIndex.value(QString::fromLatin1(name), -1);
        EXPECT_GE(i, 0) << abbrev << "." << name;
        if (value.typeId() == QMetaType::QString)
            m.setBytes(i, value.toString().toUtf8());
        else if (value.typeId() == QMetaType::Double)
            m.setNumber(i, value.toDouble());
        else
            m.setInteger(i, value.toLongLong());
    }
    return m;
}

db::Writer::Options options(const QString &spool)
{
    db::Writer::Options o;
    o.spoolFolder = spool;
    o.console = u"ops-1"_s;
    o.flushMs = 20;
    return o;
}

struct Feed : ::testing::Test
{
    QTemporaryDir dir;
    ManualClock clock{QDateTime::fromMSecsSinceEpoch(1'790'000'000'000, QTimeZone::UTC)};
    session::Console console{test::shippedSchema(), &clock};
    db::Location location = *db::Location::parse(dir.filePath(u"ops.db"_s));
    std::unique_ptr<db::Writer> writer = std::make_unique<db::Writer>(location, options(dir.filePath(u"spool"_s)));
    std::unique_ptr<session::OperationsFeed> feed = std::make_unique<session::OperationsFeed>(console, writer.get(), &clock);

    std::unique_ptr<db::Reader> read()
    {
        feed.reset();
        EXPECT_TRUE(writer->flush());
        auto reader = db::Reader::open(location);
        EXPECT_TRUE(reader.has_value());
        return reader ? std::move(*reader) : nullptr;
    }
};

} // namespace

TEST_F(Feed, SystemsPositionsPlansAndTheLogBookGoIn)
{
    console.ingest(make("Announce", 0x1f, {{"sys_name", u"lauv-sim-1"_s}, {"sys_type", 2}, {"lat", 0.7144}, {"lon", -0.1527}}));
    // 10 s of EstimatedState at 10 Hz: kept at 2 per second.
    for (int i = 0; i < 100; ++i) {
        console.ingest(make("EstimatedState", 0x1f, {{"lat", 0.7144}, {"lon", -0.1527}, {"x", double(i)}, {"y", 0.0},
                                                     {"depth", 2.0}, {"alt", 8.0}, {"psi", M_PI / 2}, {"vx", 1.0}, {"vy", 0.0}}));
        clock.advance(100);
    }
    auto pcs = [&](int state, const QString &plan, const QString &man, int outcome) {
        console.ingest(make("PlanControlState", 0x1f, {{"state", state}, {"plan_id", plan}, {"man_id", man}, {"last_outcome", outcome},
                                                       {"plan_progress", 50.0}}));
        clock.advance(1000);
    };
    pcs(1, QString(), QString(), 0);    // READY
    pcs(3, u"survey"_s, u"goto1"_s, 0); // EXECUTING: started
    pcs(3, u"survey"_s, u"goto1"_s, 0); // no change
    pcs(3, u"survey"_s, u"rows2"_s, 0); // next maneuver
    pcs(1, u"survey"_s, QString(), 1);  // READY, SUCCESS
    console.ingest(make("PlanControl", 0x1f, {{"type", 2}, {"op", 0}, {"plan_id", u"other"_s}, {"info", u"no such plan"_s}}));
    console.ingest(make("LogBookEntry", 0x1f, {{"type", 2}, {"context", u"Navigation"_s}, {"text", u"GPS fix lost"_s}}));

    auto reader = read();
    ASSERT_TRUE(reader);
    const auto systems = reader->systems();
    ASSERT_EQ(systems->size(), 1u);
    EXPECT_EQ(systems->front().name, u"lauv-sim-1"_s);
    EXPECT_EQ(systems->front().kind, u"UUV"_s);
    EXPECT_EQ(systems->front().imcId, 0x1f);
    const qint64 t0 = 1'790'000'000'000;
    EXPECT_EQ(systems->front().firstMs, t0);
    EXPECT_GE(systems->front().lastMs, t0 + 10'000);
    const auto track = reader->track(u"lauv-sim-1"_s, 0, t0 + 100'000);
    ASSERT_EQ(track->size(), 20u);
    EXPECT_NEAR(track->front().lat, 0.7144 * 180 / M_PI, 1e-9);
    EXPECT_GT(track->back().lat, track->front().lat); // moving north
    EXPECT_DOUBLE_EQ(track->front().depth, 2.0);
    EXPECT_DOUBLE_EQ(track->front().altitude, 8.0);
    EXPECT_NEAR(track->front().heading, 90.0, 1e-4); // psi is a float
    EXPECT_DOUBLE_EQ(track->front().speed, 1.0);
    const auto plans = reader->planEvents(0, t0 + 100'000);
    ASSERT_EQ(plans->size(), 4u);
    EXPECT_EQ(plans->at(0).event, u"started"_s);
    EXPECT_EQ(plans->at(0).maneuver, u"goto1"_s);
    EXPECT_EQ(plans->at(1).event, u"maneuver"_s);
    EXPECT_EQ(plans->at(1).maneuver, u"rows2"_s);
    EXPECT_EQ(plans->at(2).event, u"completed"_s);
    EXPECT_EQ(plans->at(2).plan, u"survey"_s);
    EXPECT_EQ(plans->at(3).event, u"start failure"_s);
    EXPECT_EQ(plans->at(3).detail, u"no such plan"_s);
    EXPECT_EQ(plans->at(0).console, u"ops-1"_s);
    const auto book = reader->logBook(0, t0 + 100'000);
    ASSERT_EQ(book->size(), 1u);
    EXPECT_EQ(book->front().type, u"ERROR"_s);
    EXPECT_EQ(book->front().system, u"lauv-sim-1"_s);
}

// Issue #34/#38: the database hears of a plan's end from the vehicle's state, as the plan desk does
// (the same tracker, plans::PlanRuns), never from counting replies: DUNE answers a START with
// "plan loaded" and "<maneuver>: executing maneuver", both SUCCESS, then its end; an abort ends with
// a FAILURE carrying the reason, just before the state says BLOCKED/FAILURE.
TEST_F(Feed, APlansEndIsTheVehiclesStateWithItsWordsNotACountOfReplies)
{
    console.ingest(make("Announce", 0x1f, {{"sys_name", u"lauv-sim-1"_s}, {"sys_type", 2}}));
    const auto reply = [&](int type, const QString &info) {
        console.ingest(make("PlanControl", 0x1f, {{"type", type}, {"op", 0}, {"request_id", 7}, {"plan_id", u"survey"_s}, {"info", info}}));
    };
    const auto state = [&](int state, const QString &man, int outcome) {
        console.ingest(make("PlanControlState", 0x1f, {{"state", state}, {"plan_id", u"survey"_s}, {"man_id", man}, {"last_outcome", outcome}}));
        clock.advance(1000);
    };
    state(1, QString(), 0); // READY: heard before the plan starts
    const qint64 t0 = clock.now().toMSecsSinceEpoch();
    reply(1, u"plan loaded"_s);
    reply(1, u"goto1: executing maneuver"_s);
    for (int i = 0; i < 5; ++i)
        state(3, u"goto1"_s, 0);
    reply(2, u"aborted by operator"_s);
    const qint64 ended = clock.now().toMSecsSinceEpoch();
    state(0, QString(), 2); // BLOCKED, FAILURE

    auto reader = read();
    ASSERT_TRUE(reader);
    const auto events = reader->planEvents(0, t0 + 100'000);
    ASSERT_TRUE(events.has_value());
    QStringList said;
    for (const auto &e : *events)
        said.append(e.event + u": "_s + e.detail);
    EXPECT_EQ(said, (QStringList{u"start success: plan loaded"_s, u"start success: goto1: executing maneuver"_s, u"started: "_s,
                                 u"start failure: aborted by operator"_s, u"failed: aborted by operator"_s}))
        << said.join(u" | "_s).toStdString();
    ASSERT_EQ(events->size(), 5u);
    EXPECT_EQ(events->at(2).ms, t0);
    EXPECT_EQ(events->at(4).ms, ended) << "the end at the state that said so";
}

// What the plan desk learns beyond the vehicle's reports reaches the database too (the plan log
// and the database say the same): a MAVLink mission recognised as a plan while it runs is one
// run under the plan's name; a stop the vehicle accepted by changing mode ends it "stopped".
TEST_F(Feed, TheDesksRelabelAndAcceptedStopAreTheDatabasesToo)
{
    console.ingest(make("Announce", 0x1f, {{"sys_name", u"ardurover-1"_s}, {"sys_type", 3}}));
    const auto state = [&](int state, const QString &plan, int outcome) {
        console.ingest(make("PlanControlState", 0x1f, {{"state", state}, {"plan_id", plan}, {"man_id", u"1"_s}, {"last_outcome", outcome}}));
        clock.advance(1000);
    };
    state(1, QString(), 0);
    state(3, u"mission"_s, 0);
    feed->relabelRun(0x1f, u"harbour-loop"_s);
    state(3, u"harbour-loop"_s, 0);
    feed->stopAccepted(0x1f);
    console.ingest(make("PlanControl", 0x1f, {{"type", 2}, {"op", 0}, {"plan_id", u"harbour-loop"_s}, {"info", u"left the mission for HOLD"_s}}));
    state(1, u"harbour-loop"_s, 2); // READY, FAILURE

    auto reader = read();
    ASSERT_TRUE(reader);
    const auto events = reader->planEvents(0, std::numeric_limits<qint64>::max());
    ASSERT_TRUE(events.has_value());
    QStringList said;
    for (const auto &e : *events)
        said.append(e.plan + u' ' + e.event);
    EXPECT_EQ(said, (QStringList{u"mission started"_s, u"harbour-loop start failure"_s, u"harbour-loop stopped"_s}))
        << said.join(u" | "_s).toStdString();
}

TEST_F(Feed, AlarmsAreRaisedAcknowledgedAndCleared)
{
    alarms::AlarmGraph &graph = console.alarmGraph();
    const auto node = graph.ensure(u"systems/lauv-sim-1/Battery"_s);
    graph.raise(node, alarms::Warning, u"battery at 30 %"_s);
    feed->checkAlarms();
    graph.raise(node, alarms::Error, u"battery at 10 %"_s);
    feed->checkAlarms();
    graph.acknowledge(node);
    feed->checkAlarms();
    graph.clear(node);
    feed->checkAlarms();
    auto reader = read();
    ASSERT_TRUE(reader);
    const auto alarms = reader->alarms(0, std::numeric_limits<qint64>::max());
    ASSERT_TRUE(alarms.has_value());
    QStringList said;
    for (const auto &a : *alarms)
        if (a.origin == u"systems/lauv-sim-1/Battery"_s)
            said.append(a.event + u' ' + a.level + u' ' + a.message);
    EXPECT_EQ(said, (QStringList{u"raised Warning battery at 30 %"_s, u"raised Error battery at 10 %"_s,
                                 u"acknowledged Error battery at 10 %"_s, u"cleared Normal "_s}));
}

TEST(FeedProblems, ADatabaseThatCannotBeReachedRaisesTheDatabaseAlarm)
{
    QTemporaryDir dir;
    session::Console console(test::shippedSchema());
    db::Writer writer(*db::Location::parse(u"postgresql://neptus@/ops?host=%1"_s.arg(dir.filePath(u"nothing-here"_s))),
                      options(dir.filePath(u"spool"_s)));
    session::OperationsFeed feed(console, &writer);
    writer.flush(300);
    const auto node = console.alarmGraph().find(u"database"_s);
    ASSERT_NE(node, alarms::AlarmGraph::noNode);
    EXPECT_EQ(console.alarmGraph().ownLevel(node), alarms::Warning);
    EXPECT_NE(console.alarmGraph().message(node).indexOf(u"kept on disk"_s), -1) << console.alarmGraph().message(node).toStdString();
}
