// The PlanDB protocol on an in-process link: a fake vehicle answers (or
// not) the requests the client sends; every request ends, answered or
// given up after its tries, and only the right replies are taken.
#include "plans/PlanClient.h"

#include "Schemas.h"

#include <QCoreApplication>
#include <QElapsedTimer>

#include <gtest/gtest.h>

using namespace neptus;
using namespace std::chrono_literals;
using namespace Qt::StringLiterals;
using Reply = plans::PlanClient::Reply;

namespace {

constexpr quint16 vehicle = 0x001f;

// The vehicle's side: what it was sent, and a reply it makes.
struct Link
{
    std::shared_ptr<const msg::Schema> schema = test::shippedSchema();
    std::vector<msg::Message> sent;
    std::vector<Reply> replies;

    msg::Message answer(const msg::Message &request, const char *type, const QString &info = {}) const
    {
        msg::Message reply(request.def()); // PlanDB or PlanControl
        const auto set = [&](const char *field, const QString &name) {
            const int i = reply.def()->indexOf(QString::fromLatin1(field));
            reply.setInteger(i, *reply.field(i).enumeration->parse(name));
        };
        set("type", QString::fromLatin1(type));
        set("op", request.enumText(request.def()->indexOf(u"op")));
        reply.setInteger(reply.def()->indexOf(u"request_id"), request.integer(u"request_id"));
        reply.setBytes(reply.def()->indexOf(u"plan_id"), request.bytes(request.def()->indexOf(u"plan_id")));
        reply.setBytes(reply.def()->indexOf(u"info"), info.toUtf8());
        reply.header.src = vehicle;
        return reply;
    }
};

msg::Message spec(const msg::Schema &schema, const char *id)
{
    msg::Message s(schema.byAbbrev(u"PlanSpecification"));
    s.setBytes(s.def()->indexOf(u"plan_id"), id);
    return s;
}

bool waitFor(const std::function<bool()> &done, int ms = 3000)
{
    QElapsedTimer clock;
    clock.start();
    while (!done() && clock.elapsed() < ms)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    return done();
}

} // namespace

TEST(PlanClient, ARequestIsAnsweredByItsOwnReply)
{
    Link link;
    plans::PlanClient client(link.schema, vehicle, [&](const msg::Message &m) { link.sent.push_back(m); });
    QObject::connect(&client, &plans::PlanClient::replied, [&](const Reply &r) { link.replies.push_back(r); });
    const quint16 a = client.set(spec(*link.schema, "survey"));
    const quint16 b = client.get(u"survey"_s);
    ASSERT_EQ(link.sent.size(), 2u);
    EXPECT_NE(a, b);
    const msg::Message &set = link.sent[0];
    EXPECT_EQ(set.header.dst, vehicle); // its own id, not the broadcast
    EXPECT_EQ(set.enumText(set.def()->indexOf(u"type")), u"REQUEST"_s);
    EXPECT_EQ(set.enumText(set.def()->indexOf(u"op")), u"SET"_s);
    EXPECT_EQ(set.text(u"plan_id"), u"survey"_s);
    ASSERT_TRUE(set.inlineMessage(set.def()->indexOf(u"arg")));

    // Not ours: another system, another request, another operation.
    msg::Message stranger = link.answer(set, "SUCCESS");
    stranger.header.src = 0x0020;
    EXPECT_FALSE(client.receive(stranger));
    msg::Message otherOp = link.answer(link.sent[1], "SUCCESS");
    otherOp.setInteger(otherOp.def()->indexOf(u"request_id"), a); // GET's reply with SET's id
    EXPECT_FALSE(client.receive(otherOp));
    EXPECT_TRUE(link.replies.empty());

    // Answers in the other order.
    msg::Message got = link.answer(link.sent[1], "SUCCESS");
    got.setInlineMessage(got.def()->indexOf(u"arg"), spec(*link.schema, "survey"));
    EXPECT_TRUE(client.receive(got));
    EXPECT_TRUE(client.receive(link.answer(set, "FAILURE", u"plan too large"_s)));
    ASSERT_EQ(link.replies.size(), 2u);
    EXPECT_EQ(link.replies[0].requestId, b);
    EXPECT_TRUE(link.replies[0].ok);
    ASSERT_TRUE(link.replies[0].arg);
    EXPECT_EQ(link.replies[0].arg->text(u"plan_id"), u"survey"_s);
    EXPECT_EQ(link.replies[1].requestId, a);
    EXPECT_FALSE(link.replies[1].ok);
    EXPECT_EQ(link.replies[1].info, u"plan too large"_s);
    EXPECT_EQ(client.pending(), 0);
    EXPECT_FALSE(client.receive(got)); // a late duplicate is nobody's
}

TEST(PlanClient, AnUnansweredRequestIsSentAgainThenGivenUp)
{
    Link link;
    plans::PlanClient client(link.schema, vehicle, [&](const msg::Message &m) { link.sent.push_back(m); });
    QObject::connect(&client, &plans::PlanClient::replied, [&](const Reply &r) { link.replies.push_back(r); });
    client.setTimeout(30ms);
    client.setAttempts(3);
    const quint16 id = client.remove(u"old"_s);
    ASSERT_TRUE(waitFor([&] { return !link.replies.empty(); }));
    EXPECT_EQ(link.sent.size(), 3u); // the same request, three times
    for (const msg::Message &m : link.sent)
        EXPECT_EQ(m.integer(u"request_id"), id);
    EXPECT_FALSE(link.replies[0].ok);
    EXPECT_EQ(link.replies[0].attempts, 3);
    EXPECT_EQ(link.replies[0].info, u"no answer from 0x001f after 3 tries, 30 ms apart"_s);
    EXPECT_EQ(client.pending(), 0);
}

TEST(PlanClient, ALostRequestIsRetriedAndInProgressWaits)
{
    Link link;
    int dropped = 0;
    plans::PlanClient client(link.schema, vehicle, [&](const msg::Message &m) {
        link.sent.push_back(m);
        if (dropped++ == 0)
            return; // the first send is lost on the way
        // The vehicle says it is busy every 50 ms, and is done after 600 ms:
        // three times the timeout, which only its IN_PROGRESS replies bridge.
        for (int at = 50; at < 600; at += 50)
            QTimer::singleShot(at, &client, [&, m] { client.receive(link.answer(m, "IN_PROGRESS")); });
        QTimer::singleShot(600, &client, [&, m] { client.receive(link.answer(m, "SUCCESS", u"stored"_s)); });
    });
    QObject::connect(&client, &plans::PlanClient::replied, [&](const Reply &r) { link.replies.push_back(r); });
    client.setTimeout(200ms);
    client.setAttempts(2);
    client.getState();
    ASSERT_TRUE(waitFor([&] { return !link.replies.empty(); }));
    EXPECT_TRUE(link.replies[0].ok) << link.replies[0].info.toStdString();
    EXPECT_EQ(link.replies[0].attempts, 2);
    EXPECT_EQ(link.replies[0].info, u"stored"_s);
    EXPECT_EQ(link.sent.size(), 2u); // IN_PROGRESS did not make it send again
}

// PlanControl: a START ends with the vehicle's first answer. DUNE answers a
// START three times under its id ("plan loaded", "<maneuver>: executing
// maneuver", then how the plan ended): the later two are no answer to any
// request of ours (PlanRuns reads the plan's course from PlanControlState).
TEST(PlanClient, AStartEndsWithItsFirstAnswerAndDunesLaterWordsAnswerNothing)
{
    Link link;
    plans::PlanClient client(link.schema, vehicle, [&](const msg::Message &m) { link.sent.push_back(m); });
    QObject::connect(&client, &plans::PlanClient::replied, [&](const Reply &r) { link.replies.push_back(r); });

    const quint16 id = client.start(spec(*link.schema, "survey"), u"survey"_s, 2);
    ASSERT_EQ(link.sent.size(), 1u);
    const msg::Message &start = link.sent[0];
    EXPECT_EQ(start.abbrev(), u"PlanControl"_s);
    EXPECT_EQ(start.enumText(start.def()->indexOf(u"op")), u"START"_s);
    EXPECT_EQ(start.integer(u"flags"), 2) << "IGNORE_ERRORS";
    EXPECT_EQ(start.header.dst, vehicle);
    ASSERT_NE(start.inlineMessage(start.def()->indexOf(u"arg")), nullptr);

    msg::Message wrongKind(link.schema->byAbbrev(u"PlanDB"));
    wrongKind.setInteger(wrongKind.def()->indexOf(u"request_id"), id);
    wrongKind.setInteger(wrongKind.def()->indexOf(u"type"), 1);
    wrongKind.header.src = vehicle;
    EXPECT_FALSE(client.receive(wrongKind)) << "a PlanDB reply with the same id answers nothing of ours";

    EXPECT_TRUE(client.receive(link.answer(start, "SUCCESS", u"plan loaded"_s)));
    ASSERT_EQ(link.replies.size(), 1u);
    EXPECT_TRUE(link.replies[0].ok);
    EXPECT_EQ(link.replies[0].message, u"PlanControl"_s);
    EXPECT_EQ(link.replies[0].op, u"START"_s);
    EXPECT_EQ(link.replies[0].planId, u"survey"_s);
    EXPECT_EQ(link.replies[0].info, u"plan loaded"_s);
    EXPECT_EQ(client.pending(), 0);

    EXPECT_FALSE(client.receive(link.answer(start, "SUCCESS", u"go: executing maneuver"_s)));
    EXPECT_FALSE(client.receive(link.answer(start, "SUCCESS", u"plan completed"_s)));
    EXPECT_EQ(link.replies.size(), 1u) << "one answer per request";

    client.stop(u"survey"_s);
    EXPECT_EQ(link.sent.back().enumText(link.sent.back().def()->indexOf(u"op")), u"STOP"_s);
    EXPECT_TRUE(client.receive(link.answer(link.sent.back(), "FAILURE", u"no plan is running, request ignored"_s)));
    EXPECT_FALSE(link.replies.back().ok);
    EXPECT_EQ(link.replies.back().info, u"no plan is running, request ignored"_s);
}
